#include "server/relay/send_queue.hpp"

#include <gtest/gtest.h>

namespace mc::relay {
namespace {

Message delta(std::size_t n) { return Message::frame(std::string(n, 'd'), false); }
Message key(std::size_t n) { return Message::frame(std::string(n, 'k'), true); }

TEST(SendQueue, QueuesUnderTheBound) {
  SendQueue q(1000);
  EXPECT_TRUE(q.push(key(100)));
  EXPECT_TRUE(q.push(delta(100)));
  EXPECT_EQ(q.size(), 2u);
  EXPECT_EQ(q.bytes(), 200u);
  std::vector<Message> batch;
  q.take_all(batch);
  EXPECT_EQ(batch.size(), 2u);
  EXPECT_TRUE(q.empty());
  EXPECT_EQ(q.bytes(), 0u);
}

TEST(SendQueue, OverflowDropsDeltasUntilTheNextKeyframe) {
  SendQueue q(500);
  q.push(Message::control("{\"type\":\"hello\"}"));
  q.push(key(200));
  q.push(delta(200));
  EXPECT_FALSE(q.push(delta(200)));  // over the bound: skip begins
  EXPECT_TRUE(q.skipping());
  // The queued keyframe and delta are gone too; the hello stays.
  EXPECT_EQ(q.size(), 1u);
  EXPECT_FALSE(q.push(delta(10)));
  EXPECT_TRUE(q.push(key(100)));  // resync point
  EXPECT_FALSE(q.skipping());
  EXPECT_TRUE(q.push(delta(10)));
  std::vector<Message> batch;
  q.take_all(batch);
  ASSERT_EQ(batch.size(), 3u);
  EXPECT_EQ(batch[0].kind, Message::Kind::Control);
  EXPECT_EQ(batch[1].kind, Message::Kind::Keyframe);
  EXPECT_EQ(batch[2].kind, Message::Kind::Delta);
  EXPECT_EQ(q.dropped(), 4u);
}

TEST(SendQueue, ControlMessagesAreNeverDropped) {
  SendQueue q(10);
  EXPECT_TRUE(q.push(Message::control(std::string(100, 'c'))));
  EXPECT_FALSE(q.push(delta(5)));
  EXPECT_TRUE(q.push(Message::control("x")));
  EXPECT_EQ(q.size(), 2u);
}

TEST(SendQueue, ACatchUpBurstsRoomIsGivenBack) {
  // A joiner's catch-up queues many messages at once; once they are taken,
  // an idle spectator must not keep room for all of them.
  SendQueue q(1 << 20);
  for (int i = 0; i < 30; ++i) q.push(delta(10));
  std::vector<Message> batch;
  q.take_all(batch);
  EXPECT_EQ(batch.size(), 30u);
  EXPECT_LE(q.room(), SendQueue::kKeptRoom);
  // The usual write (one frame) keeps its room: no allocation per frame.
  q.push(delta(10));
  batch.clear();
  q.take_all(batch);
  EXPECT_EQ(q.room(), 1u);
  // Appended, never swapped: the batch's own room stays with the batch.
  const auto batch_room = batch.capacity();
  q.push(delta(10));
  q.take_all(batch);
  EXPECT_EQ(batch.size(), 2u);
  EXPECT_GE(batch.capacity(), batch_room);
}

}  // namespace
}  // namespace mc::relay

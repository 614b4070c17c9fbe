// A replay player steered by whatever a spectator sends: messages of the
// wrong shape are ignored, never thrown on (an exception on the relay's
// thread ends the server), and out-of-range numbers are clamped. The inputs
// are those replay_spectator_messages_fuzz found.
#include "server/replay/replay_player.hpp"

#include <gtest/gtest.h>

#include <boost/asio/io_context.hpp>

namespace mc::replay {
namespace {

const std::string kGolden = std::string(MATCHCAST_SOURCE_DIR) + "/tests/proto/golden/recording_v3.mcrec";

std::shared_ptr<ReplayPlayer> player(boost::asio::io_context& ioc) {
  auto reader = std::make_unique<record::RecordingReader>();
  std::string error;
  EXPECT_TRUE(reader->open(kGolden, error)) << error;
  RecordingSummary summary;
  EXPECT_TRUE(summarize(*reader, summary, error)) << error;
  auto p = std::make_shared<ReplayPlayer>(ioc.get_executor(), "golden.mcrec", std::move(reader), summary);
  p->start();
  return p;
}

TEST(ReplayPlayer, MessagesOfTheWrongShapeAreIgnoredNotThrownOn) {
  boost::asio::io_context ioc;
  auto p = player(ioc);
  for (const char* text : {R"({"type":1200})", R"({"type":null,"action":"seek"})", R"({"type":"replay","action":7})",
                           R"({"type":"replay"})", R"([1,2])", R"("replay")", "", "{", R"({"type":"replay","action":"seek","time":"x"})"}) {
    EXPECT_NO_THROW(p->on_client_message(text)) << text;
  }
  EXPECT_FALSE(p->paused());
  p->on_client_message(R"({"type":"replay","action":"pause"})");
  EXPECT_TRUE(p->paused());
  p->close();
  ioc.poll();
}

TEST(ReplayPlayer, ASeekFarOutsideTheRecordingIsClampedToIt) {
  boost::asio::io_context ioc;
  auto p = player(ioc);
  p->on_client_message(R"({"type":"replay","action":"seek","time":1e300})");
  const int last = p->time();
  EXPECT_GT(last, 0);
  p->on_client_message(R"({"type":"replay","action":"seek","time":-1e300})");
  EXPECT_LT(p->time(), last);
  p->close();
  ioc.poll();
}

}  // namespace
}  // namespace mc::replay

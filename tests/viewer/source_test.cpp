// Control messages that change the picture, applied by every source.
#include "viewer/source.hpp"

#include <gtest/gtest.h>

#include "viewer/frame_buffer.hpp"

namespace mc::viewer {
namespace {

TEST(ControlMessages, FeedTeamsAndPenaltiesReachTheScreen) {
  FrameBuffer buffer;
  buffer.set_hello(proto::Hello{});
  apply_control_message(R"({"type":"feed","status":"lost","seq":5,"server_time_ms":1,"detail":"no datagram for 3 s"})",
                        buffer);
  EXPECT_EQ(buffer.meta().status, "feed lost: no datagram for 3 s");
  apply_control_message(R"({"type":"feed","status":"back","seq":6,"server_time_ms":2,"detail":""})", buffer);
  EXPECT_EQ(buffer.meta().status, "");
  apply_control_message(R"({"type":"score","seq":7,"time":3,"left":2,"right":2,"pen_left":4,"pen_right":3})", buffer);
  EXPECT_EQ(buffer.meta().pen_left, 4);
  EXPECT_EQ(buffer.meta().pen_right, 3);
  apply_control_message(
      R"({"type":"teams","seq":8,"left":{"name":"A","color":"#010203","color2":"#000000"},"right":{"name":"B","color":"#040506","color2":"#ffffff"}})",
      buffer);
  EXPECT_EQ(buffer.meta().hello->right.name, "B");
  EXPECT_EQ(buffer.meta().hello->left.color, "#010203");
}

TEST(ControlMessages, EventsUnknownTypesAndGarbageChangeNothing) {
  FrameBuffer buffer;
  buffer.set_hello(proto::Hello{});
  buffer.set_status("before");
  const auto generation = buffer.meta().hello_generation;
  for (const char* text : {R"({"type":"kick","seq":1,"time":1,"side":"left","unum":9,"foot":"right","contact_time_ms":50})",
                           R"({"type":"from_the_future","x":1})", "not json", "", "[1,2,3]",
                           R"({"type":"teams","left":7})", R"({"type":"feed","status":12})"})
    apply_control_message(text, buffer);
  EXPECT_EQ(buffer.meta().status, "before");
  EXPECT_EQ(buffer.meta().hello_generation, generation);
}

}  // namespace
}  // namespace mc::viewer

// A spectator's message is read by a SAX pass (spectator_message.cpp), not
// made into a JSON tree. It must read every message exactly as the tree did
// (the reference below is the reading it replaced): the same fields, the
// last of a repeated key, a member of the wrong type as absent, and nothing
// at all for what is not one JSON object with a string "type".
#include "server/relay/spectator_message.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace mc::relay {
namespace {

std::optional<SpectatorMessage> read_with_a_tree(std::string_view text) {
  const auto j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object()) return std::nullopt;
  const auto type = j.find("type");
  if (type == j.end() || !type->is_string()) return std::nullopt;
  SpectatorMessage m;
  m.type = type->get<std::string>();
  const auto action = j.find("action");
  if (action != j.end() && action->is_string()) m.action = action->get<std::string>();
  const auto time = j.find("time");
  if (time != j.end() && time->is_number()) m.time = time->get<double>();
  const auto speed = j.find("speed");
  if (speed != j.end() && speed->is_number()) m.speed = speed->get<double>();
  return m;
}

TEST(SpectatorMessage, ReadsEveryMessageAsAParsedTreeDoes) {
  const std::string deep = R"({"type":"replay","x":)" + std::string(100000, '[') + std::string(100000, ']') + "}";
  const std::vector<std::string> texts = {
      R"({"type":"replay","action":"seek","time":1234})",
      R"({"type":"timeshift","action":"live"})",
      R"({"type":"replay","action":"speed","speed":0.5})",
      R"({"type":"replay","action":"speed","speed":-3e2,"time":7.25})",
      R"( {"action":"pause", "type" : "replay"} )",
      " \t\r\n{\"type\":\"replay\"}\n\r\t ",  // JSON's four whitespace characters, both ends
      "\f{\"type\":\"replay\"}",                   // ... and one that is not
      "{\"type\":\"replay\"}\v",
      R"(x{"type":"replay"})",
      R"({"type":"replay"})" "\n}",
      R"({"type":"replay","type":"timeshift"})",           // the last of a repeated key
      R"({"type":"replay","type":7})",                     // ... even of another type
      R"({"type":7,"type":"replay"})",
      R"({"type":"replay","action":"seek","time":5,"time":6,"speed":1,"speed":2})",
      R"({"type":"replay","action":"seek","time":5,"time":"x"})",
      R"({"type":"replay","action":"seek","time":"x","time":5})",
      R"({"type":"replay","action":1,"action":"play"})",
      R"({"type":"replay","action":"play","action":null})",
      R"({"type":"replay","action":{"type":"x","action":"y"},"time":[1]})",  // nested: not read
      R"({"type":"replay","speed":{"speed":2},"x":{"type":5}})",
      R"({"type":"replay","time":true,"speed":false})",
      R"({"type":"replay","time":18446744073709551615,"speed":-9223372036854775808})",
      R"({"type":"replay","time":1e308,"speed":-1e-320})",
      R"({"type":"a\"b\u0041\\"})",
      R"({"type":1200})",
      R"({"type":null,"action":"seek"})",
      R"({"action":"seek"})",
      R"({})",
      R"([{"type":"replay"}])",
      R"("replay")",
      "7",
      "null",
      "",
      "{",
      R"({"type":"replay"} x)",
      R"({"type":"replay"}{"type":"replay"})",
      R"({"type":"replay",})",
      "{\"type\":\"re\xffplay\"}",  // not UTF-8
      "{\"type\":\"replay\"\0}",
      R"({"type":"\uD800"})",        // a lone high surrogate
      R"({"type":"\uDC00"})",        // a lone low surrogate
      R"({"type":"\uD83D\uDE00"})",  // a pair
      "{\"type\":\"\xed\xb0\x80\"}",  // a surrogate's bytes, raw
      R"({"\uDC00":"replay","type":"replay"})",  // ... in a key
      R"({"type":"replay","time":-0})",
      R"({"type":"replay","time":123456789012345678901234567890})",
      deep,
  };
  for (const auto& text : texts) {
    const auto want = read_with_a_tree(text);
    const auto got = read_spectator_message(text);
    ASSERT_EQ(got.has_value(), want.has_value()) << text.substr(0, 80);
    if (!want) continue;
    EXPECT_EQ(got->type, want->type) << text;
    EXPECT_EQ(got->action, want->action) << text;
    EXPECT_EQ(got->time, want->time) << text;
    EXPECT_EQ(got->speed, want->speed) << text;
  }
  // A NUL byte is not the end of the text: a message with a NUL and junk
  // after it is refused (nlohmann's own reader, the tree's too, stops at
  // the NUL and accepts it), and so is a NUL inside a string.
  EXPECT_FALSE(read_spectator_message(std::string("{\"type\":\"replay\"}\0 junk", 23)));
  EXPECT_FALSE(read_spectator_message(std::string("{\"type\":\"re\0play\"}", 19)));
  // And what the tree read, in plain figures, for the common messages.
  const auto seek = read_spectator_message(R"({"type":"replay","action":"seek","time":1234})");
  ASSERT_TRUE(seek);
  EXPECT_EQ(seek->type, "replay");
  EXPECT_EQ(seek->action, "seek");
  EXPECT_EQ(seek->time, 1234.0);
  EXPECT_FALSE(seek->speed);
}

}  // namespace
}  // namespace mc::relay

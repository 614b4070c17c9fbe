// Binary forms of stamina updates and kicks in recordings (format 3): the
// text comes back byte for byte, anything else stays text, and malformed
// bytes are refused.
#include "proto/control_binary.hpp"

#include <gtest/gtest.h>

#include <random>

#include "proto/control_messages.hpp"
#include "proto/recording.hpp"

namespace mc::proto::rec {
namespace {

StaminaUpdate sample_stamina() {
  StaminaUpdate s;
  s.seq = 23456;
  s.time = 1172;
  s.left = {8000, 7743, 0, -1, 1000000, 6980, 7404, 7500, 7210, 7176, 7450};
  s.right = {8000, 7539, 7467, 7480, 7241, 7000, 7029, 7300, 7935, 6932, 8001};
  return s;
}

TEST(ControlBinary, StaminaAndKicksComeBackByteForByteAndSmaller) {
  const std::string stamina = to_json(ControlMessage{sample_stamina()});
  const std::string kick = to_json(ControlMessage{KickEvent{24001, 1200, Side::Right, 10, Foot::Left, 1200075}});
  const std::string early = to_json(ControlMessage{KickEvent{3, 1, Side::Left, 4, Foot::Right, 0}});  // contact before seq * 50
  for (const std::string& text : {stamina, kick, early}) {
    const std::string bin = compact_control(text);
    ASSERT_FALSE(bin.empty()) << text;
    EXPECT_LT(bin.size() * 3, text.size()) << text;
    std::string back;
    ASSERT_TRUE(expand_control(bin, back)) << text;
    EXPECT_EQ(back, text);
  }
}

TEST(ControlBinary, OtherMessagesAndOtherSpellingsStayText) {
  EXPECT_EQ(compact_control(to_json(ControlMessage{GoalEvent{14, 7, Side::Left, 1, 0}})), "");
  EXPECT_EQ(compact_control(to_json(ControlMessage{PlayModeEvent{5, 2, PlayMode::PlayOn}})), "");
  // Valid JSON, but not the text to_json writes: kept as it is.
  EXPECT_EQ(compact_control(R"({"type":"kick", "seq":1,"time":0,"side":"left","unum":2,"foot":"left","contact_time_ms":50})"), "");
  EXPECT_EQ(compact_control(R"({"type":"stamina"})"), "");  // not a valid message
  EXPECT_EQ(compact_control("not json"), "");
}

TEST(ControlBinary, MalformedBytesAreRefused) {
  const std::string bin = compact_control(to_json(ControlMessage{sample_stamina()}));
  std::string out;
  EXPECT_FALSE(expand_control("", out));
  EXPECT_FALSE(expand_control(std::string("\x07", 1), out));  // unknown tag
  for (std::size_t n = 0; n < bin.size(); ++n) EXPECT_FALSE(expand_control(bin.substr(0, n), out)) << n;
  EXPECT_FALSE(expand_control(bin + "x", out));  // bytes left over
  // A stamina value past its range (8000 - 2^40) and an over-long varint.
  std::string big = bin.substr(0, bin.size() - 1) + std::string("\xff\xff\xff\xff\xff\x7f", 6);
  EXPECT_FALSE(expand_control(big, out));
  EXPECT_FALSE(expand_control(std::string("\x02") + std::string(12, '\xff'), out));
  // Kick flag byte: side 3 and unum 31 do not exist.
  std::string kick = compact_control(to_json(ControlMessage{KickEvent{10, 5, Side::Left, 3, Foot::Left, 500}}));
  ASSERT_GE(kick.size(), 4u);
  kick[3] = static_cast<char>(3);
  EXPECT_FALSE(expand_control(kick, out));
  kick[3] = static_cast<char>(31 << 3);
  EXPECT_FALSE(expand_control(kick, out));
  // Random bytes: refused or decoded, never a crash.
  std::mt19937 rng(7);
  for (int i = 0; i < 2000; ++i) {
    std::string junk(rng() % 40, '\0');
    for (char& c : junk) c = static_cast<char>(rng());
    expand_control(junk, out);
  }
}

TEST(ControlBinary, AChunkGivesBackTheTextsInOrder) {
  ChunkBuilder b;
  const std::vector<std::string> texts = {
      to_json(ControlMessage{sample_stamina()}), to_json(ControlMessage{GoalEvent{14, 7, Side::Left, 1, 0}}),
      to_json(ControlMessage{KickEvent{15, 7, Side::Left, 9, Foot::Right, 760}}), R"({"type":"future","x":1})"};
  for (const auto& t : texts) b.add_control(t);
  ChunkInfo info;
  const std::string record = b.finish(info);
  RecordView v;
  std::string error;
  ASSERT_EQ(parse_record(record, v, error), RecordStatus::Ok);
  std::vector<ChunkEntry> entries;
  ASSERT_TRUE(parse_chunk(v.payload, info, entries, error)) << error;
  ASSERT_EQ(entries.size(), texts.size());
  for (std::size_t i = 0; i < texts.size(); ++i) EXPECT_EQ(entries[i].bytes, texts[i]);
}

}  // namespace
}  // namespace mc::proto::rec

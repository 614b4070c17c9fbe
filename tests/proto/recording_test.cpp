// The recording format in memory (proto/recording.hpp).
#include "proto/recording.hpp"

#include <gtest/gtest.h>

#include "proto/frame_codec.hpp"
#include "tests/proto/support/synthetic.hpp"

namespace mc::proto::rec {
namespace {

TEST(RecordingFormat, FileHeaderRoundTripsAndRefusesOtherMajors) {
  FileHeader h;
  h.created_unix_ms = 1763785000123ull;
  std::string bytes = encode_file_header(h);
  ASSERT_EQ(bytes.size(), kFileHeaderSize);
  FileHeader back;
  std::string error;
  ASSERT_TRUE(parse_file_header(bytes, back, error)) << error;
  EXPECT_EQ(back.created_unix_ms, h.created_unix_ms);
  bytes[6] = 9;
  EXPECT_FALSE(parse_file_header(bytes, back, error));
  EXPECT_NE(error.find("unsupported recording format major version 9"), std::string::npos) << error;
  EXPECT_FALSE(parse_file_header("MCREC", back, error));
  EXPECT_FALSE(parse_file_header("XXXXXXXXXXXXXXXXXXXX", back, error));
  EXPECT_NE(error.find("magic"), std::string::npos);
}

TEST(RecordingFormat, RecordsDetectTruncationAndCorruption) {
  const std::string rec = encode_record(RecordType::Hello, "{\"type\":\"hello\"}");
  RecordView v;
  std::string error;
  ASSERT_EQ(parse_record(rec, v, error), RecordStatus::Ok) << error;
  EXPECT_EQ(v.payload, "{\"type\":\"hello\"}");
  EXPECT_EQ(v.total_size, rec.size());
  EXPECT_EQ(record_size_hint(rec), rec.size());
  for (std::size_t n = 0; n < rec.size(); ++n)
    EXPECT_EQ(parse_record(std::string_view(rec).substr(0, n), v, error), RecordStatus::Truncated) << n;
  for (std::size_t i = 4; i < rec.size(); ++i) {  // any flipped bit after the length is caught
    std::string bad = rec;
    bad[i] = static_cast<char>(bad[i] ^ 0x10);
    EXPECT_EQ(parse_record(bad, v, error), RecordStatus::Corrupt) << i;
  }
  EXPECT_EQ(crc32("123456789"), 0xCBF43926u);  // the standard check value
}

TEST(RecordingFormat, ChunksKeepFramesAndControlsInOrder) {
  const SkeletonDef s = testing::humanoid_skeleton();
  const auto frames = testing::scripted_frames(s, 5);
  FrameEncoder enc(s);
  ChunkBuilder b;
  std::vector<std::string> encoded;
  std::string error;
  for (const auto& f : frames) {
    bool key = false;
    encoded.push_back(enc.encode(f, key));
    ASSERT_TRUE(b.add_frame(encoded.back(), error)) << error;
    if (f.seq == 2) b.add_control(R"({"type":"kick"})");
  }
  EXPECT_FALSE(b.add_frame("junk", error));
  ChunkInfo info;
  const std::string record = b.finish(info);
  EXPECT_TRUE(b.empty());
  EXPECT_EQ(info.frame_count, 5u);
  EXPECT_TRUE(info.starts_with_keyframe);
  RecordView v;
  ASSERT_EQ(parse_record(record, v, error), RecordStatus::Ok);
  ASSERT_EQ(v.type, RecordType::Chunk);
  ChunkInfo parsed;
  std::vector<ChunkEntry> entries;
  ASSERT_TRUE(parse_chunk(v.payload, parsed, entries, error)) << error;
  ASSERT_EQ(entries.size(), 6u);
  EXPECT_EQ(entries[3].kind, ChunkEntry::Kind::Control);
  EXPECT_EQ(entries[3].bytes, R"({"type":"kick"})");
  EXPECT_EQ(entries[0].bytes, encoded[0]);
  EXPECT_EQ(entries[4].bytes, encoded[3]);  // compact headers are restored byte for byte
  EXPECT_EQ(entries[5].bytes, encoded[4]);
  EXPECT_EQ(parsed.first_seq, frames[0].seq);
  // A chunk payload cut anywhere is refused, never over-read.
  for (std::size_t n = 0; n < v.payload.size(); ++n)
    EXPECT_FALSE(parse_chunk(v.payload.substr(0, n), parsed, entries, error)) << n;
}

// Format 2 deflates a chunk's control messages together (with a preset
// dictionary); format 1 chunks, with the text inline, still parse.
TEST(RecordingFormat, ControlTextIsDeflatedAndFormatOneChunksStillParse) {
  ChunkBuilder b;
  std::string raw;
  for (int i = 0; i < 5; ++i) {
    const std::string m = R"({"left":[8000,7743,7498,7869,7674,0,1404,0,0,1176,0],"right":[8000,7539,7467,7480,)" +
                          std::to_string(7000 + i) + R"(,0,3029,0,3935,2932,0],"seq":)" + std::to_string(20 * i) +
                          R"(,"time":)" + std::to_string(10 * i) + R"(,"type":"stamina"})";
    b.add_control(m);
    raw += m;
  }
  ChunkInfo info;
  const std::string record = b.finish(info);
  RecordView v;
  std::string error;
  ASSERT_EQ(parse_record(record, v, error), RecordStatus::Ok);
  // 5 messages of ~150 B: the dictionary and the repeats leave under a fifth.
  EXPECT_LT(v.payload.size() * 5, raw.size()) << v.payload.size() << " of " << raw.size();
  ChunkInfo parsed;
  std::vector<ChunkEntry> entries;
  ASSERT_TRUE(parse_chunk(v.payload, parsed, entries, error)) << error;
  ASSERT_EQ(entries.size(), 5u);
  std::string back;
  for (const auto& e : entries) back += e.bytes;
  EXPECT_EQ(back, raw);

  // Format 1: u32 first seq | i32 time | u16 stoppage | u8 substep | u8 flags
  // | u32 frame count | u32 entry count | kind 2, length, text.
  std::string v1(16, '\0');
  v1 += std::string("\x01\0\0\0", 4);
  v1 += "\x02\x0f";
  v1 += R"({"type":"kick"})";
  ASSERT_TRUE(parse_chunk(v1, parsed, entries, error, 1)) << error;
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].bytes, R"({"type":"kick"})");
  EXPECT_FALSE(parse_chunk(v1, parsed, entries, error, 2));  // read as format 2 it is no deflate block
}

// A chunk that claims more control text than its block could inflate to is
// refused with a clear error. (That the refusal comes before any allocation
// for the claim is parse_chunk's bound check; a test cannot see it.)
TEST(RecordingFormat, AnImpossibleControlLengthIsRefused) {
  ChunkInfo info;
  std::vector<ChunkEntry> entries;
  std::string error;
  // Format 2: 16-byte info, u32 entry count, the block to the end.
  std::string p(16, '\0');
  p += std::string("\x01\0\0\0", 4);
  p += "\x02\x80\x80\x80\x10";  // one control entry of 32 MiB
  p += "abc";                      // and a 3-byte block
  EXPECT_FALSE(parse_chunk(p, info, entries, error, 2));
  EXPECT_NE(error.find("do not inflate"), std::string::npos) << error;
  // Format 3: LEB128 info and entry count, the block after its length.
  std::string p3("\x00\x00\x00\x00\x00\x00\x01", 7);  // seq, time, stoppage, flags, substep, 0 frames, 1 entry
  p3 += "\x02\x80\x80\x80\x10\x03" "abc";
  EXPECT_FALSE(parse_chunk(p3, info, entries, error, 3));
  EXPECT_NE(error.find("do not inflate"), std::string::npos) << error;
  p3.back() = 'd';  // bytes after the block: the block length says 3
  p3 += "e";
  EXPECT_FALSE(parse_chunk(p3, info, entries, error, 3));
}

TEST(RecordingFormat, IndexAndTrailerRoundTrip) {
  std::vector<ChunkInfo> chunks;
  for (int i = 0; i < 5; ++i) chunks.push_back({100u + 1000u * static_cast<unsigned>(i), 20u * static_cast<unsigned>(i), 10 * i, 0, 0, true, 20});
  const std::string rec = encode_index(chunks);
  RecordView v;
  std::string error;
  ASSERT_EQ(parse_record(rec, v, error), RecordStatus::Ok);
  std::vector<ChunkInfo> back;
  ASSERT_TRUE(parse_index(v.payload, back, error)) << error;
  ASSERT_EQ(back.size(), 5u);
  EXPECT_EQ(back[3].offset, 3100u);
  EXPECT_EQ(back[3].first_time, 30);
  EXPECT_FALSE(parse_index(v.payload.substr(0, 10), back, error));
  EXPECT_FALSE(parse_index(std::string(v.payload) + "x", back, error));   // bytes after the last entry
  std::string hostile(v.payload);
  hostile.replace(0, 4, "\xff\xff\xff\xff");                            // 4 billion entries claimed
  EXPECT_FALSE(parse_index(hostile, back, error));
  EXPECT_TRUE(back.empty());
  // Cut anywhere: refused, never over-read.
  for (std::size_t n = 0; n < v.payload.size(); ++n) EXPECT_FALSE(parse_index(v.payload.substr(0, n), back, error)) << n;
  std::uint64_t off = 0;
  EXPECT_TRUE(parse_trailer(encode_trailer(12345), off));
  EXPECT_EQ(off, 12345u);
  EXPECT_FALSE(parse_trailer("not a trailer....", off));
}

TEST(RecordingFormat, FindChunkPicksTheLastKeyframeChunkAtOrBefore) {
  std::vector<ChunkInfo> c = {{0, 0, 0, 0, 0, true, 20}, {0, 20, 10, 0, 0, true, 20}, {0, 40, 20, 0, 0, false, 20},
                              {0, 60, 30, 0, 0, true, 20}, {0, 80, 30, 5, 0, true, 20}};
  EXPECT_EQ(find_chunk(c, -5), 0u);
  EXPECT_EQ(find_chunk(c, 0), 0u);
  EXPECT_EQ(find_chunk(c, 15), 1u);
  EXPECT_EQ(find_chunk(c, 25), 1u);  // chunk 2 does not start with a keyframe
  EXPECT_EQ(find_chunk(c, 30), 3u);
  EXPECT_EQ(find_chunk(c, 30, 7), 4u);  // a stoppage (repeated time)
  EXPECT_EQ(find_chunk(c, 1000), 4u);
  EXPECT_EQ(find_chunk({}, 3), 0u);
}

// The server's recordings: a chunk of control messages only (frame count 0,
// time 0) before every keyframe chunk, a keyframe every 200 frames (100
// cycles) and chunks of 20 frames (10 cycles) between. A seek must land
// where a walk of every chunk would, at every time; the soak found seeks to
// cycles 36 and 117 landing on 171 when the search took those 0s as times.
TEST(RecordingFormat, FindChunkLooksPastChunksOfControlMessagesOnly) {
  std::vector<ChunkInfo> c;
  std::uint32_t seq = 0;
  for (int t = 1; t < 1000; t += 10) {
    const bool key = (t - 1) % 100 == 0;
    if (key) c.push_back({0, 0, 0, 0, 0, false, 0});  // the messages before the keyframe
    c.push_back({0, seq, t, 0, 0, key, 20});
    seq += 20;
  }
  const auto walk = [&](int time) {  // the reference: the last keyframe chunk at or before
    std::size_t best = 0;
    for (std::size_t i = 0; i < c.size(); ++i)
      if (c[i].frame_count > 0 && c[i].starts_with_keyframe && c[i].first_time <= time) best = i;
    return best;
  };
  for (int time = -3; time < 1010; ++time) ASSERT_EQ(find_chunk(c, time), walk(time)) << "time " << time;
  EXPECT_EQ(c[find_chunk(c, 36)].first_time, 1);
  EXPECT_EQ(c[find_chunk(c, 117)].first_time, 101);
  // Only control messages, or nothing with frames after the first: no crash, chunk 0.
  EXPECT_EQ(find_chunk({{0, 0, 0, 0, 0, false, 0}, {0, 0, 0, 0, 0, false, 0}}, 50), 0u);
}

}  // namespace
}  // namespace mc::proto::rec

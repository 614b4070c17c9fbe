// The recording's frame stream (proto/frame_stream.hpp, recording format 3):
// the frames it gives back are the frames the wire codec gives back, header
// field for field, and damaged streams are refused, never over-read.
#include "proto/frame_stream.hpp"

#include <gtest/gtest.h>

#include "proto/recording.hpp"
#include "tests/proto/support/synthetic.hpp"

namespace mc::proto {
namespace {

// Frames whose headers change the way a real game's do, and some ways it
// rarely does: a seq gap, a time jump back (a stoppage replay), a stoppage
// count, play-mode and score changes, jitter, a stall and jumps in server time.
std::vector<PoseFrame> awkward_frames(const SkeletonDef& s, int n) {
  auto frames = testing::scripted_frames(s, n);
  std::uint64_t clock = 1763769600123ull;
  for (int i = 0; i < n; ++i) {
    PoseFrame& f = frames[static_cast<std::size_t>(i)];
    clock += i % 7 == 3 ? 49 : i % 11 == 5 ? 1250 : 50;
    f.server_time_ms = clock;
    if (i == 30) f.server_time_ms = 0;  // a source without a clock, then back: jumps of 2^40 ms
    if (i == 31) f.server_time_ms = ~std::uint64_t{0} - 3;
    if (i >= 9) f.seq += 5;                      // a gap: the encoder makes a keyframe
    if (i >= 14 && i < 20) f.time = 14, f.stoppage = i - 13;  // a stoppage
    if (i >= 17) f.play_mode = PlayMode::FreeKickL;
    if (i >= 25) f.score_left = 1;
  }
  return frames;
}

struct Streamed {
  std::vector<std::string> chunks;      // each chunk's stream bytes
  std::vector<StreamStart> starts;      // and its first frame's fields
  std::vector<std::uint32_t> counts;    // and its frame count
  std::vector<FrameHeader> headers;     // every frame's header, as coded
};

Streamed stream(const SkeletonDef& s, const std::vector<PoseFrame>& frames, std::size_t chunk_frames,
                int keyframe_interval) {
  FrameEncoder enc(s, EncoderOptions{keyframe_interval});
  FrameStreamEncoder st(enc);
  Streamed out;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (st.frame_count() == 0)
      out.starts.push_back({frames[i].seq, frames[i].time, frames[i].stoppage, frames[i].substep});
    out.headers.push_back(st.add(frames[i]));
    if (st.frame_count() == chunk_frames || i + 1 == frames.size()) {
      out.counts.push_back(st.frame_count());
      out.chunks.push_back(st.finish());
    }
  }
  return out;
}

TEST(FrameStream, GivesBackWhatTheWireCodecGivesBack) {
  const SkeletonDef s = testing::humanoid_skeleton();
  const auto frames = awkward_frames(s, 40);
  const Streamed st = stream(s, frames, 7, 10);
  ASSERT_EQ(st.chunks.size(), 6u);

  // The reference: the same frames through the wire codec.
  FrameEncoder wire_enc(s, EncoderOptions{10});
  FrameDecoder wire_dec(s);
  FrameDecoder dec(s);
  std::size_t n = 0;
  std::string error;
  for (std::size_t c = 0; c < st.chunks.size(); ++c) {
    FrameStreamDecoder sd(dec, st.chunks[c], st.starts[c], st.counts[c]);
    for (std::uint32_t k = 0; k < st.counts[c]; ++k, ++n) {
      bool key = false;
      const std::string bytes = wire_enc.encode(frames[n], key);
      EXPECT_EQ(key, st.headers[n].keyframe) << n;
      PoseFrame want, got;
      ASSERT_TRUE(wire_dec.decode(bytes, want, error)) << error;
      ASSERT_TRUE(sd.next(got, error)) << "frame " << n << ": " << error;
      EXPECT_EQ(got.seq, want.seq);
      EXPECT_EQ(got.time, want.time);
      EXPECT_EQ(got.stoppage, want.stoppage);
      EXPECT_EQ(got.substep, want.substep);
      EXPECT_EQ(got.server_time_ms, want.server_time_ms) << n;
      EXPECT_EQ(got.play_mode, want.play_mode);
      EXPECT_EQ(got.score_left, want.score_left);
      EXPECT_EQ(got.ball.x, want.ball.x);
      for (std::size_t p = 0; p < kMaxPlayers; ++p) {
        EXPECT_EQ(got.players[p].x, want.players[p].x);
        EXPECT_EQ(got.players[p].heading, want.players[p].heading);
        for (int d = 0; d < s.dof_count(); ++d)
          ASSERT_EQ(got.players[p].angles[static_cast<std::size_t>(d)], want.players[p].angles[static_cast<std::size_t>(d)])
              << "frame " << n << " player " << p << " dof " << d;
      }
    }
    // Asking for more than the chunk holds is refused.
    PoseFrame extra;
    EXPECT_FALSE(sd.next(extra, error));
  }
  EXPECT_EQ(n, frames.size());
  EXPECT_TRUE(st.headers[9].keyframe);  // after the seq gap
  // A header costs a few bits, not the 26 bytes of the wire, even with
  // these awkward headers: at least 20 bytes a frame less than the wire.
  std::size_t stream_bytes = 0, wire_bytes = 0;
  for (const auto& c : st.chunks) stream_bytes += c.size();
  FrameEncoder again(s, EncoderOptions{10});
  for (const auto& f : frames) {
    bool key = false;
    wire_bytes += again.encode(f, key).size();
  }
  EXPECT_LT(stream_bytes + 20 * frames.size(), wire_bytes);
}

TEST(FrameStream, ATruncatedOrDamagedStreamIsRefusedNeverOverRead) {
  const SkeletonDef s = testing::humanoid_skeleton();
  const auto frames = awkward_frames(s, 12);
  const Streamed st = stream(s, frames, 12, 100);
  ASSERT_EQ(st.chunks.size(), 1u);
  const std::string& bytes = st.chunks[0];
  std::string error;
  const auto read_all = [&](std::string_view b, std::uint32_t count) {
    FrameDecoder dec(s);
    FrameStreamDecoder sd(dec, b, st.starts[0], count);
    PoseFrame f;
    std::uint32_t good = 0;
    while (good < count && sd.next(f, error)) ++good;
    return good;
  };
  EXPECT_EQ(read_all(bytes, 12), 12u);
  // Cut anywhere: never all 12 frames (the last one's end is missing).
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    const std::string cut = bytes.substr(0, n);  // its own allocation: ASan sees an over-read
    EXPECT_LT(read_all(cut, 12), 12u) << n;
    EXPECT_FALSE(error.empty());
  }
  // Bytes after the last frame: refused at the last frame.
  EXPECT_EQ(read_all(bytes + std::string("\x01\x02", 2), 12), 11u);
  EXPECT_NE(error.find("after its last frame"), std::string::npos) << error;
  // A chunk that says it holds fewer frames than the stream: refused too.
  EXPECT_EQ(read_all(bytes, 5), 4u);
  // Every single-byte change: refused or decoded, never a crash.
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    std::string bad = bytes;
    bad[i] = static_cast<char>(bad[i] ^ 0x5a);
    read_all(bad, 12);
  }
}

TEST(FrameStream, ChunksCarryStreamFramesBetweenControlMessages) {
  const SkeletonDef s = testing::humanoid_skeleton();
  const auto frames = testing::scripted_frames(s, 6);
  FrameEncoder enc(s);
  FrameStreamEncoder st(enc);
  rec::ChunkBuilder b;
  b.add_control(R"({"type":"play_mode"})");
  for (const auto& f : frames) {
    b.add_stream_frame(st.add(f));
    if (f.seq == 2) b.add_control(R"({"type":"kick"})");
  }
  rec::ChunkInfo info;
  const std::string record = b.finish(info, st.finish());
  EXPECT_EQ(info.frame_count, 6u);
  rec::RecordView v;
  std::string error;
  ASSERT_EQ(rec::parse_record(record, v, error), rec::RecordStatus::Ok) << error;
  rec::ChunkInfo parsed;
  std::vector<rec::ChunkEntry> entries;
  std::string_view frame_stream;
  ASSERT_TRUE(rec::parse_chunk(v.payload, parsed, entries, error, rec::kFormatMajor, &frame_stream)) << error;
  ASSERT_EQ(entries.size(), 8u);
  EXPECT_EQ(entries[0].bytes, R"({"type":"play_mode"})");
  EXPECT_EQ(entries[4].kind, rec::ChunkEntry::Kind::Control);  // after frames 0, 1, 2
  EXPECT_EQ(entries[4].bytes, R"({"type":"kick"})");
  EXPECT_EQ(entries[7].kind, rec::ChunkEntry::Kind::StreamFrame);
  FrameDecoder dec(s);
  FrameStreamDecoder sd(dec, frame_stream, {parsed.first_seq, parsed.first_time, parsed.first_stoppage,
                                            parsed.first_substep}, 6);
  PoseFrame f;
  for (const auto& want : frames) {
    ASSERT_TRUE(sd.next(f, error)) << error;
    EXPECT_EQ(f.seq, want.seq);
  }
  // A payload cut anywhere is refused by the chunk parser or by the stream.
  for (std::size_t n = 0; n < v.payload.size(); ++n) {
    const std::string cut(v.payload.substr(0, n));
    if (!rec::parse_chunk(cut, parsed, entries, error, rec::kFormatMajor, &frame_stream)) continue;
    FrameDecoder d(s);
    FrameStreamDecoder cs(d, frame_stream, {parsed.first_seq, parsed.first_time, parsed.first_stoppage,
                                            parsed.first_substep}, 6);
    bool all = true;
    for (int k = 0; k < 6 && all; ++k) all = cs.next(f, error);
    EXPECT_FALSE(all) << n;
  }
  // A run of stream frames longer than the chunk's frame count is refused
  // before anything is allocated for it.
  std::string hostile(v.payload);
  const std::size_t run = hostile.find(std::string("\x04\x03", 2));  // the run of frames 0, 1, 2
  ASSERT_NE(run, std::string::npos);
  // 2^32 - 1 frames: without the bound, inserting their entries would ask
  // for ~170 GB and throw.
  hostile.replace(run + 1, 1, std::string("\xff\xff\xff\xff\x0f", 5));
  EXPECT_FALSE(rec::parse_chunk(hostile, parsed, entries, error, rec::kFormatMajor, &frame_stream));
  EXPECT_NE(error.find("bad entry"), std::string::npos) << error;
}

}  // namespace
}  // namespace mc::proto

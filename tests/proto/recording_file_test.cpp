// Recording files: server/record's writer and reader, crash safety (a
// writer SIGKILLed mid-stream) and the committed golden recording.
#include "server/record/recording_reader.hpp"
#include "server/record/recording_writer.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "proto/control_messages.hpp"
#include "proto/frame_codec.hpp"
#include "tests/proto/support/synthetic.hpp"

namespace mc::record {
namespace {

namespace fs = std::filesystem;

class RecordingFile : public ::testing::Test {
 protected:
  void SetUp() override {
    char tmpl[] = "/tmp/mc-rec-test-XXXXXX";
    ASSERT_NE(::mkdtemp(tmpl), nullptr);
    dir = tmpl;
    hello.skeleton = proto::testing::humanoid_skeleton();
    hello.left.name = "L";
    hello.right.name = "R";
    frames = proto::testing::scripted_frames(hello.skeleton, 200);
    proto::FrameEncoder enc(hello.skeleton);
    for (const auto& f : frames) {
      bool key = false;
      encoded.push_back(enc.encode(f, key));
    }
  }
  void TearDown() override { fs::remove_all(dir); }

  // Writes frames [0, n) with a kick event after frame 30; closes when asked.
  std::string write(std::size_t n, bool close, WriterOptions options = {}) {
    const std::string path = dir + "/game.mcrec";
    RecordingWriter w;
    std::string error;
    EXPECT_TRUE(w.open(path, proto::to_json(hello), error, options)) << error;
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_TRUE(w.add_frame(encoded[i], error)) << error;
      if (i == 30) {
        EXPECT_TRUE(w.add_control(proto::to_json(proto::ControlMessage{proto::KickEvent{30, 15, Side::Left, 7, proto::Foot::Right, 1500}}), error));
      }
    }
    if (close) {
      EXPECT_TRUE(w.close(error)) << error;
    } else {
      EXPECT_TRUE(w.flush(error)) << error;
      // Leave without an index, as a killed writer would (the destructor
      // would close properly, so detach the file by copying it first).
      fs::copy_file(path, path + ".unclosed");
    }
    return close ? path : path + ".unclosed";
  }

  std::string dir;
  proto::Hello hello;
  std::vector<PoseFrame> frames;
  std::vector<std::string> encoded;
};

TEST_F(RecordingFile, ClosedFileReadsBackEveryFrameAndControl) {
  const std::string path = write(200, true);
  RecordingReader r;
  std::string error;
  ASSERT_TRUE(r.open(path, error)) << error;
  EXPECT_FALSE(r.recovered());
  EXPECT_EQ(r.hello().left.name, "L");
  EXPECT_EQ(r.frame_count(), 200u);
  EXPECT_EQ(r.chunks().size(), 10u);  // one per keyframe interval
  PoseFrame f;
  std::vector<std::string> controls;
  std::uint32_t n = 0;
  while (r.next(f, error, &controls)) {
    EXPECT_EQ(f.seq, frames[n].seq);
    EXPECT_NEAR(f.players[3].x, frames[n].players[3].x, 0.01);
    ++n;
  }
  EXPECT_TRUE(error.empty()) << error;
  EXPECT_EQ(n, 200u);
  ASSERT_EQ(controls.size(), 1u);
  EXPECT_NE(controls[0].find("\"kick\""), std::string::npos);
}

TEST_F(RecordingFile, AKnownHelloIsSharedOnlyWithTheSameHello) {
  // The relay opens a reader per replay spectator and gives each the hello
  // the catalog read: it must be taken for the same file, and never for a
  // file whose hello differs (another game written under the same name).
  const std::string path = write(40, true);
  RecordingReader first;
  std::string error;
  ASSERT_TRUE(first.open(path, error)) << error;
  const auto known = first.shared_hello();
  RecordingReader again;
  ASSERT_TRUE(again.open(path, error, known)) << error;
  EXPECT_EQ(again.shared_hello(), known);

  hello.left.name = "Other";
  const std::string other = write(40, true);
  RecordingReader changed;
  ASSERT_TRUE(changed.open(other, error, known)) << error;
  EXPECT_NE(changed.shared_hello(), known);
  EXPECT_EQ(changed.hello().left.name, "Other");
  PoseFrame f;
  EXPECT_TRUE(changed.next(f, error)) << error;
}

TEST_F(RecordingFile, TranscodingKeepsEveryDecodedValue) {
  for (int interval : {0, 7, 40}) {
    WriterOptions options;
    options.sync = false;
    options.keyframe_interval = interval;
    const std::string path = write(200, true, options);
    RecordingReader r;
    std::string error;
    ASSERT_TRUE(r.open(path, error)) << error;
    proto::FrameDecoder stream(hello.skeleton);
    PoseFrame f, g;
    std::size_t n = 0;
    while (r.next(f, error)) {
      ASSERT_TRUE(stream.decode(encoded[n], g, error)) << error;
      ASSERT_EQ(f.seq, g.seq);
      ASSERT_EQ(f.server_time_ms, g.server_time_ms);
      for (std::size_t i = 0; i < f.players.size(); ++i) {
        ASSERT_EQ(f.players[i].x, g.players[i].x) << "interval " << interval << " frame " << n;
        ASSERT_EQ(f.players[i].heading, g.players[i].heading);
        ASSERT_EQ(f.players[i].angles, g.players[i].angles) << "interval " << interval << " frame " << n;
      }
      ++n;
    }
    EXPECT_EQ(n, 200u) << error;
  }
}

// The frame stream codes substep in one bit: a frame from the wire with
// another substep value is skipped and counted, never stored wrong.
TEST_F(RecordingFile, AFrameWithAnUnknownSubstepIsSkippedAndCounted) {
  const std::string path = dir + "/odd.mcrec";
  RecordingWriter w;
  std::string error;
  ASSERT_TRUE(w.open(path, proto::to_json(hello), error)) << error;
  for (std::size_t i = 0; i < 40; ++i) {
    std::string bytes = encoded[i];
    // Header byte 14, substep, of the stream's keyframe at seq 20 (even: 0):
    // 2 has the same parity, so the wire decoder reads the frames alike.
    if (i == 20) bytes[14] = 2;
    ASSERT_TRUE(w.add_frame(bytes, error)) << error;
  }
  ASSERT_TRUE(w.close(error)) << error;
  EXPECT_EQ(w.skipped_frames(), 1u);
  RecordingReader r;
  ASSERT_TRUE(r.open(path, error)) << error;
  PoseFrame f;
  std::size_t n = 0;
  while (r.next(f, error)) {
    EXPECT_LE(f.substep, 1);
    EXPECT_NE(f.seq, frames[20].seq);
    ++n;
  }
  EXPECT_TRUE(error.empty()) << error;
  EXPECT_EQ(n, 39u);  // frame 21 starts a keyframe (a seq gap after the skip)
}

TEST_F(RecordingFile, SeeksToAnySimulationTime) {
  const std::string path = write(200, true);
  RecordingReader r;
  std::string error;
  ASSERT_TRUE(r.open(path, error)) << error;
  PoseFrame f;
  for (int t : {0, 1, 9, 10, 11, 37, 50, 99}) {
    ASSERT_TRUE(r.seek(t, f, error)) << t << ": " << error;
    EXPECT_EQ(f.time, t);
    EXPECT_EQ(f.substep, 0);
    EXPECT_NEAR(f.players[5].y, frames[f.seq].players[5].y, 0.01);
    PoseFrame g;
    ASSERT_TRUE(r.next(g, error));  // playback continues after a seek
    EXPECT_EQ(g.seq, f.seq + 1);
  }
  EXPECT_FALSE(r.seek(100000, f, error));
  EXPECT_NE(error.find("after the end"), std::string::npos) << error;
}

// A seek forward with no keyframe on the way goes on from where the reader
// is, and finds what a seek from the keyframe finds: every pair of times,
// both ways, against a reader that seeks afresh.
TEST_F(RecordingFile, ASeekForwardGoesOnFromWhereItIs) {
  const std::string path = write(200, true, WriterOptions{.max_chunk_frames = 20, .sync = false, .keyframe_interval = 60});
  std::string error;
  PoseFrame f, g;
  for (int a : {0, 5, 20, 29, 31, 44, 70}) {
    for (int b : {0, 6, 21, 30, 45, 62, 99}) {
      RecordingReader r, fresh;
      ASSERT_TRUE(r.open(path, error)) << error;
      ASSERT_TRUE(fresh.open(path, error)) << error;
      ASSERT_TRUE(r.seek(a, f, error)) << a << ": " << error;
      const std::uint64_t before = r.decoded_frames();
      ASSERT_TRUE(r.seek(b, f, error)) << a << " -> " << b << ": " << error;
      ASSERT_TRUE(fresh.seek(b, g, error)) << b << ": " << error;
      EXPECT_EQ(f.seq, g.seq) << a << " -> " << b;
      EXPECT_EQ(f.time, b);
      ASSERT_EQ(f.players.size(), g.players.size());
      for (std::size_t i = 0; i < f.players.size(); ++i) {
        EXPECT_EQ(f.players[i].x, g.players[i].x) << a << " -> " << b;
        EXPECT_EQ(f.players[i].angles, g.players[i].angles) << a << " -> " << b;
      }
      // Frames 2t and 2t+1 are at time t; keyframes at frames 0, 60, 120, 180.
      const std::uint64_t cost = r.decoded_frames() - before;
      if (b > a && b * 2 / 60 == a * 2 / 60) {
        EXPECT_EQ(cost, static_cast<std::uint64_t>(2 * (b - a))) << a << " -> " << b;
      } else {
        EXPECT_EQ(cost, fresh.decoded_frames()) << a << " -> " << b;
      }
      ASSERT_TRUE(r.next(f, error));
      ASSERT_TRUE(fresh.next(g, error));
      EXPECT_EQ(f.seq, g.seq);
    }
  }
}

TEST_F(RecordingFile, UnclosedFileIsRecoveredFromItsRecords) {
  const std::string path = write(95, false);
  RecordingReader r;
  std::string error;
  ASSERT_TRUE(r.open(path, error)) << error;
  EXPECT_TRUE(r.recovered());
  EXPECT_EQ(r.frame_count(), 95u);
  PoseFrame f;
  ASSERT_TRUE(r.seek(40, f, error)) << error;
  EXPECT_EQ(f.time, 40);
}

// The scan reads records a block (64 KB) at a time: a file of many blocks,
// with records across every block's end, is recovered whole.
TEST_F(RecordingFile, UnclosedFileOfManyReadBlocksIsRecoveredWhole) {
  const auto many = proto::testing::scripted_frames(hello.skeleton, 4000);
  const std::string path = dir + "/long.mcrec";
  {
    RecordingWriter w;
    std::string error;
    ASSERT_TRUE(w.open(path, proto::to_json(hello), error)) << error;
    proto::FrameEncoder enc(hello.skeleton);
    for (const auto& f : many) {
      bool key = false;
      ASSERT_TRUE(w.add_frame(enc.encode(f, key), error)) << error;
    }
    ASSERT_TRUE(w.flush(error)) << error;
    fs::copy_file(path, path + ".unclosed");  // without the index the destructor writes
  }
  ASSERT_GT(fs::file_size(path + ".unclosed"), 3u * (64u << 10)) << "the file must span several read blocks";
  RecordingReader closed, unclosed;
  std::string error;
  ASSERT_TRUE(closed.open(path, error)) << error;
  ASSERT_TRUE(unclosed.open(path + ".unclosed", error)) << error;
  EXPECT_FALSE(closed.recovered());
  EXPECT_TRUE(unclosed.recovered());
  EXPECT_EQ(unclosed.frame_count(), many.size());
  ASSERT_EQ(unclosed.chunks().size(), closed.chunks().size());
  for (std::size_t i = 0; i < closed.chunks().size(); ++i) {
    EXPECT_EQ(unclosed.chunks()[i].offset, closed.chunks()[i].offset) << i;
    EXPECT_EQ(unclosed.chunks()[i].first_time, closed.chunks()[i].first_time) << i;
  }
  PoseFrame f;
  ASSERT_TRUE(unclosed.seek(many.back().time, f, error)) << error;
  EXPECT_EQ(f.time, many.back().time);
}

TEST_F(RecordingFile, FileCutAnywhereKeepsEveryCompleteChunk) {
  const std::string path = write(200, true);
  const auto size = fs::file_size(path);
  std::ifstream in(path, std::ios::binary);
  const std::string all((std::istreambuf_iterator<char>(in)), {});
  const std::size_t hello_end =
      proto::rec::kFileHeaderSize + proto::rec::encode_record(proto::rec::RecordType::Hello, proto::to_json(hello)).size();
  for (std::size_t cut = 0; cut < size; cut += 97) {
    const std::string p = dir + "/cut.mcrec";
    std::ofstream(p, std::ios::binary | std::ios::trunc) << all.substr(0, cut);
    RecordingReader r;
    std::string error;
    if (!r.open(p, error)) {
      EXPECT_LT(cut, hello_end) << "only a file without a complete hello may be refused: " << error;
      continue;
    }
    PoseFrame f;
    std::uint64_t n = 0;
    while (r.next(f, error)) ++n;
    EXPECT_TRUE(error.empty()) << cut << ": " << error;
    EXPECT_EQ(n, r.frame_count());
    EXPECT_EQ(n % 20, 0u) << "whole chunks only, cut at " << cut;
  }
}

TEST_F(RecordingFile, SigkilledWriterLosesAtMostOneSecond) {
  const std::string path = dir + "/killed.mcrec";
  int pipefd[2];
  ASSERT_EQ(::pipe(pipefd), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // The child writes frames at about 1 kHz and reports each one it added.
    ::close(pipefd[0]);
    RecordingWriter w;
    std::string error;
    if (!w.open(path, proto::to_json(hello), error, {20, false})) ::_exit(2);
    for (std::uint32_t i = 0;; ++i) {
      if (!w.add_frame(encoded[i], error)) ::_exit(3);
      if (::write(pipefd[1], &i, sizeof i) != sizeof i) ::_exit(4);
      std::this_thread::sleep_for(std::chrono::microseconds(500));
      if (i == 190) for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));  // stop within one stream
    }
  }
  ::close(pipefd[1]);
  std::uint32_t last = 0, got = 0;
  while (::read(pipefd[0], &got, sizeof got) == sizeof got) {
    last = got;
    if (last >= 137) break;  // mid-chunk
  }
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  // Frames the child added between our last read and the kill.
  while (::read(pipefd[0], &got, sizeof got) == sizeof got) last = got;
  ::close(pipefd[0]);
  ASSERT_TRUE(WIFSIGNALED(status));

  RecordingReader r;
  std::string error;
  ASSERT_TRUE(r.open(path, error)) << error;
  EXPECT_TRUE(r.recovered());
  const std::uint64_t added = last + 1;
  EXPECT_LE(r.frame_count(), added);
  EXPECT_GE(r.frame_count() + 20, added) << "more than one chunk (1 s) lost";
  PoseFrame f;
  std::uint64_t n = 0;
  while (r.next(f, error)) {
    EXPECT_EQ(f.seq, frames[n].seq);
    ++n;
  }
  EXPECT_TRUE(error.empty()) << error;
  EXPECT_EQ(n, r.frame_count());
}

// The committed golden recordings (written by proto_golden_gen from the
// golden frames, one per format major) must stay readable by every later
// version.
class GoldenRecording : public ::testing::TestWithParam<std::string> {};

TEST_P(GoldenRecording, StaysReadable) {
  const std::string dir = std::string(MATCHCAST_SOURCE_DIR) + "/tests/proto/golden/";
  RecordingReader r;
  std::string error;
  ASSERT_TRUE(r.open(dir + GetParam(), error)) << error;
  EXPECT_FALSE(r.recovered());
  std::ifstream in(dir + "frames_v1.json");
  std::stringstream ss;
  ss << in.rdbuf();
  const auto golden = nlohmann::json::parse(ss.str());
  const auto& expected = golden.at("frames");
  ASSERT_EQ(r.frame_count(), expected.size());
  PoseFrame f;
  std::vector<std::string> controls;
  std::size_t n = 0;
  while (r.next(f, error, &controls)) {
    const auto& e = expected.at(n).at("expected");
    EXPECT_EQ(f.seq, e.at("seq").get<std::uint32_t>());
    EXPECT_NEAR(f.ball.x, e.at("ball").at("x").get<double>(), 1e-4);
    for (int d = 0; d < r.hello().skeleton.dof_count(); ++d)
      EXPECT_NEAR(f.players[4].angles[static_cast<std::size_t>(d)],
                  e.at("players").at(4).at("angles").at(static_cast<std::size_t>(d)).get<double>(), 1e-4);
    ++n;
  }
  EXPECT_EQ(n, expected.size());
  ASSERT_EQ(controls.size(), 2u);
  EXPECT_NE(controls[0].find(R"("type":"kick")"), std::string::npos) << controls[0];
  EXPECT_NE(controls[1].find(R"("type":"goal")"), std::string::npos) << controls[1];
  ASSERT_TRUE(r.seek(expected.at(12).at("expected").at("time").get<int>(), f, error)) << error;
}

INSTANTIATE_TEST_SUITE_P(EveryFormat, GoldenRecording,
                         ::testing::Values("recording_v1.mcrec", "recording_v2.mcrec", "recording_v3.mcrec"));

}  // namespace
}  // namespace mc::record

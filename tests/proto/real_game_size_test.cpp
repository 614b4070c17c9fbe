// Issue 5's size targets, on the two real full games in tests/data/rcg, as a
// test that fails when a change to anim or proto breaks them: the stream's
// mean frame size (<= 300 B) and the server's recording of the whole game
// with its control messages. The benchmark (bench/pose_stream_bench.cpp)
// prints these figures and the rest.
//
// The recording's target is 3 MB, and it is NOT met since issue 23: planted
// feet at a run are real motion that costs 6 % more (3.195 and 3.174 MB;
// proto/SPEC.md section 7 has where the bits go and what was tried). The
// benchmark still reports the 3 MB target as not met. This test guards the
// measured size instead (kRecordingBound), so that a change that makes the
// file bigger still fails here; lower the bound to 3 MB when the codec or
// the animation wins the 6 % back. Raised since, first from 3.200 to 3.205
// MB: the arms lifted clear of the thighs (issue 23, 955 player-frames with
// a hand inside a thigh to 0) cost 0.2 % (3.195 -> 3.202 MB); then to 3.210
// MB: 6 cm of clearance instead of 3, so that no hand passes through a
// thigh in the clients' 60 Hz blend either (10 and 4 drawn frames to 0),
// 0.15 % (3.202 -> 3.207 MB). Then to 3.215 MB: feet in the air kept 5 cm
// off the grass (anim/swing_clearance.hpp, the clients' sliding at 60 Hz)
// cost 0.09 % (3,208,492 -> 3,211,314 B; game 2 3,186,532 -> 3,189,378).
// Soles kept apart and kicks reached with the hip (anim/footsteps.cpp,
// anim/kick_reach.hpp) added 0.04 % within it (3,212,641 B; game 2
// 3,190,808). Then to 3.235 MB: the animator rounds its frames to the
// grid itself, the hip and knee of each leg on the grass to the grid point
// either side that keeps its ankle put (anim/grid_rounding.hpp; the
// grounded foot's speed at 20 Hz a third lower), 0.6 % (3,212,710 ->
// 3,232,598 B; game 2 3,190,787 -> 3,210,099). Then to 3.240 MB: a
// sprinter's foot on the grass for two frames, not one (anim/footsteps.cpp;
// the 9+ m/s band's grounded foot at 60 Hz 3.9 -> 0.6 m/s), 0.13 %
// (3,236,762 B; game 2 3,216,463). Legs turned apart where the clients'
// blend brings them through each other (anim/drawn_leg_clearance.hpp)
// added 77 B within it (3,236,839 B; game 2 3,216,534). Then to 3.245 MB:
// a foot in the air kept higher the further it travels with the body
// (anim/swing_clearance.hpp; every grounded-foot band at the clients' 60 Hz
// within issue 23's 0.5 m/s), 0.16 % (3,241,954 B; game 2 3,222,392).
// The knee's and the hip's flexion turns apart at the frame, in 2-deg
// steps (anim/drawn_leg_clearance.cpp): 3,241,888 B; game 2 3,222,332.
// The clients' blend checked over the whole frame, in 4-deg steps:
// 3,241,920 B; game 2 3,222,362. Turns checked as the stream rounds
// them, refused steps halved, whole-body actions checked too (and a
// thigh kept off its own hand):
// 3,241,916 B; game 2 3,222,367. A knee's own speed limit, the kicking
// foot kept off the grass after contact and hands checked in the blend
// more often (2026-11-30, session 33): 3,241,205 B; game 2 3,221,535;
// the drawn-leg check's knee on its own limit: 3,241,206 B; 3,221,533.
// A foot left crossed behind the other uncrosses a pass length off
// (session 34): 3,241,136 B; 3,221,237. Its way checked past a foot that
// lifts, landing steps bounded, drawn travel held within 0.54 m:
// 3,241,467 B; 3,221,198.
#include <gtest/gtest.h>

#include <cstdio>

#include <sys/stat.h>
#include <unistd.h>

#include "proto/frame_codec.hpp"
#include "proto/hello.hpp"
#include "server/record/recording_reader.hpp"
#include "server/record/recording_writer.hpp"
#include "tests/proto/support/real_game.hpp"

namespace mc::proto {
namespace {

class RealGameSize : public ::testing::TestWithParam<const char*> {};

TEST_P(RealGameSize, StreamAndRecordingMeetTheirTargets) {
  testing::RealGame game;
  std::string error;
  const std::string log = std::string(MATCHCAST_TEST_RCG_DIR) + "/full/" + GetParam();
  ASSERT_TRUE(testing::load_real_game(log, true, 0, game, error)) << error;
  if (game.animated_by != "anim::Animator") GTEST_SKIP() << "anim is not built: the targets are for its frames";
  ASSERT_GT(game.frames.size(), 12000u);  // a whole game: 6,000 cycles at 20 Hz and more
  ASSERT_GT(game.controls.size(), 1000u);  // stamina every second, kicks, play modes

  FrameEncoder enc(game.skeleton);
  std::vector<std::string> encoded;
  std::size_t bytes = 0;
  for (const auto& f : game.frames) {
    bool key = false;
    encoded.push_back(enc.encode(f, key));
    bytes += encoded.back().size();
  }
  EXPECT_LE(static_cast<double>(bytes) / static_cast<double>(encoded.size()), 300.0);

  Hello hello;
  hello.skeleton = game.skeleton;
  hello.left.name = game.left_name;
  hello.right.name = game.right_name;
  const std::string path = ::testing::TempDir() + "size-" + std::to_string(::getpid()) + ".mcrec";
  {
    record::RecordingWriter w;
    record::WriterOptions options;  // the server's: a keyframe every 200 frames in the file
    options.sync = false;
    ASSERT_TRUE(w.open(path, to_json(hello), error, options)) << error;
    testing::for_each_in_stream_order(
        game, [&](std::size_t i) { EXPECT_TRUE(w.add_frame(encoded[i], error)) << error; },
        [&](const std::string& text) { EXPECT_TRUE(w.add_control(text, error)) << error; });
    ASSERT_TRUE(w.close(error)) << error;
  }
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  constexpr off_t kRecordingBound = 3'245'000;  // the target is 3'000'000: see the top of this file
  EXPECT_LE(st.st_size, kRecordingBound) << "the recording of a full game grew past its measured size";
  if (st.st_size > 3'000'000)
    std::printf("[ target ] recording %lld B: over the 3 MB target (not met since issue 23)\n",
                static_cast<long long>(st.st_size));

  // And it reads back whole.
  record::RecordingReader r;
  ASSERT_TRUE(r.open(path, error)) << error;
  EXPECT_FALSE(r.recovered());
  PoseFrame f;
  std::vector<std::string> controls;
  std::size_t n = 0;
  while (r.next(f, error, &controls)) ++n;
  EXPECT_TRUE(error.empty()) << error;
  EXPECT_EQ(n, game.frames.size());
  EXPECT_EQ(controls.size(), game.controls.size());
  EXPECT_EQ(r.skipped_frames(), 0u);
  ::unlink(path.c_str());
}

INSTANTIATE_TEST_SUITE_P(SharedFullGames, RealGameSize,
                         ::testing::Values("20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz",
                                           "20261122031059-HELIOS_A_4-vs-HELIOS_B_3.rcg.gz"));

}  // namespace
}  // namespace mc::proto

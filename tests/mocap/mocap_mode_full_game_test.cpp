// The animator's mocap mode (issue 9) on a whole real game: the quality
// targets of issue 4 hold with the CMU kicks, as in the keyframe mode
// (tests/anim/quality_full_games_test.cpp), and the kicks are the mocap ones.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "anim/animator.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/mocap/io/motion_source_files.hpp"
#include "anim/tools/metrics.hpp"
#include "server/ingest/state_source.hpp"

namespace mc::anim::mocap {
namespace {

TEST(MocapModeFullGame, TargetsHoldOnTheFirstGame) {
  std::string err;
  const auto source = io::load_mocap_motion_source(std::string(MATCHCAST_MOCAP_DIR) + "", err);
  ASSERT_NE(source, nullptr) << err;
  auto src = ingest::open_log(
      std::string(MATCHCAST_TEST_RCG_DIR) + "/full/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz", err);
  ASSERT_TRUE(src) << err;
  std::vector<WorldState> states;
  WorldState s;
  while (src->next(s)) states.push_back(s);
  ASSERT_GT(states.size(), 6000u);
  AnimConfig cfg;
  cfg.motion_source = source;
  std::vector<PoseFrame> frames, key_frames;
  std::vector<FrameInfo> infos;
  std::vector<AnimEvent> events;
  Animator a(human_skeleton(), src->params(), cfg);
  a.set_frame_info_sink(&infos);
  for (const WorldState& st : states) a.push(st, frames, &events);
  a.finish(frames, &events);
  ASSERT_EQ(frames.size(), 2 * states.size());
  const tools::QualityReport r =
      tools::measure(human_skeleton(), states, frames, infos, events, src->params().ball_size());
  EXPECT_TRUE(tools::targets_hold(r)) << tools::format_report(r);
  EXPECT_GT(r.kicks, 500);
  // The kicks really are the mocap ones: the kick frames differ from the keyframe mode's.
  Animator k(human_skeleton(), src->params());
  for (const WorldState& st : states) k.push(st, key_frames);
  k.finish(key_frames);
  ASSERT_EQ(key_frames.size(), frames.size());
  long differing = 0, in_action = 0;
  for (std::size_t i = 0; i < frames.size(); ++i)
    for (std::size_t p = 0; p < kMaxPlayers; ++p) {
      if (!infos[i].players[p].in_action) continue;
      ++in_action;
      differing += frames[i].players[p].angles != key_frames[i].players[p].angles;
    }
  EXPECT_GT(differing, in_action / 4) << differing << " of " << in_action;
}

}  // namespace
}  // namespace mc::anim::mocap

// The quality tool's targets on both full games of tests/data/rcg/full
// (issue 4): the same measurement as matchcast-anim-quality.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "anim/animator.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/tools/metrics.hpp"
#include "server/ingest/state_source.hpp"

namespace mc::anim::tools {
namespace {

void check_log(const char* name) {
  const std::string path = std::string(MATCHCAST_TEST_RCG_DIR) + "/full/" + name;
  std::string err;
  auto src = ingest::open_log(path, err);
  ASSERT_TRUE(src) << err;
  std::vector<WorldState> states;
  WorldState s;
  while (src->next(s)) states.push_back(s);
  ASSERT_GT(states.size(), 6000u);
  std::vector<PoseFrame> frames;
  std::vector<FrameInfo> infos;
  std::vector<AnimEvent> events;
  Animator a(human_skeleton(), src->params());
  a.set_frame_info_sink(&infos);
  for (const WorldState& st : states) a.push(st, frames, &events);
  a.finish(frames, &events);
  ASSERT_EQ(frames.size(), 2 * states.size());
  const QualityReport r = measure(human_skeleton(), states, frames, infos, events, src->params().ball_size());
  EXPECT_TRUE(targets_hold(r)) << name << "\n" << format_report(r);
  EXPECT_GT(r.kicks, 500);           // the game's kicks were found and animated
  EXPECT_GT(r.cadence.values.size(), 10000u);
}

TEST(QualityFullGames, TargetsHoldOnTheFirstGame) { check_log("20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz"); }
TEST(QualityFullGames, TargetsHoldOnTheSecondGame) { check_log("20261122031059-HELIOS_A_4-vs-HELIOS_B_3.rcg.gz"); }

}  // namespace
}  // namespace mc::anim::tools

// The whole pipeline on the real CMU clips: loaders, graph, pruning, map.
#include "anim/mocap/io/asset_cache.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "anim/mocap/graph_steer_job.hpp"
#include "anim/mocap/reach_overlay.hpp"

using namespace mc::anim::mocap;

namespace {
// The graph and map of the CMU clips in shared/, from the test cache.
bool load_real_assets(io::MocapAssets& a, std::string& error) {
  io::AssetOptions o;
  o.clips.dir = std::string(MATCHCAST_MOCAP_DIR) + "";
  o.map.start_node = -1;
  o.cache_dir = MATCHCAST_MOCAP_CACHE;
  return io::load_or_build_assets(o, a, error);
}
}  // namespace

TEST(CmuAssets, GraphAndMapFromTheRealClips) {
  io::MocapAssets a;
  std::string error;
  ASSERT_TRUE(load_real_assets(a, error)) << error;
  const auto& s = a.graph.stats;
  EXPECT_GT(s.frames, 2000);                // 17 clips at 30 Hz
  EXPECT_LT(s.nodes_after, s.frames);       // pruning removed dead ends
  EXPECT_GT(s.nodes_after, s.frames / 2);   // but kept most of the data
  EXPECT_GT(s.transitions_after, 500);
  // Both subjects (BVH subject 10 and ASF subject 16) are in the kept component.
  bool bvh = false, asf = false;
  for (const auto& n : a.graph.nodes) {
    const auto& name = a.graph.clip_names[n.clip];
    bvh = bvh || name.find(".bvh") != std::string::npos;
    asf = asf || name.find(".amc") != std::string::npos;
  }
  EXPECT_TRUE(bvh);
  EXPECT_TRUE(asf);
  // The human map is asymmetric: 3 m behind costs more than 3 m ahead.
  const auto& g = a.map.grid;
  const float ahead = a.map.cost[static_cast<std::size_t>(g.index(3.1f, 0.1f))];
  const float behind = a.map.cost[static_cast<std::size_t>(g.index(-2.9f, 0.1f))];
  ASSERT_NE(ahead, kUnreached);
  EXPECT_GT(behind, 1.5f * ahead);
  // Loading again gives the same graph from the cache.
  io::MocapAssets b;
  ASSERT_TRUE(load_real_assets(b, error)) << error;
  EXPECT_TRUE(b.from_cache);
  EXPECT_EQ(b.graph.targets, a.graph.targets);
  EXPECT_EQ(b.map.cost, a.map.cost);
  EXPECT_EQ(b.map_params.start_node, a.map_params.start_node);
}

TEST(CmuAssets, ReachModelForTheServer) {
  std::string error;
  const auto model = io::load_reach_model(std::string(MATCHCAST_MOCAP_DIR) + "", MATCHCAST_MOCAP_CACHE, error);
  ASSERT_TRUE(model) << error;
  EXPECT_GT(model->reference_speed, 0.8f);
  EXPECT_LT(model->reference_speed, 2.5f);
  ReachPlayer p;
  p.glide = 0;
  // Turning round costs: 8 m behind takes longer than 8 m ahead.
  EXPECT_GT(reach_time(*model, p, -8, 0), reach_time(*model, p, 8, 0) + 0.5f);
  EXPECT_FALSE(io::load_reach_model("/nonexistent", "", error));
  EXPECT_FALSE(error.empty());
}

TEST(CmuAssets, SteeringTheRealGraphTurnsBothWays) {
  io::MocapAssets a;
  std::string error;
  ASSERT_TRUE(load_real_assets(a, error)) << error;
  for (const float want : {-0.6f, 0.6f}) {
    int node = a.map_params.start_node;
    double turned = 0;
    const int frames = 300;
    for (int k = 0; k < frames; ++k) {
      int next = -1;
      GraphSteerJob job;
      job.graph = &a.graph;
      job.node = node;
      job.want_speed = 1.0f;
      job.want_turn = want;
      job.next = &next;
      ASSERT_TRUE(job.Run());
      node = next;
      turned += a.graph.nodes[static_cast<std::size_t>(node)].dyaw;
    }
    const double rate = turned / (frames / 30.0);
    EXPECT_GT(rate * want, 0.1) << "wanted " << want << " rad/s, got " << rate;
  }
}

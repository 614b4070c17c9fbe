#include "anim/mocap/mocap_blob.hpp"

#include <gtest/gtest.h>

#include "synthetic_motion.hpp"

using namespace mc::anim::mocap;

TEST(MocapBlob, GraphRoundTrips) {
  GraphBuildParams p;
  p.threshold_rms = 0.02f;
  const MotionGraph g = build_motion_graph({test::synthetic_walker(100, 20)}, p);
  ASSERT_GT(g.size(), 0);
  const std::string bytes = serialize_graph(g);
  MotionGraph back;
  std::string error;
  ASSERT_TRUE(deserialize_graph(bytes, back, error)) << error;
  EXPECT_EQ(back.size(), g.size());
  EXPECT_EQ(back.targets, g.targets);
  EXPECT_EQ(back.first_edge, g.first_edge);
  EXPECT_EQ(back.transition, g.transition);
  EXPECT_EQ(back.clip_names, g.clip_names);
  EXPECT_EQ(back.stats.transition_edges, g.stats.transition_edges);
  EXPECT_EQ(back.nodes[5].fwd, g.nodes[5].fwd);
  EXPECT_EQ(serialize_graph(back), bytes);
}

TEST(MocapBlob, GarbageIsRefusedWithoutCrashing) {
  GraphBuildParams p;
  p.threshold_rms = 0.02f;
  const std::string bytes = serialize_graph(build_motion_graph({test::synthetic_walker(60, 20)}, p));
  MotionGraph g;
  std::string error;
  EXPECT_FALSE(deserialize_graph("", g, error));
  EXPECT_FALSE(deserialize_graph("MCGRAPH1", g, error));
  for (std::size_t cut = 0; cut < bytes.size(); cut += 7) EXPECT_FALSE(deserialize_graph(bytes.substr(0, cut), g, error));
  std::string flipped = bytes;
  // An edge target past the node count.
  flipped[flipped.size() - 5] = '\xff';
  flipped[flipped.size() - 4] = '\xff';
  EXPECT_FALSE(deserialize_graph(flipped, g, error));
  EXPECT_FALSE(deserialize_graph(bytes + "x", g, error));
  // Every single-byte corruption is either refused or yields a consistent graph.
  for (std::size_t i = 8; i < bytes.size(); i += 3) {
    std::string c = bytes;
    c[i] = static_cast<char>(c[i] ^ 0x5a);
    if (deserialize_graph(c, g, error)) {
      for (auto t : g.targets) EXPECT_LT(t, g.nodes.size());
    }
  }
}

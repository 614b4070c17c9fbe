// A reach model whose answer is known, shared by the reach-map tests: a
// one-node graph that walks straight ahead at 1.5 m/s (0.05 m per 30 Hz
// frame), on a 10 x 10 m grid of 0.5 m cells, nothing else reachable.
#pragma once

#include <memory>

#include "anim/mocap/capability_map.hpp"
#include "anim/mocap/motion_graph.hpp"
#include "anim/mocap/reach_overlay.hpp"

namespace mc::anim::mocap::test {

inline std::shared_ptr<const ReachModel> straight_walker_reach_model() {
  MotionGraph g;
  GraphNode n;
  n.fwd = 0.05f;
  g.nodes = {n};
  g.first_edge = {0, 1};
  g.targets = {0};
  g.transition = {0};
  CapabilityParams p;
  p.grid = MapGrid{20, 20, 0.5f, -5, -5};
  p.iterations = 1;
  p.max_depth = 100;
  return std::make_shared<const ReachModel>(make_reach_model(compute_capability_map(g, p), 30));
}

}  // namespace mc::anim::mocap::test

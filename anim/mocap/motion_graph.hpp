// The motion graph (Kovar, Gleicher, Pighin 2002, as used by Sukthankar,
// Mandel and Sycara): frames are nodes; each frame has an edge to the next
// frame of its clip, and a transition edge i -> j+1 (and j -> i+1) wherever
// the window distance D(i, j) is under a threshold and a local minimum of the
// distance matrix. Sinks and dead ends are then removed by keeping only the
// largest strongly connected component (an iterative Tarjan, no recursion).
//
// Offline: build_motion_graph() is O(frames^2) window distances. The result
// is immutable runtime data (plain arrays, CSR adjacency) that can be
// serialized (mocap_blob.hpp).
//
// Ground-plane motion per node, in the frame of the previous frame's facing:
// `fwd` metres forward, `right` metres to the right, `dyaw` radians turned
// to the right (rcssserver's angle sense: +x forward, +y right).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "anim/mocap/mocap_clip.hpp"

namespace mc::anim::mocap {

struct GraphNode {
  std::uint16_t clip = 0;
  std::int32_t frame = 0;       // frame of the clip (after resampling)
  float fwd = 0, right = 0;     // m, root motion from the clip's previous frame
  float dyaw = 0;               // rad, turn to the right since the previous frame
  float speed = 0;              // m/s, ground speed averaged over +-0.25 s
};

struct GraphBuildParams {
  int window = 10;              // frames compared (1/3 s at 30 Hz), also the blend length
  float threshold_rms = 0.06f;  // m: sqrt(D / sum of weights) under this makes a transition
  int min_frame_gap = 10;       // no transitions between frames this close in one clip
};

struct GraphStats {
  int frames = 0;               // nodes before pruning
  int natural_edges = 0, transition_edges = 0;
  int components = 0;           // strongly connected components
  int nodes_after = 0, edges_after = 0, transitions_after = 0;
  double build_seconds = 0;     // filled by the caller that times it
};

struct MotionGraph {
  float hz = 30;
  int window = 10;
  std::vector<std::string> clip_names;
  std::vector<GraphNode> nodes;
  std::vector<std::uint32_t> first_edge;  // nodes + 1 offsets into `targets`
  std::vector<std::uint32_t> targets;     // node indices
  std::vector<std::uint8_t> transition;   // per edge: 1 = transition, 0 = next frame of the clip
  GraphStats stats;

  int size() const { return static_cast<int>(nodes.size()); }
  int degree(int n) const { return static_cast<int>(first_edge[static_cast<std::size_t>(n) + 1] - first_edge[static_cast<std::size_t>(n)]); }
  // Node index of (clip, frame), or -1 when pruned.
  int find(int clip, int frame) const;
};

// Builds the graph of all clips (same skeleton, same frame rate).
MotionGraph build_motion_graph(const std::vector<MocapClip>& clips, const GraphBuildParams& params = {});

// Strongly connected components of a CSR graph (iterative Tarjan):
// component id per node, ids 0..count-1. Returns the count.
int strongly_connected_components(const std::vector<std::uint32_t>& first_edge,
                                  const std::vector<std::uint32_t>& targets, std::vector<int>& component);

// Keeps the largest strongly connected component of `g` (nodes renumbered in
// order, edges kept when both ends stay); fills stats.components/..._after.
void keep_largest_scc(MotionGraph& g);

// Per-frame ground motion of a clip (size frames; the first frame is zero).
std::vector<GraphNode> clip_ground_motion(const MocapClip& clip, std::uint16_t clip_index);

}  // namespace mc::anim::mocap

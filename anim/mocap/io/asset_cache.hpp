// The motion graph and the walking capability map built from the CMU clips,
// cached as one file under a cache directory, named by a hash of the clip
// bytes and every parameter: tests, tools and the server load it instead of
// rebuilding it (the graph takes seconds, the map a few more).
#pragma once

#include <memory>
#include <string>

#include "anim/mocap/capability_map.hpp"
#include "anim/mocap/io/clip_files.hpp"
#include "anim/mocap/motion_graph.hpp"
#include "anim/mocap/reach_overlay.hpp"

namespace mc::anim::mocap::io {

struct AssetOptions {
  ClipSetOptions clips;
  GraphBuildParams graph{10, 0.08f, 10};
  CapabilityParams map;               // start_node < 0: the walk clip's node nearest 1 m/s
  std::string start_clip = "cmu_10_04.bvh";
  std::string cache_dir;              // "" = no cache
};

struct MocapAssets {
  MotionGraph graph;
  CapabilityMap map;
  CapabilityParams map_params;        // as used (start node resolved)
  bool from_cache = false;
  double graph_seconds = 0, map_seconds = 0;  // build times (0 when loaded)
  std::string cache_path;
};

bool load_or_build_assets(const AssetOptions& options, MocapAssets& assets, std::string& error);

// The reach overlay's model for the server: the clips of `mocap_dir`, cached
// in `cache_dir` ("" = none). Null with `error` set when the clips cannot be read.
std::shared_ptr<const ReachModel> load_reach_model(const std::string& mocap_dir, const std::string& cache_dir,
                                                   std::string& error);

// The node of `clip_name` with a ground speed nearest `speed` (m/s), away from
// the clip's ends; -1 when the clip has no node left after pruning.
int pick_start_node(const MotionGraph& graph, const std::string& clip_name, float speed);

}  // namespace mc::anim::mocap::io

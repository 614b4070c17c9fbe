// The physical capability map of Sukthankar, Mandel and Sycara: seeded Monte
// Carlo random walks through the motion graph from a start pose, each cell
// of a grid keeping the cheapest path that reached it, with cost
//   C = F + alpha |r - g|^2      (F frames, r where the path is, g the cell centre)
// Obstacles prune paths that enter them; constraints disable edges (a speed
// limit); convergence is tracked per cell.
//
// Map frame: the start pose at the origin facing +x, +y to its RIGHT
// (rcssserver's sense), metres. Costs in frames of the graph (30 Hz).
// Offline: the maps are precomputed and then only read (capability_lookup.hpp).
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "anim/mocap/motion_graph.hpp"

namespace mc::anim::mocap {

inline constexpr float kUnreached = std::numeric_limits<float>::infinity();

// A square-celled grid over the map frame. Cell (0, 0) has its lower corner at
// (origin_x, origin_y); cells are numbered row by row (y major).
struct MapGrid {
  int width = 48, height = 48;
  float cell = 0.25f;                     // m
  float origin_x = -6.0f, origin_y = -6.0f;

  int cells() const { return width * height; }
  // Cell holding (x, y), or -1 outside.
  int index(float x, float y) const;
  float center_x(int i) const { return origin_x + (static_cast<float>(i % width) + 0.5f) * cell; }
  float center_y(int i) const { return origin_y + (static_cast<float>(i / width) + 0.5f) * cell; }
};

struct CapabilityParams {
  MapGrid grid;
  int start_node = 0;              // graph node of the start pose
  int max_depth = 300;             // frames per walk (10 s at 30 Hz)
  int iterations = 200000;         // walks (about 2 s on the CMU graph; the far cells converge slowly)
  std::uint64_t seed = 1;          // walk i uses its own stream derived from (seed, i)
  float alpha = 0;                 // goal weight (the paper ran alpha = 0), frames per m^2
  std::vector<std::uint8_t> obstacles;  // grid.cells() flags, 1 = blocked; empty = none
  float max_speed = 0;             // m/s; > 0 disables edges into faster frames
  int checkpoint_every = 100;      // iterations between convergence samples
  std::vector<int> tracked_cells;  // cells whose cost is sampled at each checkpoint
};

struct CapabilityMap {
  MapGrid grid;
  std::vector<float> cost;                   // per cell, kUnreached when no path got there
  std::vector<std::uint32_t> best_iteration; // the walk that set the cost (its last improvement)
  std::vector<std::uint16_t> best_step;      // and the step (frames) at which it was there
  // Convergence: per checkpoint, iterations done, cells improved since the
  // previous checkpoint, and the cost of each tracked cell.
  std::vector<int> checkpoint_iteration;
  std::vector<int> checkpoint_improved;
  std::vector<float> tracked_history;        // checkpoints * tracked_cells
  int iterations = 0;
  long long steps = 0;                       // walk steps taken in all
  int pruned_by_obstacles = 0;               // walks ended by entering an obstacle

  int reached() const;
  // Iteration by which `fraction` of the reached cells had their final cost.
  int converged_iteration(double fraction) const;
};

CapabilityMap compute_capability_map(const MotionGraph& graph, const CapabilityParams& params);

// The graph nodes of the saved path of a cell (start node first, best_step + 1
// nodes), regenerated from the walk's seed: paths cost no memory.
std::vector<int> cell_path(const MotionGraph& graph, const CapabilityParams& params, const CapabilityMap& map, int cell);

// Convergence against the final map: for each cell `final` reached, the
// iteration (1-based) from which its cost stayed within `tolerance` (relative)
// of the final cost, found by replaying the same seeded walks; 0 elsewhere.
std::vector<std::uint32_t> iterations_within(const MotionGraph& graph, const CapabilityParams& params,
                                             const CapabilityMap& final_map, float tolerance);
// The iteration by which `fraction` of the reached cells were within tolerance.
std::uint32_t iteration_quantile(std::vector<std::uint32_t> iterations, double fraction);

// Grassfire (Blum 1967): 8-connected shortest distance (m) from the start cell
// (the cell holding the origin) around obstacles; kUnreached where cut off.
std::vector<float> grassfire(const MapGrid& grid, const std::vector<std::uint8_t>& obstacles);

// Splitmix64-seeded xorshift generator: the same stream on every platform.
class WalkRng {
 public:
  WalkRng(std::uint64_t seed, std::uint64_t stream);
  std::uint64_t next();
  // Uniform in [0, n), n > 0.
  std::uint32_t below(std::uint32_t n) { return static_cast<std::uint32_t>(((next() >> 32) * n) >> 32); }

 private:
  std::uint64_t s_;
};

}  // namespace mc::anim::mocap

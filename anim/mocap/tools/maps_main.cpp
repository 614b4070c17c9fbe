// matchcast-mocap-maps: reproduces the figures of Sukthankar, Mandel and
// Sycara from the CMU clips. Builds (or loads from the cache) the motion graph
// and the walking capability map, then writes PNG + CSV for Figure 4
// (convergence), Figure 5 (cost against distance), Figure 6 (capability map,
// grassfire, difference, with and without an obstacle) and Figure 7 (the
// opponent model), and prints the graph's size before and after pruning.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "anim/mocap/io/asset_cache.hpp"
#include "anim/mocap/opponent_model.hpp"
#include "anim/mocap/reach_overlay.hpp"
#include "anim/mocap/tools/figure_png.hpp"

using namespace mc::anim::mocap;
using mc::anim::mocap::tools::HeatStyle;
using mc::anim::mocap::tools::Series;

namespace {

struct Options {
  std::string data = MATCHCAST_DEFAULT_MOCAP_DIR;
  std::string out = "mocap-figures";
  std::string cache = MATCHCAST_DEFAULT_MOCAP_CACHE;
  int iterations = 200000;
  int obstacle_iterations = 1000000;  // most walks end at the wall early: cheap, and needed to cover its shadow
  int depth = 300;
  std::uint64_t seed = 1;
  float threshold = 0.08f;
};

bool save(const std::string& path, const mc::anim::tools::Image& img) {
  std::string err;
  if (!mc::anim::tools::write_png(path, img, err)) { std::fprintf(stderr, "%s\n", err.c_str()); return false; }
  std::printf("wrote %s\n", path.c_str());
  return true;
}

std::string fmt(float v) {
  if (v == kUnreached || !std::isfinite(v)) return "";
  char b[32];
  std::snprintf(b, sizeof b, "%.3f", static_cast<double>(v));
  return b;
}

float max_finite(const std::vector<float>& v) {
  float m = 0;
  for (float x : v)
    if (x != kUnreached && std::isfinite(x)) m = std::max(m, x);
  return m;
}

// Mean cost of the reached cells at distance [d0, d1) within `half_angle` of `bearing`.
float mean_cost(const CapabilityMap& m, float d0, float d1, float bearing, float half_angle) {
  double s = 0;
  int n = 0;
  for (int i = 0; i < m.grid.cells(); ++i) {
    const float x = m.grid.center_x(i), y = m.grid.center_y(i), d = std::hypot(x, y);
    float a = std::atan2(y, x) - bearing;
    a = std::atan2(std::sin(a), std::cos(a));
    if (d < d0 || d >= d1 || std::fabs(a) > half_angle || m.cost[static_cast<std::size_t>(i)] == kUnreached) continue;
    s += m.cost[static_cast<std::size_t>(i)];
    ++n;
  }
  return n ? static_cast<float>(s / n) : kUnreached;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto val = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (a == "--data") o.data = val();
    else if (a == "--out") o.out = val();
    else if (a == "--cache-dir") o.cache = val();
    else if (a == "--iterations") o.iterations = std::max(1, std::atoi(val().c_str()));
    else if (a == "--obstacle-iterations") o.obstacle_iterations = std::max(1, std::atoi(val().c_str()));
    else if (a == "--depth") o.depth = std::max(1, std::atoi(val().c_str()));
    else if (a == "--seed") o.seed = std::strtoull(val().c_str(), nullptr, 10);
    else if (a == "--threshold") o.threshold = std::strtof(val().c_str(), nullptr);
    else {
      std::fprintf(stderr,
                   "usage: %s [--data DIR] [--out DIR] [--cache-dir DIR|\"\"] [--iterations N] [--obstacle-iterations N] "
                   "[--depth FRAMES] "
                   "[--seed S] [--threshold M]\n",
                   argv[0]);
      return 2;
    }
  }
  io::AssetOptions ao;
  ao.clips.dir = o.data;
  ao.graph.threshold_rms = o.threshold;
  ao.map.iterations = o.iterations;  // the cached map uses the same count
  ao.map.max_depth = o.depth;
  ao.map.seed = o.seed;
  ao.map.start_node = -1;
  ao.cache_dir = o.cache;
  const MapGrid& grid = ao.map.grid;
  // Tracked cells for Figure 4: 3 m ahead, 3 m to the right, 3 m behind.
  ao.map.tracked_cells = {grid.index(3.1f, 0.1f), grid.index(0.1f, 3.1f), grid.index(-2.9f, 0.1f)};
  io::MocapAssets as;
  std::string error;
  if (!io::load_or_build_assets(ao, as, error)) { std::fprintf(stderr, "error: %s\n", error.c_str()); return 1; }
  const auto& st = as.graph.stats;
  std::printf("motion graph: %d frames, %d clip edges + %d transitions before pruning; %d strongly connected "
              "components; largest kept: %d nodes, %d edges (%d transitions)%s\n",
              st.frames, st.natural_edges, st.transition_edges, st.components, st.nodes_after, st.edges_after,
              st.transitions_after, as.from_cache ? " [cache]" : "");
  std::printf("graph build %.2f s (%s), start node %d (%s frame %d, %.2f m/s)\n", st.build_seconds,
              as.from_cache ? "when cached" : "now", as.map_params.start_node,
              as.graph.clip_names[as.graph.nodes[static_cast<std::size_t>(as.map_params.start_node)].clip].c_str(),
              as.graph.nodes[static_cast<std::size_t>(as.map_params.start_node)].frame,
              static_cast<double>(as.graph.nodes[static_cast<std::size_t>(as.map_params.start_node)].speed));
  // The cached map has no convergence history: recompute it here (and time it).
  CapabilityParams mp = as.map_params;
  mp.tracked_cells = ao.map.tracked_cells;
  auto t0 = std::chrono::steady_clock::now();
  const CapabilityMap map = compute_capability_map(as.graph, mp);
  const double map_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("capability map: %d iterations in %.3f s, %d of %d cells reached; converged (last improvement) for "
              "50%% of cells by %d, 90%% by %d, 99%% by %d, all by %d iterations\n",
              map.iterations, map_s, map.reached(), grid.cells(), map.converged_iteration(0.5),
              map.converged_iteration(0.9), map.converged_iteration(0.99), map.converged_iteration(1.0));
  for (float tol : {0.05f, 0.0f}) {
    const auto within = iterations_within(as.graph, mp, map, tol);
    std::printf("  within %.0f%% of the final cost: 50%% of cells by iteration %u, 90%% by %u, 99%% by %u\n",
                static_cast<double>(tol * 100), iteration_quantile(within, 0.5), iteration_quantile(within, 0.9),
                iteration_quantile(within, 0.99));
  }
  for (std::size_t t = 0; t < mp.tracked_cells.size(); ++t) {
    const int c = mp.tracked_cells[t];
    std::printf("  tracked cell %zu at (%.1f, %.1f) m: cost %s frames, last improved at iteration %u\n", t,
                static_cast<double>(grid.center_x(c)), static_cast<double>(grid.center_y(c)),
                fmt(map.cost[static_cast<std::size_t>(c)]).c_str(), map.best_iteration[static_cast<std::size_t>(c)] + 1);
  }
  const ReachModel model = make_reach_model(map, as.graph.hz);
  const float frames_per_m = as.graph.hz / model.reference_speed;
  std::printf("reference speed straight ahead %.2f m/s\n", static_cast<double>(model.reference_speed));
  const float ahead = mean_cost(map, 2.5f, 3.5f, 0, 0.5f), behind = mean_cost(map, 2.5f, 3.5f, 3.14159f, 0.5f),
              right = mean_cost(map, 2.5f, 3.5f, 1.5708f, 0.5f), left = mean_cost(map, 2.5f, 3.5f, -1.5708f, 0.5f);
  std::printf("asymmetry at 2.5-3.5 m: ahead %.1f, right %.1f, left %.1f, behind %.1f frames (behind/ahead %.2f)\n",
              static_cast<double>(ahead), static_cast<double>(right), static_cast<double>(left),
              static_cast<double>(behind), static_cast<double>(behind / ahead));

  // Figure 6, with an obstacle: a wall 1.5 m ahead, 3 m wide.
  std::vector<std::uint8_t> wall(static_cast<std::size_t>(grid.cells()), 0);
  for (int i = 0; i < grid.cells(); ++i) {
    const float x = grid.center_x(i), y = grid.center_y(i);
    if (x > 1.5f && x < 2.0f && std::fabs(y) < 1.5f) wall[static_cast<std::size_t>(i)] = 1;
  }
  CapabilityParams mo = as.map_params;
  mo.obstacles = wall;
  mo.iterations = o.obstacle_iterations;
  t0 = std::chrono::steady_clock::now();
  const CapabilityMap map_o = compute_capability_map(as.graph, mo);
  std::printf("with the obstacle: %d iterations in %.3f s, %d cells reached, %d walks pruned by it\n", map_o.iterations,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), map_o.reached(),
              map_o.pruned_by_obstacles);
  auto to_frames = [&](std::vector<float> g) {
    for (auto& v : g)
      if (v != kUnreached) v *= frames_per_m;
    return g;
  };
  const auto grass = to_frames(grassfire(grid, {})), grass_o = to_frames(grassfire(grid, wall));
  auto diff = [&](const std::vector<float>& a, const std::vector<float>& b) {
    std::vector<float> d(a.size(), kUnreached);
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a[i] != kUnreached && b[i] != kUnreached) d[i] = a[i] - b[i];
    return d;
  };
  const auto dmap = diff(map.cost, grass), dmap_o = diff(map_o.cost, grass_o);

  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  const int start_cell = grid.index(0.01f, 0.01f);
  HeatStyle hs;
  hs.vmax = std::max(max_finite(map.cost), max_finite(grass));
  hs.marks = {start_cell};
  bool ok = save(o.out + "/fig6_capability.png", heat_map(grid, map.cost, hs));
  ok &= save(o.out + "/fig6_grassfire.png", heat_map(grid, grass, hs));
  HeatStyle hd = hs;
  hd.diverging = true;
  hd.vmax = std::max(max_finite(dmap), -[&] { float m = 0; for (float v : dmap) if (v != kUnreached) m = std::min(m, v); return m; }());
  ok &= save(o.out + "/fig6_difference.png", heat_map(grid, dmap, hd));
  HeatStyle ho = hs;
  ho.obstacles = &wall;
  ok &= save(o.out + "/fig6_capability_obstacle.png", heat_map(grid, map_o.cost, ho));
  ok &= save(o.out + "/fig6_grassfire_obstacle.png", heat_map(grid, grass_o, ho));
  HeatStyle hdo = hd;
  hdo.obstacles = &wall;
  ok &= save(o.out + "/fig6_difference_obstacle.png", heat_map(grid, dmap_o, hdo));
  {
    std::ofstream f(o.out + "/fig6_maps.csv");
    f << "cell,x_m,y_m,capability_frames,grassfire_frames,difference,capability_obstacle_frames,"
         "grassfire_obstacle_frames,difference_obstacle,obstacle\n";
    for (int i = 0; i < grid.cells(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      f << i << ',' << fmt(grid.center_x(i)) << ',' << fmt(grid.center_y(i)) << ',' << fmt(map.cost[k]) << ','
        << fmt(grass[k]) << ',' << fmt(dmap[k]) << ',' << fmt(map_o.cost[k]) << ',' << fmt(grass_o[k]) << ','
        << fmt(dmap_o[k]) << ',' << int(wall[k]) << '\n';
    }
  }
  // Figure 4: convergence of the tracked cells.
  {
    std::vector<Series> s(3);
    const std::uint8_t colours[3][3] = {{200, 0, 0}, {0, 140, 0}, {0, 0, 200}};
    std::ofstream f(o.out + "/fig4_convergence.csv");
    f << "iteration,ahead_3m,right_3m,behind_3m,cells_improved\n";
    float ymax = 0;
    const std::size_t nt = mp.tracked_cells.size();
    for (std::size_t c = 0; c < map.checkpoint_iteration.size(); ++c) {
      f << map.checkpoint_iteration[c];
      for (std::size_t t = 0; t < nt; ++t) {
        const float v = map.tracked_history[c * nt + t];
        f << ',' << fmt(v);
        s[t].x.push_back(static_cast<float>(map.checkpoint_iteration[c]));
        s[t].y.push_back(v == kUnreached ? NAN : v);
        if (v != kUnreached) ymax = std::max(ymax, v);
      }
      f << ',' << map.checkpoint_improved[c] << '\n';
    }
    for (std::size_t t = 0; t < 3; ++t) { s[t].r = colours[t][0]; s[t].g = colours[t][1]; s[t].b = colours[t][2]; }
    ok &= save(o.out + "/fig4_convergence.png", tools::plot(s, 0, static_cast<float>(map.iterations), 0, ymax * 1.1f, true));
  }
  // Figure 5: cost against distance, with the grassfire line.
  {
    Series pts, line;
    pts.r = 30; pts.g = 30; pts.b = 160;
    line.r = 220; line.g = 0; line.b = 0;
    std::ofstream f(o.out + "/fig5_cost_vs_distance.csv");
    f << "cell,distance_m,bearing_deg,capability_frames,grassfire_frames\n";
    float dmax = 0, cmax = 0;
    for (int i = 0; i < grid.cells(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (map.cost[k] == kUnreached) continue;
      const float d = std::hypot(grid.center_x(i), grid.center_y(i));
      f << i << ',' << fmt(d) << ',' << fmt(std::atan2(grid.center_y(i), grid.center_x(i)) * 57.29578f) << ','
        << fmt(map.cost[k]) << ',' << fmt(grass[k]) << '\n';
      pts.x.push_back(d);
      pts.y.push_back(map.cost[k]);
      dmax = std::max(dmax, d);
      cmax = std::max(cmax, map.cost[k]);
    }
    line.x = {0, dmax};
    line.y = {0, dmax * frames_per_m};
    ok &= save(o.out + "/fig5_cost_vs_distance.png", tools::plot({pts, line}, 0, dmax, 0, cmax * 1.05f, false));
    // The line is drawn as a scatter of two points; draw it as a line on top.
    auto img = tools::plot({pts}, 0, dmax, 0, cmax * 1.05f, false);
    const auto lim = tools::plot({line}, 0, dmax, 0, cmax * 1.05f, true);
    for (std::size_t p = 0; p + 2 < img.rgb.size(); p += 3)
      if (lim.rgb[p] == 220 && lim.rgb[p + 1] == 0) { img.rgb[p] = 220; img.rgb[p + 1] = 0; img.rgb[p + 2] = 0; }
    ok &= save(o.out + "/fig5_cost_vs_distance.png", img);
  }
  // Figure 7: opponent model. We stand at S facing +x; the opponent 3 m ahead,
  // 1 m to our right, facing us. Ts = 10 frames to shoot, eps = 5 frames. The
  // score is the closeness to a goal 5 m ahead.
  {
    // Both cost fields from the reach model, so that cells outside a map get
    // its far-field estimate instead of "never" (same speed for both agents).
    const AgentPose opp{3.0f, 1.0f, 3.14159265f};
    ReachPlayer own_p, opp_p;
    own_p.top_speed = opp_p.top_speed = model.reference_speed;
    own_p.glide = opp_p.glide = 0;
    opp_p.x = opp.x; opp_p.y = opp.y; opp_p.heading = opp.heading;
    std::vector<float> cd(static_cast<std::size_t>(grid.cells())), co(cd.size());
    for (int i = 0; i < grid.cells(); ++i) {
      cd[static_cast<std::size_t>(i)] = reach_time(model, own_p, grid.center_x(i), grid.center_y(i)) * as.graph.hz;
      co[static_cast<std::size_t>(i)] = reach_time(model, opp_p, grid.center_x(i), grid.center_y(i)) * as.graph.hz;
    }
    const float ts = 10, eps = 5;
    const auto safe = safe_cells(cd, co, ts, eps);
    const float gx = 5, gy = 0;
    const int best = best_safe_cell(safe, [&](int c) { return -std::hypot(grid.center_x(c) - gx, grid.center_y(c) - gy); });
    int n_safe = 0;
    for (auto s : safe) n_safe += s;
    std::printf("opponent model (Co > Cd + Ts + eps, Ts %.0f, eps %.0f frames): %d safe cells; best for a goal at "
                "(%.0f, %.0f): cell %d at (%.2f, %.2f)\n",
                static_cast<double>(ts), static_cast<double>(eps), n_safe, static_cast<double>(gx), static_cast<double>(gy),
                best, best >= 0 ? static_cast<double>(grid.center_x(best)) : 0.0,
                best >= 0 ? static_cast<double>(grid.center_y(best)) : 0.0);
    HeatStyle h7 = hs;
    h7.highlight = &safe;
    h7.marks = {start_cell, grid.index(opp.x, opp.y), best, grid.index(gx, gy)};
    ok &= save(o.out + "/fig7_opponent.png", heat_map(grid, cd, h7));
    std::ofstream f(o.out + "/fig7_opponent.csv");
    f << "cell,x_m,y_m,own_frames,opponent_frames,safe,best\n";
    for (int i = 0; i < grid.cells(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      f << i << ',' << fmt(grid.center_x(i)) << ',' << fmt(grid.center_y(i)) << ',' << fmt(cd[k]) << ','
        << fmt(co[k]) << ',' << int(safe[k]) << ',' << (i == best ? 1 : 0) << '\n';
    }
  }
  return ok ? 0 : 1;
}

// matchcast-mocap-bench: the figures of issue 9's benchmarks. Graph build
// time (always rebuilt, no cache), capability-map convergence time, and the
// reach overlay's cost per frame for 22 players on one core (target <= 1 ms).
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "anim/mocap/io/asset_cache.hpp"
#include "anim/mocap/reach_overlay.hpp"

using namespace mc::anim::mocap;
using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
  std::string data = MATCHCAST_DEFAULT_MOCAP_DIR;
  int frames = 2000, iterations = 200000;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--data" && i + 1 < argc) data = argv[++i];
    else if (a == "--frames" && i + 1 < argc) frames = std::max(1, std::atoi(argv[++i]));
    else if (a == "--iterations" && i + 1 < argc) iterations = std::max(1, std::atoi(argv[++i]));
    else { std::fprintf(stderr, "usage: %s [--data DIR] [--frames N] [--iterations N]\n", argv[0]); return 2; }
  }
  io::AssetOptions ao;
  ao.clips.dir = data;
  ao.map.iterations = iterations;
  ao.map.start_node = -1;
  ao.cache_dir = "";  // measure the build
  io::MocapAssets as;
  std::string error;
  const auto t0 = Clock::now();
  if (!io::load_or_build_assets(ao, as, error)) { std::fprintf(stderr, "error: %s\n", error.c_str()); return 1; }
  const double total = std::chrono::duration<double>(Clock::now() - t0).count();
  const auto& st = as.graph.stats;
  std::printf("graph: %d frames -> %d nodes, %d edges (%d transitions) after keeping the largest of %d SCCs\n",
              st.frames, st.nodes_after, st.edges_after, st.transitions_after, st.components);
  std::printf("graph build: %.3f s (window distances + Tarjan); clip loading+map: %.3f s in all\n", as.graph_seconds, total);
  const auto within = iterations_within(as.graph, as.map_params, as.map, 0.05f);
  const std::uint32_t w90 = iteration_quantile(within, 0.9), w99 = iteration_quantile(within, 0.99);
  const double per_it = as.map_seconds / as.map.iterations;
  std::printf("capability map: %d iterations x %d frames in %.3f s (%.1f us/iteration), %d cells reached; within 5%% "
              "of the final cost: 90%% of cells by iteration %u (%.3f s), 99%% by %u (%.3f s); exact final: 99%% by %d\n",
              as.map.iterations, as.map_params.max_depth, as.map_seconds, 1e6 * per_it, as.map.reached(), w90,
              w90 * per_it, w99, w99 * per_it, as.map.converged_iteration(0.99));

  const ReachModel model = make_reach_model(as.map, as.graph.hz);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> ux(-52, 52), uy(-34, 34), ua(-3.14159f, 3.14159f), uv(-1, 1);
  std::vector<ReachPlayer> players(22);
  std::vector<std::uint8_t> owner(static_cast<std::size_t>(MapGrid{53, 34, 2.0f, -53, -34}.cells()));
  std::vector<float> times(owner.size());
  int ball = -1;
  float ball_t = 0;
  std::vector<double> per_frame;
  auto cpu_us = [] {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e6 + static_cast<double>(ts.tv_nsec) / 1e3;
  };
  double cpu = 0;
  long checksum = 0;
  for (int f = 0; f < frames; ++f) {
    for (int p = 0; p < 22; ++p) {
      auto& r = players[static_cast<std::size_t>(p)];
      r.team = static_cast<std::int8_t>(p < 11 ? 0 : 1);
      r.x = ux(rng); r.y = uy(rng); r.heading = ua(rng);
      r.vx = 4 * uv(rng); r.vy = 4 * uv(rng);
      r.top_speed = 10.5f * (0.9f + 0.1f * (uv(rng) + 1));
    }
    ReachOverlayJob job;
    job.model = &model;
    job.players = players;
    job.owner = owner;
    job.time = times;
    job.ball_x = ux(rng); job.ball_y = uy(rng); job.ball_vx = 2 * uv(rng); job.ball_vy = 2 * uv(rng);
    job.ball_player = &ball;
    job.ball_time = &ball_t;
    const double c0 = cpu_us();
    const auto a = Clock::now();
    if (!job.Run()) { std::fprintf(stderr, "overlay job refused\n"); return 1; }
    per_frame.push_back(std::chrono::duration<double, std::micro>(Clock::now() - a).count());
    cpu += cpu_us() - c0;
    checksum += owner[100] + ball;
  }
  std::sort(per_frame.begin(), per_frame.end());
  double sum = 0;
  for (double v : per_frame) sum += v;
  std::printf("reach overlay, 22 players, %zu cells (2 m), ball search 50 cycles: mean %.1f us, p50 %.1f us, p99 %.1f "
              "us per frame wall; %.1f us CPU (target <= 1000 us) [checksum %ld]\n",
              owner.size(), sum / frames, per_frame[per_frame.size() / 2],
              per_frame[std::min(per_frame.size() - 1, per_frame.size() * 99 / 100)], cpu / frames, checksum);
  return 0;
}

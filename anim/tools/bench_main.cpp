// matchcast-anim-bench: animates whole logs on one core and prints frames/s
// and how many live games (20 frames/s each) one core could animate.
// Reading the log is not timed: only Animator::push/finish are. Exits 1 when
// a full game takes more than 1 s of CPU (issue 23); the quality figures'
// own regressions are anim_quality_full_games_test's. It also prints a
// digest of every frame's positions and angles (FNV-1a over their bits): a
// change made only for speed must leave it as it was.
//
//   matchcast-anim-bench [--repeat N] LOG...
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "anim/animator.hpp"
#include "anim/human_skeleton.hpp"
#include "server/ingest/state_source.hpp"

namespace {

// FNV-1a 64 over the bits of what the animation computes.
std::uint64_t digest(const std::vector<mc::PoseFrame>& frames) {
  std::uint64_t h = 14695981039346656037ull;
  auto mix = [&h](float v) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    for (int i = 0; i < 4; ++i) h = (h ^ ((bits >> (8 * i)) & 0xffu)) * 1099511628211ull;
  };
  for (const auto& f : frames)
    for (const auto& p : f.players) {
      for (float v : {p.x, p.y, p.z, p.heading}) mix(v);
      for (float v : p.angles) mix(v);
    }
  return h;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace mc;
  int repeat = 3;
  std::vector<std::string> logs;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--repeat" && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else logs.push_back(arg);
  }
  if (logs.empty()) {
    std::fprintf(stderr, "usage: %s [--repeat N] LOG...\n", argv[0]);
    return 2;
  }
  bool all_ok = true;
  for (const std::string& log : logs) {
    std::string err;
    auto src = ingest::open_log(log, err);
    if (!src) { std::fprintf(stderr, "%s: %s\n", log.c_str(), err.c_str()); return 2; }
    std::vector<WorldState> states;
    WorldState s;
    while (src->next(s)) states.push_back(s);
    std::vector<PoseFrame> frames;
    frames.reserve(2 * states.size());
    // CPU time of this thread (what one core spends, whatever else runs on
    // the machine) and wall time, best of `repeat`.
    auto cpu_now = [] {
      timespec ts{};
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
      return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    };
    double best = 1e9, best_wall = 1e9;
    for (int r = 0; r < repeat; ++r) {
      frames.clear();
      const auto t0 = std::chrono::steady_clock::now();
      const double c0 = cpu_now();
      anim::Animator a(anim::human_skeleton(), src->params());
      for (const WorldState& st : states) a.push(st, frames);
      a.finish(frames);
      best = std::min(best, cpu_now() - c0);
      best_wall = std::min(best_wall, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    const double fps = static_cast<double>(frames.size()) / best;
    std::printf("%s\n  %zu states -> %zu frames in %.3f s CPU (%.3f s wall), best of %d: %.0f frames/s, %.0f player-poses/s\n"
                "  one core animates %.0f live games at 20 frames/s; target: a full game in <= 1 s: %s\n"
                "  frames' digest %016llx\n",
                log.c_str(), states.size(), frames.size(), best, best_wall, repeat, fps, fps * kMaxPlayers, fps / 20.0,
                best <= 1.0 ? "PASS" : "FAIL", static_cast<unsigned long long>(digest(frames)));
    all_ok = all_ok && best <= 1.0;
  }
  return all_ok ? 0 : 1;
}

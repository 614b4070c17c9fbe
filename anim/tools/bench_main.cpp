// matchcast-anim-bench: animates whole logs on one core and prints frames/s
// and how many live games (20 frames/s each) one core could animate.
// Reading the log is not timed: only Animator::push/finish are.
//
//   matchcast-anim-bench [--repeat N] LOG...
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "anim/animator.hpp"
#include "anim/human_skeleton.hpp"
#include "server/ingest/state_source.hpp"

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
  for (const std::string& log : logs) {
    std::string err;
    auto src = ingest::open_log(log, err);
    if (!src) { std::fprintf(stderr, "%s: %s\n", log.c_str(), err.c_str()); return 2; }
    std::vector<WorldState> states;
    WorldState s;
    while (src->next(s)) states.push_back(s);
    std::vector<PoseFrame> frames;
    frames.reserve(2 * states.size());
    double best = 1e9;
    for (int r = 0; r < repeat; ++r) {
      frames.clear();
      const auto t0 = std::chrono::steady_clock::now();
      anim::Animator a(anim::human_skeleton(), src->params());
      for (const WorldState& st : states) a.push(st, frames);
      a.finish(frames);
      const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      best = std::min(best, sec);
    }
    const double fps = static_cast<double>(frames.size()) / best;
    std::printf("%s\n  %zu states -> %zu frames in %.3f s (best of %d): %.0f frames/s, %.0f player-poses/s\n"
                "  one core animates %.0f live games at 20 frames/s; target: a full game in <= 1 s: %s\n",
                log.c_str(), states.size(), frames.size(), best, repeat, fps, fps * kMaxPlayers, fps / 20.0,
                best <= 1.0 ? "PASS" : "FAIL");
  }
  return 0;
}

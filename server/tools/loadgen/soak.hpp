// The load generator's long-run mode (scripts/soak.sh): a population of
// spectators that changes all the time, with a JSON line of counters every
// few seconds instead of one report at the end.
//   - `clients` spectators, of which a share stalled (never read; each one
//     reads again after stall_for, finds out whether the relay cut it off,
//     and is replaced by a new stalled one);
//   - churn: every second `churn` healthy spectators leave and as many
//     new ones join;
//   - bursts: every `burst_every` seconds `burst` more join at once and
//     stay `burst_stay` seconds.
// Counters are cumulative over the run, per behaviour.
#pragma once

#include <chrono>
#include <string>

#include "proto/hello.hpp"

namespace mc::loadgen {

struct SoakOptions {
  std::string host = "127.0.0.1";
  unsigned short port = 8080;
  std::string target = "/ws";
  unsigned clients = 2000;
  double stalled_share = 0.01;
  std::chrono::milliseconds stall_for{30000};
  unsigned churn = 20;               // per second, leaving and joining
  unsigned burst = 500;
  double burst_every_s = 300;        // 0 = no bursts
  double burst_stay_s = 60;
  double ramp_per_s = 500;           // the first `clients` join at this rate
  double duration_s = 1800;
  double report_every_s = 10;
  unsigned threads = 2;
  bool header_only = true;
};

// Runs until duration_s has passed; prints a JSON line every
// report_every_s and a last one at the end (with "final":true). Returns 0.
int run_soak(const SoakOptions& options, const proto::Hello& hello);

}  // namespace mc::loadgen

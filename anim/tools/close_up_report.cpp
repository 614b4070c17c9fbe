// The close-up report: whether a CloseUpReport meets issue 23's targets, and
// the table that prints it (the measuring itself is close_up_metrics.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "anim/tools/close_up_metrics.hpp"

namespace mc::anim::tools {

namespace {
using namespace close_up;  // the targets
}  // namespace

bool close_up_targets_hold(const CloseUpReport& r) {
  bool ok = true;
  for (int b = 0; b < kSpeedBands; ++b)
    if (!r.grounded_mps[static_cast<std::size_t>(b)].values.empty())
      ok = ok && band_mean(r, b) <= (b == 0 ? kStandMeanMps : kGroundedMeanMps);
  ok = ok && r.kick_box_m.percentile(95) <= kKickP95M && r.kick_box_m.max() <= kKickMaxM && r.kicks_inside == 0;
  ok = ok && r.leg_step_deg.max() <= kLegStepDeg && r.arm_step_deg.max() <= kArmStepDeg && r.ankle_pops == 0;
  ok = ok && r.trunk_step_deg.max() <= kTrunkStepDeg && r.head_step_deg.max() <= kHeadStepDeg;
  ok = ok && r.thighs_close == 0 && r.shins_close == 0 && r.feet_close == 0 && r.hands_inside == 0;
  ok = ok && r.floating <= kMaxFloatingPlayerFrames * r.draws_per_frame;
  ok = ok && (r.draws_per_frame > 1 || r.ankle_limit_share <= kAnkleLimitShare);
  ok = ok && r.cadence.percentile(99) <= kCadenceP99;
  ok = ok && r.root_error_m.max() <= 0.01 && r.limit_violations == 0;
  ok = ok && r.lowest_m >= -kGroundTolerance && r.step_in_m.max() <= kMaxStepInTarget + kStepInQuantM;
  return ok;
}

std::string format_close_up(const std::vector<const CloseUpReport*>& reports) {
  std::string out;
  char line[512];
  auto row = [&](const char* name, const char* target, auto value, auto pass) {
    int n = std::snprintf(line, sizeof line, "%-44s", name);
    for (const CloseUpReport* r : reports) {
      char cell[64];
      value(*r, cell, sizeof cell);
      const int ok = pass(*r);
      n += std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), " %18s %-4s", cell,
                         ok < 0 ? "" : ok ? "ok" : "FAIL");
    }
    std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), "  %s\n", target);
    out += line;
  };
  auto none = [](const CloseUpReport&) { return -1; };
  {
    int n = std::snprintf(line, sizeof line, "%-44s", "close-up metrics (decoded stream, hello skeleton)");
    for (const CloseUpReport* r : reports) {
      char h[32];
      std::snprintf(h, sizeof h, "at %d Hz", 20 * r->draws_per_frame);
      n += std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), " %18s %-4s", h, "");
    }
    std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), "  target\n");
    out += line;
  }
  row("drawn frames / active player-frames", "", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%ld/%ld", r.frames, r.player_frames); }, none);
  for (int b = 0; b < kSpeedBands; ++b) {
    char name[80];
    std::snprintf(name, sizeof name, "grounded foot, root %s m/s: mean, >0.5", speed_band_name(b));
    row(name, b == 0 ? "mean <= 0.2 m/s" : "mean <= 0.5 m/s",
        [b](const CloseUpReport& r, char* c, std::size_t s) {
          const Distribution& d = r.grounded_mps[static_cast<std::size_t>(b)];
          std::snprintf(c, s, "%.2f %3.0f%% n%zu", d.mean(),
                        d.values.empty() ? 0.0 : 100.0 * static_cast<double>(r.grounded_over_half[static_cast<std::size_t>(b)]) / static_cast<double>(d.values.size()),
                        d.values.size()); },
        [b](const CloseUpReport& r) {
          return r.grounded_mps[static_cast<std::size_t>(b)].values.empty() ||
                 band_mean(r, b) <= (b == 0 ? kStandMeanMps : kGroundedMeanMps); });
  }
  row("  fastest grounded foot (m/s)", "", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%.2f", r.grounded_worst_mps); }, none);
  row("kick: foot box to ball surface mean (m)", "", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%+.4f", r.kick_box_m.mean()); }, none);
  row("kick: foot box to ball p95 / max (m)", "p95 <= 0.02, max <= 0.03", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%+.3f/%+.3f", r.kick_box_m.percentile(95), r.kick_box_m.max()); },
    [](const CloseUpReport& r) { return r.kick_box_m.percentile(95) <= kKickP95M && r.kick_box_m.max() <= kKickMaxM; });
  row("kick: deepest inside / kicks > 2 cm inside", "none > 0.02 inside", [](const CloseUpReport& r, char* c, std::size_t s) {
    const auto& v = r.kick_box_m.values;
    std::snprintf(c, s, "%+.3f / %ld", v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()), r.kicks_inside); },
    [](const CloseUpReport& r) { return r.kicks_inside == 0; });
  row("kick: toe tip to ball mean / p95 / max (m)", "", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%.3f/%.3f/%.3f", r.kick_toe_m.mean(), r.kick_toe_m.percentile(95), r.kick_toe_m.max()); }, none);
  row("legs: change p99 / max (deg per 50 ms)", "max <= 60", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%.1f/%.1f", r.leg_step_deg.percentile(99), r.leg_step_deg.max()); },
    [](const CloseUpReport& r) { return r.leg_step_deg.max() <= kLegStepDeg; });
  row("  player-frames over 50 / over 60", "", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%ld/%ld", r.legs_over_50, r.legs_over_60); }, none);
  row("arms: change p99 / max (deg per 50 ms)", "max <= 45", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%.1f/%.1f", r.arm_step_deg.percentile(99), r.arm_step_deg.max()); },
    [](const CloseUpReport& r) { return r.arm_step_deg.max() <= kArmStepDeg; });
  row("  player-frames over 45 / over 50", "", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%ld/%ld", r.arms_over_45, r.arms_over_50); }, none);
  row("trunk: change p99 / max, frames > 45", "max <= 45", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%.1f/%.1f %ld", r.trunk_step_deg.percentile(99), r.trunk_step_deg.max(), r.trunk_over_45); },
    [](const CloseUpReport& r) { return r.trunk_step_deg.max() <= kTrunkStepDeg; });
  row("neck+head: change p99 / max, frames > 45", "max <= 45", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%.1f/%.1f %ld", r.head_step_deg.percentile(99), r.head_step_deg.max(), r.head_over_45); },
    [](const CloseUpReport& r) { return r.head_step_deg.max() <= kHeadStepDeg; });
  row("ankle pops (foot-frames) / fastest (m)", "0", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%ld / %.2f", r.ankle_pops, r.ankle_step_max_m); },
    [](const CloseUpReport& r) { return r.ankle_pops == 0; });
  row("too close: thighs / shins / feet", "0 / 0 / 0", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%ld/%ld/%ld", r.thighs_close, r.shins_close, r.feet_close); },
    [](const CloseUpReport& r) { return r.thighs_close == 0 && r.shins_close == 0 && r.feet_close == 0; });
  row("  crossed pairs (thigh/shin/foot of the other leg)", "", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%ld", r.crossed_close); }, none);
  row("hand > 2 cm inside body or thigh / deepest (m)", "0", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%ld / %.3f", r.hands_inside, r.hand_depth_max_m); },
    [](const CloseUpReport& r) { return r.hands_inside == 0; });
  row("floating player-frames / highest (m)", "<= 50 per 20 Hz", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%ld / %.3f", r.floating, r.floating_max_m); },
    [](const CloseUpReport& r) { return r.floating <= kMaxFloatingPlayerFrames * r.draws_per_frame; });
  row("time at a limit: worse ankle / worst joint", "ankle <= 2%", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%.1f%%/%.1f%%", 100 * r.ankle_limit_share, 100 * r.worst_limit_share); },
    [](const CloseUpReport& r) { return r.draws_per_frame > 1 ? -1 : r.ankle_limit_share <= kAnkleLimitShare ? 1 : 0; });
  row("cadence p99 / max (steps/s, 2-s windows)", "p99 <= 4.5", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%.2f/%.2f", r.cadence.percentile(99), r.cadence.max()); },
    [](const CloseUpReport& r) { return r.cadence.percentile(99) <= kCadenceP99; });
  row("root error at cycles max (m)", "<= 0.01", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%.4f", r.root_error_m.max()); },
    [](const CloseUpReport& r) { return r.root_error_m.max() <= 0.01; });
  row("joint-limit violations (animator output)", "0", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%ld", r.limit_violations); }, [](const CloseUpReport& r) { return r.limit_violations == 0; });
  row("lowest body point (m)", ">= -0.02", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%.4f", r.lowest_m); }, [](const CloseUpReport& r) { return r.lowest_m >= -kGroundTolerance; });
  row("step-in root offset on contact max (m)", "<= 0.30 (+0.01 quantization)", [](const CloseUpReport& r, char* c, std::size_t s) {
    std::snprintf(c, s, "%.3f", r.step_in_m.max()); },
    [](const CloseUpReport& r) { return r.step_in_m.max() <= kMaxStepInTarget + kStepInQuantM; });
  for (const CloseUpReport* r : reports) {
    char buf[1024];
    std::snprintf(buf, sizeof buf,
                  "  at %d Hz worst: grounded %s | kick %s | leg %s | arm %s | trunk %s | head %s | clearance %s | "
                  "hand %s | float %s | limit joint %s | lowest %s\n",
                  20 * r->draws_per_frame, r->grounded_worst_where.c_str(), r->kick_worst_where.c_str(),
                  r->leg_worst_where.c_str(), r->arm_worst_where.c_str(), r->trunk_worst_where.c_str(),
                  r->head_worst_where.c_str(), r->clearance_worst_where.c_str(), r->hand_worst_where.c_str(),
                  r->floating_where.c_str(), r->worst_limit_joint.c_str(), r->lowest_where.c_str());
    out += buf;
  }
  return out;
}

}  // namespace mc::anim::tools

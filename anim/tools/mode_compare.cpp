#include "anim/tools/mode_compare.hpp"

#include <cstdio>

namespace mc::anim::tools {

std::string format_comparison(const QualityReport& k, const QualityReport& m) {
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "%-32s %14s %14s   %s\n", "metric", "keyframe", "mocap", "target");
  out += line;
  auto row = [&](const char* name, double a, double b, const char* target, bool ok_a, bool ok_b) {
    std::snprintf(line, sizeof line, "%-32s %9.4f %-4s %9.4f %-4s   %s\n", name, a, ok_a ? "ok" : "FAIL", b,
                  ok_b ? "ok" : "FAIL", target);
    out += line;
  };
  auto info = [&](const char* name, double a, double b) {
    std::snprintf(line, sizeof line, "%-32s %9.4f      %9.4f\n", name, a, b);
    out += line;
  };
  std::snprintf(line, sizeof line, "%-32s %9ld      %9ld\n", "frames", k.frames, m.frames);
  out += line;
  std::snprintf(line, sizeof line, "%-32s %9ld      %9ld\n", "kicks", k.kicks, m.kicks);
  out += line;
  row("root error at cycles max (m)", k.root_error_m.max(), m.root_error_m.max(), "<= 0.01",
      k.root_error_m.max() <= 0.01, m.root_error_m.max() <= 0.01);
  row("planted-foot slide mean (m)", k.slide_m.mean(), m.slide_m.mean(), "<= 0.02", k.slide_m.mean() <= 0.02,
      m.slide_m.mean() <= 0.02);
  info("planted-foot slide p95 (m)", k.slide_m.percentile(95), m.slide_m.percentile(95));
  row("foot-to-ball at contact mean (m)", k.contact_m.mean(), m.contact_m.mean(), "<= 0.05",
      k.contact_m.mean() <= 0.05, m.contact_m.mean() <= 0.05);
  info("foot-to-ball at contact p95 (m)", k.contact_m.percentile(95), m.contact_m.percentile(95));
  info("foot-to-ball at contact max (m)", k.contact_m.max(), m.contact_m.max());
  row("cadence max (steps/s)", k.cadence.max(), m.cadence.max(), "<= 4.5", k.cadence.max() <= 4.5,
      m.cadence.max() <= 4.5);
  std::snprintf(line, sizeof line, "%-32s %9ld %-4s %9ld %-4s   0\n", "joint-limit violations", k.limit_violations,
                k.limit_violations == 0 ? "ok" : "FAIL", m.limit_violations, m.limit_violations == 0 ? "ok" : "FAIL");
  out += line;
  row("largest joint jump (deg)", k.max_jump_deg, m.max_jump_deg, "<= 60", k.max_jump_deg <= kMaxJumpTarget,
      m.max_jump_deg <= kMaxJumpTarget);
  row("lowest point (m)", k.lowest_m, m.lowest_m, ">= -0.02", k.lowest_m >= -kGroundTolerance,
      m.lowest_m >= -kGroundTolerance);
  row("step-in on contact max (m)", k.step_in_m.max(), m.step_in_m.max(), "<= 0.30",
      k.step_in_m.max() <= kMaxStepInTarget + kStepInQuantM, m.step_in_m.max() <= kMaxStepInTarget + kStepInQuantM);
  std::snprintf(line, sizeof line, "%-32s %14s %14s\n", "all targets", targets_hold(k) ? "HOLD" : "FAIL",
                targets_hold(m) ? "HOLD" : "FAIL");
  out += line;
  return out;
}

}  // namespace mc::anim::tools

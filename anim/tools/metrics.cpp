#include "anim/tools/metrics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "anim/body_frame.hpp"
#include "anim/ground_contact.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/local_to_model_job.hpp"

namespace mc::anim::tools {

double Distribution::mean() const {
  if (values.empty()) return 0;
  double s = 0;
  for (double v : values) s += v;
  return s / static_cast<double>(values.size());
}

double Distribution::percentile(double p) const {
  if (values.empty()) return 0;
  std::vector<double> v = values;
  std::sort(v.begin(), v.end());
  const auto i = static_cast<std::size_t>(std::clamp(p / 100.0, 0.0, 1.0) * static_cast<double>(v.size() - 1) + 0.5);
  return v[i];
}

double Distribution::max() const {
  return values.empty() ? 0 : *std::max_element(values.begin(), values.end());
}

namespace {

void pose_models(const SkeletonDef& s, const PlayerPose& pose, std::vector<glm::mat4>& m) {
  m.resize(s.joints.size());
  LocalToModelJob fk{&s, std::span<const float>(pose.angles.data(), pose.angles.size()),
                     glm::vec3(0, pose.z, 0), m};
  fk.Run();
}

glm::vec3 to_field(const PlayerPose& pose, const glm::vec3& body) {
  const BodyFrame f(pose.x, pose.y, pose.heading);
  float fx, fy;
  f.to_field(body.x, body.z, fx, fy);
  return {fx, fy, body.y};
}

}  // namespace

glm::vec3 joint_point_field(const SkeletonDef& s, const PlayerPose& pose, int joint, glm::vec3 local) {
  std::vector<glm::mat4> m;
  pose_models(s, pose, m);
  return to_field(pose, glm::vec3(m[static_cast<std::size_t>(joint)] * glm::vec4(local, 1.0f)));
}

QualityReport measure(const SkeletonDef& skel, const std::vector<WorldState>& states,
                      const std::vector<PoseFrame>& frames, const std::vector<FrameInfo>& infos,
                      const std::vector<AnimEvent>& events, double ball_r) {
  QualityReport r;
  r.frames = static_cast<long>(frames.size());
  if (frames.empty()) return r;
  const std::uint32_t seq0 = frames[0].seq;
  const int foot_joint[2] = {kRFoot, kLFoot};

  // Per player and foot: the running stance (landing spot, largest distance).
  // `swung`: the foot was seen in the air since the last reset, so its next
  // stance is a real touch-down (not feet put down by a teleport).
  struct Stance { bool on = false; glm::vec3 start{0}; double worst = 0; int frames = 0; bool swung = false; };
  std::array<std::array<Stance, 2>, kMaxPlayers> stance{};
  std::array<std::vector<double>, kMaxPlayers> landings;  // times (s) of touch-downs
  std::vector<glm::mat4> m;
  const int dofs = skel.dof_count();
  // Strides (three touch-downs) of one player since its last teleport.
  double fastest = 0;
  auto flush_strides = [&](std::size_t p) {
    auto& l = landings[p];
    for (std::size_t i = 2; i < l.size(); ++i) {
      if (l[i] - l[i - 2] >= 2.0) continue;
      const double c = 2.0 / (l[i] - l[i - 2]);
      r.cadence.values.push_back(c);
      if (c > fastest) {
        fastest = c;
        char buf[96];
        std::snprintf(buf, sizeof buf, "seq %u, slot %zu", seq0 + static_cast<std::uint32_t>(std::lround(l[i] / 0.05)), p);
        r.max_cadence_where = buf;
      }
    }
    l.clear();
  };

  for (std::size_t fi = 0; fi < frames.size(); ++fi) {
    const PoseFrame& f = frames[fi];
    const FrameInfo* info = fi < infos.size() ? &infos[fi] : nullptr;
    const PoseFrame* prev = fi > 0 ? &frames[fi - 1] : nullptr;
    const FrameInfo* prev_info = fi > 0 && fi - 1 < infos.size() ? &infos[fi - 1] : nullptr;
    const std::size_t si = f.seq / 2;
    const WorldState* st = f.substep == 0 && si < states.size() ? &states[si] : nullptr;
    const double t = 0.05 * static_cast<double>(f.seq - seq0);
    for (std::size_t p = 0; p < kMaxPlayers; ++p) {
      const PlayerPose& pose = f.players[p];
      const bool active = (pose.state & state_bits::kStand) != 0;
      if (st != nullptr && st->players[p].active())
        r.root_error_m.values.push_back(std::hypot(pose.x - st->players[p].x, pose.y - st->players[p].y));
      // Limits.
      std::size_t k = 0;
      for (const JointDef& j : skel.joints)
        for (std::size_t d = 0; d < j.dofs.size(); ++d, ++k)
          if (pose.angles[k] < j.limits[d][0] - 0.01f || pose.angles[k] > j.limits[d][1] + 0.01f)
            ++r.limit_violations;
      if (!active || info == nullptr) {
        for (auto& s : stance[p]) s.on = s.swung = false;
        continue;
      }
      const PlayerFrameInfo& pi = info->players[p];
      // Jumps between frames, outside actions and resets.
      if (prev != nullptr && prev_info != nullptr && (prev->players[p].state & state_bits::kStand) &&
          !pi.reset && !pi.in_action && !prev_info->players[p].in_action && !prev_info->players[p].reset) {
        for (int d = 0; d < dofs; ++d) {
          const double raw = std::fabs(pose.angles[static_cast<std::size_t>(d)] -
                                       prev->players[p].angles[static_cast<std::size_t>(d)]);
          // Neck and head yaw follow the server's neck angle exactly, which
          // turns up to 180 deg per cycle: reported on their own.
          if (d == dof::kNeck || d == dof::kHead) {
            r.max_head_jump_deg = std::max(r.max_head_jump_deg, raw);
            continue;
          }
          const double jump = raw;
          const int leg = d >= dof::kLHip ? 1 : d >= dof::kRHip ? 0 : -1;
          const bool stance = leg >= 0 && pi.planted[leg] && prev_info->players[p].planted[leg];
          ++r.joint_frames;
          if (jump > 15.0) {
            ++r.jumps_over_15;
            if (std::getenv("MATCHCAST_ANIM_JUMPS") != nullptr) {
              const double v = std::hypot(pose.x - prev->players[p].x, pose.y - prev->players[p].y) / 0.05;
              std::fprintf(stderr, "jump dof %d %.1f v %.1f stance %d %s seq %u slot %zu\n", d, jump, v, stance ? 1 : 0, action_name(pi.action), f.seq, p);
            }
          }
          if (!stance) r.max_jump_swing_deg = std::max(r.max_jump_swing_deg, jump);
          if (jump > r.max_jump_deg) {
            r.max_jump_deg = jump;
            char buf[160];
            std::snprintf(buf, sizeof buf, "seq %u, %s %d, dof %d (%s)", f.seq,
                          pose.side == Side::Left ? "left" : "right", pose.unum, d, action_name(pi.action));
            r.max_jump_where = buf;
          }
        }
      }
      // Stances of planted feet.
      pose_models(skel, pose, m);
      const float lowest = lowest_point_ms(skel, m);
      if (lowest < -kGroundTolerance && std::getenv("MATCHCAST_ANIM_GROUND") != nullptr)
        std::fprintf(stderr, "ground %.3f seq %u slot %zu %s%s\n", lowest, f.seq, p, action_name(pi.action),
                     pi.in_action ? " (in action)" : "");
      if (lowest < r.lowest_m) {
        r.lowest_m = lowest;
        char buf[96];
        std::snprintf(buf, sizeof buf, "seq %u, slot %zu (%s)", f.seq, p, action_name(pi.action));
        r.lowest_where = buf;
      }
      for (int foot = 0; foot < 2; ++foot) {
        Stance& s = stance[p][static_cast<std::size_t>(foot)];
        const glm::vec3 ankle = to_field(pose, glm::vec3(m[static_cast<std::size_t>(foot_joint[foot])][3]));
        const bool planted = pi.planted[foot] && !pi.reset;
        if (pi.reset) s.swung = false;
        if (planted && !s.on) {
          if (s.swung && !pi.in_action) landings[p].push_back(t);
          s = Stance{true, ankle, 0, 0, false};
        }
        if (!pi.planted[foot] && !pi.reset) s.swung = true;
        if (planted) {
          s.worst = std::max(s.worst, static_cast<double>(std::hypot(ankle.x - s.start.x, ankle.y - s.start.y)));
          ++s.frames;
        } else if (s.on) {
          if (s.frames >= 2) r.slide_m.values.push_back(s.worst);
          if (s.frames >= 2 && s.worst > 0.3 && std::getenv("MATCHCAST_ANIM_SLIDES") != nullptr)
            std::fprintf(stderr, "slide %.2f seq %u slot %zu foot %d frames %d\n", s.worst, f.seq, p, foot, s.frames);
          if (s.frames >= 2 && s.worst >= r.slide_m.max()) {
            char buf[96];
            std::snprintf(buf, sizeof buf, "seq %u, slot %zu, foot %d", f.seq, p, foot);
            r.max_slide_where = buf;
          }
          s.on = false;
        }
      }
      if (pi.reset) flush_strides(p);  // no stride spans a teleport
    }
  }
  for (auto& ps : stance)
    for (auto& s : ps)
      if (s.on && s.frames >= 2) r.slide_m.values.push_back(s.worst);
  for (std::size_t p = 0; p < landings.size(); ++p) flush_strides(p);
  for (const AnimEvent& e : events) {
    if (e.type != AnimEventType::Kick || e.seq < seq0) continue;
    const std::size_t fi = e.seq - seq0;
    if (fi >= frames.size()) continue;
    const std::size_t p = static_cast<std::size_t>(player_index(e.side, e.unum));
    const PlayerPose& pose = frames[fi].players[p];
    // From the foot's box (its contact surface, whichever face meets the
    // ball) to the ball's surface, as issue 23 measures it.
    const int foot = e.foot == Foot::Right ? kRFoot : kLFoot;
    pose_models(skel, pose, m);
    const glm::mat4& fm = m[static_cast<std::size_t>(foot)];
    const BallPose& b = frames[fi].ball;
    float bx, bz;
    BodyFrame(pose.x, pose.y, pose.heading).to_body(b.x, b.y, bx, bz);
    const glm::vec3 local = glm::transpose(glm::mat3(fm)) * (glm::vec3(bx, b.z, bz) - glm::vec3(fm[3]));
    const Segment& seg = skel.joints[static_cast<std::size_t>(foot)].segment;
    const glm::vec3 q = glm::abs(local - glm::vec3(seg.center[0], seg.center[1], seg.center[2])) -
                        0.5f * glm::vec3(seg.size[0], seg.size[1], seg.size[2]);
    const glm::vec3 outside = glm::max(q, glm::vec3(0.0f));
    const double d = std::sqrt(glm::dot(outside, outside)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
    r.contact_m.values.push_back(std::fabs(d - ball_r));
    if (fi > 0 && fi + 1 < frames.size()) {  // the step-in: how far the root leaves its path for the contact
      const PlayerPose& a = frames[fi - 1].players[p];
      const PlayerPose& c = frames[fi + 1].players[p];
      r.step_in_m.values.push_back(std::hypot(pose.x - 0.5 * (a.x + c.x), pose.y - 0.5 * (a.y + c.y)));
    }
    if (std::getenv("MATCHCAST_ANIM_CONTACTS") != nullptr && std::fabs(d - ball_r) > 0.1)
      std::fprintf(stderr, "contact %.3f seq %u slot %zu foot %d ball %.2f %.2f root %.2f %.2f h %.0f\n", std::fabs(d - ball_r),
                   e.seq, p, static_cast<int>(e.foot), b.x, b.y, pose.x, pose.y, pose.heading);
    ++r.kicks;
  }
  return r;
}

bool targets_hold(const QualityReport& r) {
  return r.root_error_m.max() <= 0.01 && r.slide_m.mean() <= 0.02 && r.contact_m.mean() <= 0.05 &&
         r.cadence.max() <= 4.5 && r.limit_violations == 0 && r.max_jump_deg <= kMaxJumpTarget &&
         r.lowest_m >= -kGroundTolerance && r.step_in_m.max() <= kMaxStepInTarget + kStepInQuantM;
}

std::string format_report(const QualityReport& r) {
  char buf[3072];
  auto pf = [](bool ok) { return ok ? "PASS" : "FAIL"; };
  std::snprintf(
      buf, sizeof buf,
      "frames %ld, kicks %ld\n"
      "root error at cycles     max %.4f m  mean %.5f m          target <= 0.01 m   %s\n"
      "planted-foot slide       mean %.4f m  p95 %.4f m  max %.4f m (%s) (%zu stances)  target mean <= 0.02 m  %s\n"
      "foot-to-ball at contact  mean %.4f m  p95 %.4f m  max %.4f m   target <= 0.05 m   %s\n"
      "cadence                  max %.2f steps/s (%s)  p99 %.2f  mean %.2f (%zu strides)  target <= 4.5   %s\n"
      "joint-limit violations   %ld                              target 0           %s\n"
      "largest joint jump       %.2f deg at %s   target <= 60 deg   %s\n"
      "  joint-frames over 15 deg: %ld of %ld (%.4f%%); largest outside legs in a continuing stance: %.2f deg\n"
      "  (neck/head yaw, which follow the server's neck angle exactly: largest jump %.1f deg, not counted)\n"
      "lowest body point        %.4f m at %s   target >= -%.2f m   %s\n"
      "step-in root offset      mean %.4f m  p95 %.4f m  max %.4f m   target <= %.2f m (+%.2f grid)   %s\n",
      r.frames, r.kicks, r.root_error_m.max(), r.root_error_m.mean(), pf(r.root_error_m.max() <= 0.01),
      r.slide_m.mean(), r.slide_m.percentile(95), r.slide_m.max(), r.max_slide_where.c_str(), r.slide_m.values.size(),
      pf(r.slide_m.mean() <= 0.02), r.contact_m.mean(), r.contact_m.percentile(95), r.contact_m.max(),
      pf(r.contact_m.mean() <= 0.05), r.cadence.max(), r.max_cadence_where.c_str(), r.cadence.percentile(99), r.cadence.mean(),
      r.cadence.values.size(), pf(r.cadence.max() <= 4.5), r.limit_violations, pf(r.limit_violations == 0),
      r.max_jump_deg, r.max_jump_where.c_str(), pf(r.max_jump_deg <= kMaxJumpTarget), r.jumps_over_15, r.joint_frames,
      100.0 * static_cast<double>(r.jumps_over_15) / static_cast<double>(std::max(1L, r.joint_frames)), r.max_jump_swing_deg, r.max_head_jump_deg,
      r.lowest_m, r.lowest_where.c_str(), kGroundTolerance, pf(r.lowest_m >= -kGroundTolerance), r.step_in_m.mean(),
      r.step_in_m.percentile(95), r.step_in_m.max(), kMaxStepInTarget, kStepInQuantM,
      pf(r.step_in_m.max() <= kMaxStepInTarget + kStepInQuantM));
  return buf;
}

}  // namespace mc::anim::tools

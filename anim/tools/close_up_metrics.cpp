#include "anim/tools/close_up_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "anim/ground_contact.hpp"
#include "anim/tools/posed_body.hpp"

namespace mc::anim::tools {

const char* speed_band_name(int b) {
  static const char* kNames[kSpeedBands] = {"stand (<0.5)", "0.5-1", "1-2", "2-3", "3-4", "4-5",
                                            "5-6",          "6-7",   "7-8", "8-9", "9+"};
  return b >= 0 && b < kSpeedBands ? kNames[b] : "?";
}

int speed_band(double v) {
  if (v < 0.5) return 0;
  if (v < 1.0) return 1;
  return std::min(kSpeedBands - 1, 1 + static_cast<int>(v));
}

double band_mean(const CloseUpReport& r, int band) { return r.grounded_mps[static_cast<std::size_t>(band)].mean(); }

namespace {

using namespace close_up;
using namespace posed;

// `k`: the draw's place past frame `f`, in drawn frames (k + phase).
std::string who(const PoseFrame& f, double k, int m, const PlayerPose& p, const char* what) {
  char buf[160];
  if (m > 1 && k > 0)
    std::snprintf(buf, sizeof buf, "seq %u+%g/%d, %s %d%s%s", f.seq, k, m, p.side == Side::Left ? "left" : "right",
                  p.unum, what[0] ? ", " : "", what);
  else
    std::snprintf(buf, sizeof buf, "seq %u, %s %d%s%s", f.seq, p.side == Side::Left ? "left" : "right", p.unum,
                  what[0] ? ", " : "", what);
  return buf;
}

}  // namespace

CloseUpReport measure_close_up(const StreamView& view, const std::vector<WorldState>& states,
                               const std::vector<PoseFrame>& produced, int draws_per_frame, DrawnLegs drawn_legs,
                               double draw_phase) {
  CloseUpReport r;
  const int m = std::max(1, draws_per_frame);
  const double phase = m > 1 ? std::clamp(draw_phase, 0.0, 0.999) : 0.0;
  r.draws_per_frame = m;
  const std::vector<PoseFrame>& frames = view.frames;
  if (frames.empty()) return r;
  const SkeletonDef& skel = view.skeleton;
  const Rig rig(skel);
  const int dofs = skel.dof_count();
  const double frame_s = 0.001 * kFrameIntervalMs;
  const double dt = frame_s / m;
  const double per_frame = frame_s / dt;  // changes scaled to 50 ms

  std::array<Geom, kMaxPlayers> prev, cur;
  std::array<bool, kMaxPlayers> have_prev{};
  // Cadence: touch-down times and the start of each player's current run.
  std::array<std::vector<double>, kMaxPlayers> touch;
  std::array<double, kMaxPlayers> run_start{};
  std::array<bool, kMaxPlayers> in_run{};
  auto flush_run = [&](std::size_t p, double end) {
    if (in_run[p])
      for (double t0 = run_start[p]; t0 + 2.0 <= end + 1e-9; t0 += 1.0) {
        const auto n = std::count_if(touch[p].begin(), touch[p].end(), [&](double t) { return t >= t0 && t < t0 + 2.0; });
        if (n > 0) r.cadence.values.push_back(0.5 * static_cast<double>(n));
      }
    touch[p].clear();
    in_run[p] = false;
  };
  // Time at the limits (20 Hz frames).
  std::vector<long> at_limit(skel.joints.size(), 0);
  long limit_frames = 0;

  float worst_step[4] = {0, 0, 0, 0};
  // Debugging aid: MATCHCAST_CLOSEUP_TRACE="SLOT FROM_SEQ TO_SEQ" prints that
  // player's feet on every drawn frame (stderr).
  // MATCHCAST_CLOSEUP_SLIDES=V lists the grounded feet faster than V m/s,
  // the poses deeper than 2 cm under the grass and more (anim/README.md).
  const double slides_over = std::getenv("MATCHCAST_CLOSEUP_SLIDES") ? std::atof(std::getenv("MATCHCAST_CLOSEUP_SLIDES")) : 0.0;
  int trace_slot = -1;
  unsigned trace_from = 0, trace_to = 0;
  if (const char* t = std::getenv("MATCHCAST_CLOSEUP_TRACE"))
    if (std::sscanf(t, "%d %u %u", &trace_slot, &trace_from, &trace_to) != 3) trace_slot = -1;
  PoseFrame drawn;
  const LegBlend legs(skel);
  // MATCHCAST_CLOSEUP_BREAKDOWN=B sorts the drawn grounded pairs by whether
  // the foot is on the grass in the 20 Hz frames around them (stderr), for
  // the speed bands from B up (4, 3 m/s, at least; 10 is 9+ m/s).
  const bool breakdown = m > 1 && std::getenv("MATCHCAST_CLOSEUP_BREAKDOWN");
  const int bd_band = breakdown ? std::max(4, std::atoi(std::getenv("MATCHCAST_CLOSEUP_BREAKDOWN"))) : 4;
  std::vector<std::array<std::array<bool, 2>, kMaxPlayers>> g20;
  if (breakdown) {
    g20.resize(frames.size());
    Geom gg;
    for (std::size_t i = 0; i < frames.size(); ++i)
      for (std::size_t p = 0; p < kMaxPlayers; ++p) {
        pose(skel, rig, frames[i].players[p], gg);
        for (int s = 0; s < 2; ++s) g20[i][p][static_cast<std::size_t>(s)] = gg.active && gg.feet[s].grounded;
      }
  }
  double bd_sum[4] = {0, 0, 0, 0};
  long bd_n[4] = {0, 0, 0, 0};
  // The same pairs by the foot's speed: below 1, 1-3, 3-6 and 6+ m/s (a
  // foot skimming the grass in its swing is in the last).
  double bd_speed_sum[4][4] = {};
  long bd_speed_n[4][4] = {};
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const int subs = i + 1 < frames.size() ? m : 1;
    for (int k = 0; k < subs; ++k) {
      const PoseFrame* fp = &frames[i];
      // This draw's place between frames i and i + 1 (the last frame is
      // drawn as it is).
      const double at = i + 1 < frames.size() ? (k + phase) / m : 0.0;
      if (at > 0.0) {
        blend_like_clients(frames[i], frames[i + 1], static_cast<float>(at), dofs, drawn,
                           drawn_legs == DrawnLegs::LegBlend ? &legs : nullptr);
        fp = &drawn;
      } else if (m > 1) {
        drawn = frames[i];
        fp = &drawn;
      }
      // At the drawing rate, every pose as a client draws it: rested on the grass.
      if (m > 1) rest_on_grass(skel, drawn);
      const PoseFrame& f = *fp;
      ++r.frames;
      const double t = (static_cast<double>(i) + at) * frame_s;
      // The 20 Hz interval the pair (previous drawn frame, this one) lies in.
      const bool has_interval = k > 0 || i > 0;
      const std::size_t lo = k > 0 ? i : (i > 0 ? i - 1 : 0);
      // Past frame i as well when this draw is the first after it at a
      // phase: the pair then spans frame i.
      const std::size_t hi = k == 0 && at > 0.0 && i > 0 ? i : lo;
      for (std::size_t p = 0; p < kMaxPlayers; ++p) {
        const PlayerPose& pp = f.players[p];
        Geom& g = cur[p];
        pose(skel, rig, pp, g);
        if (!g.active) {
          have_prev[p] = false;
          flush_run(p, t);
          continue;
        }
        ++r.player_frames;
        // Nothing under the grass.
        float lowest_here = 0;
        for (std::size_t j = 0; j < skel.joints.size(); ++j) {
          const float low = segment_lowest_ms(skel.joints[j].segment, g.world[j]);
          lowest_here = std::min(lowest_here, low);
          if (low < r.lowest_m) {
            r.lowest_m = low;
            r.lowest_where = who(f, at * m, m, pp, skel.joints[j].name.c_str());
          }
        }
        if (slides_over > 0 && lowest_here < -0.02f)
          std::fprintf(stderr, "under seq %u+%d slot %zu %.3f rate %d\n", f.seq, k, p, lowest_here, m);
        // Time at the limits.
        if (m == 1 || k == 0) {
          ++limit_frames;
          for (std::size_t j = 0; j < skel.joints.size(); ++j) {
            const JointDef& jd = skel.joints[j];
            for (std::size_t d = 0; d < jd.dofs.size(); ++d) {
              const float a = pp.angles[static_cast<std::size_t>(rig.first_dof[j]) + d];
              if (a <= jd.limits[d][0] + kAtLimitDeg || a >= jd.limits[d][1] - kAtLimitDeg) {
                ++at_limit[j];
                break;
              }
            }
          }
        }
        // Clearance and hands, on every drawn frame.
        {
          const float ct = clearance(rig, g, rig.thigh[0], rig.thigh[1]);
          const float cs = clearance(rig, g, rig.shin[0], rig.shin[1]);
          const float cf = clearance(rig, g, rig.foot[0], rig.foot[1]);
          float cx = 1;
          for (int s = 0; s < 2; ++s) {
            cx = std::min(cx, clearance(rig, g, rig.thigh[s], rig.shin[1 - s]));
            cx = std::min(cx, clearance(rig, g, rig.thigh[s], rig.foot[1 - s]));
            cx = std::min(cx, clearance(rig, g, rig.shin[s], rig.foot[1 - s]));
          }
          if (slides_over > 0 && (ct < 0 || cs < 0 || cf < 0)) {
            // The root's speed over this 20 Hz interval: which gait brings legs together.
            const PlayerPose& next = frames[std::min(i + 1, frames.size() - 1)].players[p];
            const double v = std::hypot(next.x - frames[i].players[p].x, next.y - frames[i].players[p].y) / frame_s;
            std::fprintf(stderr, "close seq %u+%d slot %zu thighs %.3f shins %.3f feet %.3f v %.1f\n", f.seq, k, p, ct, cs, cf, v);
          }
          if (ct < 0) ++r.thighs_close;
          if (cs < 0) ++r.shins_close;
          if (cf < 0) ++r.feet_close;
          if (cx < 0) ++r.crossed_close;
          if ((ct < 0 || cs < 0 || cf < 0) && r.clearance_worst_where.empty())
            r.clearance_worst_where = who(f, at * m, m, pp, ct < 0 ? "thighs" : cs < 0 ? "shins" : "feet");
          float depth = 0;
          for (int s = 0; s < 2; ++s)
            for (int body : {rig.pelvis, rig.torso, rig.thigh[0], rig.thigh[1]}) {
              const float dd = hand_depth(rig, g, rig.hand[s], body);
              if (slides_over > 0 && dd > kHandDepthM)
                std::fprintf(stderr, "hand %.3f seq %u+%d slot %zu hand %d in %s\n", dd, f.seq, k, p, s,
                             skel.joints[static_cast<std::size_t>(body)].name.c_str());
              depth = std::max(depth, dd);
            }
          if (depth > kHandDepthM) ++r.hands_inside;
          if (depth > r.hand_depth_max_m) {
            r.hand_depth_max_m = depth;
            r.hand_worst_where = who(f, at * m, m, pp, "");
          }
        }
        // Frame-to-frame figures: only within one 20 Hz interval without a
        // teleport, with the player active at both of its ends.
        bool pair = have_prev[p] && has_interval;
        if (pair) {
          const PlayerPose& a = frames[lo].players[p];
          const PlayerPose& b = frames[std::min(lo + 1, frames.size() - 1)].players[p];
          pair = (a.state & state_bits::kStand) && (b.state & state_bits::kStand) &&
                 std::hypot(b.x - a.x, b.y - a.y) <= kTeleportM;
          if (pair && hi > lo) {
            const PlayerPose& c = frames[hi + 1].players[p];
            pair = (c.state & state_bits::kStand) && std::hypot(c.x - b.x, c.y - b.y) <= kTeleportM;
          }
        }
        if (!pair) {
          flush_run(p, t);
          in_run[p] = true;
          run_start[p] = t;
        }
        if (pair) {
          const Geom& q = prev[p];
          const double root_v = std::hypot(g.x - q.x, g.y - q.y) / dt;
          const int band = speed_band(root_v);
          for (int s = 0; s < 2; ++s) {
            const FootGeom& fa = q.feet[s];
            const FootGeom& fb = g.feet[s];
            if (fb.grounded && !fa.grounded) touch[p].push_back(t);
            if (!(fa.grounded && fb.grounded)) continue;
            const int j = rig.foot[s];
            const glm::vec3 pa(q.world[static_cast<std::size_t>(j)] * glm::vec4(fa.contact_ls, 1.0f));
            const glm::vec3 pb(g.world[static_cast<std::size_t>(j)] * glm::vec4(fa.contact_ls, 1.0f));
            const double v = std::hypot(pb.x - pa.x, pb.z - pa.z) / dt;
            r.grounded_mps[static_cast<std::size_t>(band)].values.push_back(v);
            if (breakdown && band >= bd_band) {
              const std::size_t hi = std::min(lo + 1, frames.size() - 1);
              const int c = (g20[lo][p][static_cast<std::size_t>(s)] ? 2 : 0) + (g20[hi][p][static_cast<std::size_t>(s)] ? 1 : 0);
              bd_sum[c] += v;
              ++bd_n[c];
              const int q = v < 1 ? 0 : v < 3 ? 1 : v < 6 ? 2 : 3;
              bd_speed_sum[c][q] += v;
              ++bd_speed_n[c][q];
            }
            if (slides_over > 0 && v > slides_over)
              std::fprintf(stderr, "slide %.2f m/s seq %u+%d slot %zu foot %d root %.1f m/s low %.3f -> %.3f rate %d\n", v, f.seq, k, p,
                           s, root_v, fa.lowest, fb.lowest, m);
            if (v > 0.5) ++r.grounded_over_half[static_cast<std::size_t>(band)];
            if (v > r.grounded_worst_mps) {
              r.grounded_worst_mps = v;
              char what[96];
              std::snprintf(what, sizeof what, "%s foot, root %.1f m/s", s == 0 ? "right" : "left", root_v);
              r.grounded_worst_where = who(f, at * m, m, pp, what);
            }
          }
          // Joint changes by group.
          float step[4] = {0, 0, 0, 0};
          int worst[4] = {0, 0, 0, 0};
          for (std::size_t j = 0; j < skel.joints.size(); ++j) {
            const float d = rotation_deg(q.rot[j], g.rot[j]) * static_cast<float>(per_frame);
            const int gr = rig.group[j];
            if (d > step[gr]) { step[gr] = d; worst[gr] = static_cast<int>(j); }
          }
          Distribution* dist[4] = {&r.leg_step_deg, &r.arm_step_deg, &r.trunk_step_deg, &r.head_step_deg};
          std::string* where[4] = {&r.leg_worst_where, &r.arm_worst_where, &r.trunk_worst_where, &r.head_worst_where};
          for (int gr = 0; gr < 4; ++gr) {
            if (step[gr] > worst_step[gr] || dist[gr]->values.empty()) {
              worst_step[gr] = step[gr];
              *where[gr] = who(f, at * m, m, pp, skel.joints[static_cast<std::size_t>(worst[gr])].name.c_str());
            }
            dist[gr]->values.push_back(step[gr]);
          }
          if (step[kLegs] > 50) ++r.legs_over_50;
          if (step[kLegs] > kLegStepDeg) ++r.legs_over_60;
          if (step[kArms] > kArmStepDeg) ++r.arms_over_45;
          if (step[kArms] > 50) ++r.arms_over_50;
          if (step[kTrunk] > 45) ++r.trunk_over_45;
          if (step[kHead] > 45) ++r.head_over_45;
          // Ankle pops.
          const glm::vec3 pel_a(q.world[0][3]), pel_b(g.world[0][3]);
          for (int s = 0; s < 2; ++s) {
            const auto j = static_cast<std::size_t>(rig.foot[s]);
            const glm::vec3 aa(q.world[j][3]), ab(g.world[j][3]);
            const double mv = glm::length(ab - aa) * per_frame;
            const double rel = glm::length((ab - pel_b) - (aa - pel_a)) * per_frame;
            r.ankle_step_max_m = std::max(r.ankle_step_max_m, mv);
            if (mv > kAnklePopM || rel > kAnklePopRelM) {
              ++r.ankle_pops;
              if (slides_over > 0)
                std::fprintf(stderr, "pop seq %u+%d slot %zu foot %d move %.2f rel %.2f root %.1f m/s rate %d\n", f.seq, k, p, s,
                             mv, rel, root_v, m);
            }
          }
          // Floating.
          const float low = std::min(g.feet[0].lowest, g.feet[1].lowest);
          if (low > kFloatAboveM && root_v < kFloatSlowerMps) {
            ++r.floating;
            if (slides_over > 0) std::fprintf(stderr, "float %.3f seq %u+%d slot %zu root %.1f m/s\n", low, f.seq, k, p, root_v);
            if (low > r.floating_max_m) {
              r.floating_max_m = low;
              r.floating_where = who(f, at * m, m, pp, "");
            }
          }
        }
        if (static_cast<int>(p) == trace_slot && f.seq >= trace_from && f.seq <= trace_to) {
          std::fprintf(stderr, "seq %u+%d x %.3f y %.3f z %.3f h %.1f pair %d", f.seq, k, pp.x, pp.y, pp.z, pp.heading, pair ? 1 : 0);
          for (int s = 0; s < 2; ++s) {
            const auto j = static_cast<std::size_t>(rig.foot[s]);
            const glm::vec3 c(g.world[j] * glm::vec4(g.feet[s].contact_ls, 1.0f));
            float v = 0;
            if (pair && prev[p].feet[s].grounded && g.feet[s].grounded) {
              const glm::vec3 pa(prev[p].world[j] * glm::vec4(prev[p].feet[s].contact_ls, 1.0f));
              const glm::vec3 pb(g.world[j] * glm::vec4(prev[p].feet[s].contact_ls, 1.0f));
              v = static_cast<float>(std::hypot(pb.x - pa.x, pb.z - pa.z) / dt);
            }
            std::fprintf(stderr, " | %c low %.3f %s c %.3f %.3f v %.2f", s == 0 ? 'R' : 'L', g.feet[s].lowest,
                         g.feet[s].grounded ? "G" : "-", c.x, c.z, v);
          }
          std::fprintf(stderr, " | apart %.3f %.3f %.3f\n", clearance(rig, g, rig.thigh[0], rig.thigh[1]),
                       clearance(rig, g, rig.shin[0], rig.shin[1]), clearance(rig, g, rig.foot[0], rig.foot[1]));
        }
        std::swap(prev[p], cur[p]);
        have_prev[p] = true;
      }
    }
  }
  const double end_t = static_cast<double>(frames.size()) * frame_s;
  for (std::size_t p = 0; p < kMaxPlayers; ++p) flush_run(p, end_t);
  if (std::getenv("MATCHCAST_CLOSEUP_LIMITS") != nullptr && m == 1) {  // per dof, min and max
    std::vector<long> lo(static_cast<std::size_t>(dofs), 0), hi(static_cast<std::size_t>(dofs), 0);
    long n = 0;
    for (const PoseFrame& f : frames)
      for (const PlayerPose& pp : f.players) {
        if ((pp.state & state_bits::kStand) == 0) continue;
        ++n;
        std::size_t k = 0;
        for (const JointDef& jd : skel.joints)
          for (std::size_t d = 0; d < jd.dofs.size(); ++d, ++k) {
            if (pp.angles[k] <= jd.limits[d][0] + kAtLimitDeg) ++lo[k];
            if (pp.angles[k] >= jd.limits[d][1] - kAtLimitDeg) ++hi[k];
          }
      }
    for (int k = 0; k < dofs; ++k)
      if (lo[static_cast<std::size_t>(k)] + hi[static_cast<std::size_t>(k)] > n / 1000)
        std::fprintf(stderr, "limit dof %d: at min %.2f%%, at max %.2f%%\n", k, 100.0 * lo[static_cast<std::size_t>(k)] / n,
                     100.0 * hi[static_cast<std::size_t>(k)] / n);
  }
  // Time at the limits.
  for (std::size_t j = 0; j < skel.joints.size(); ++j) {
    const double share = limit_frames > 0 ? static_cast<double>(at_limit[j]) / static_cast<double>(limit_frames) : 0.0;
    if (static_cast<int>(j) == rig.foot[0] || static_cast<int>(j) == rig.foot[1])
      r.ankle_limit_share = std::max(r.ankle_limit_share, share);
    if (share > r.worst_limit_share) {
      r.worst_limit_share = share;
      r.worst_limit_joint = skel.joints[j].name;
    }
  }
  // Root at cycles and joint limits (the animator's output: the encoder clamps).
  for (const PoseFrame& f : frames) {
    const std::size_t si = f.seq / 2;
    if (f.substep != 0 || si >= states.size()) continue;
    for (std::size_t p = 0; p < kMaxPlayers; ++p)
      if (states[si].players[p].active())
        r.root_error_m.values.push_back(
            std::hypot(f.players[p].x - states[si].players[p].x, f.players[p].y - states[si].players[p].y));
  }
  for (const PoseFrame& f : produced)
    for (const PlayerPose& pp : f.players) {
      std::size_t k = 0;
      for (const JointDef& j : skel.joints)
        for (std::size_t d = 0; d < j.dofs.size(); ++d, ++k)
          if (pp.angles[k] < j.limits[d][0] - 0.01f || pp.angles[k] > j.limits[d][1] + 0.01f) ++r.limit_violations;
    }
  // Kicks at contact_time_ms.
  const std::uint32_t seq0 = frames[0].seq;
  double worst_kick = 0;
  for (const proto::KickEvent& e : view.kicks) {
    const std::uint64_t seq = e.contact_time_ms / kFrameIntervalMs;
    if (seq < seq0 || seq - seq0 >= frames.size()) continue;
    const std::size_t fi = seq - seq0;
    const int slot = player_index(e.side, e.unum);
    if (slot < 0) continue;
    if (std::getenv("MATCHCAST_CLOSEUP_SLIDES") != nullptr && m == 1)
      std::fprintf(stderr, "kick seq %llu slot %d\n", static_cast<unsigned long long>(seq), slot);
    const PlayerPose& pp = frames[fi].players[static_cast<std::size_t>(slot)];
    Geom g;
    pose(skel, rig, pp, g);
    const int j = rig.foot[e.foot == proto::Foot::Left ? 1 : 0];
    const Box& b = rig.box[static_cast<std::size_t>(j)];
    const glm::mat4& w = g.world[static_cast<std::size_t>(j)];
    const BallPose& ball = frames[fi].ball;
    const glm::vec3 bw(ball.x, ball.z, ball.y);
    const glm::vec3 bl = glm::transpose(glm::mat3(w)) * (bw - glm::vec3(w[3]));
    const double d = box_sd(b, bl) - view.ball_radius;
    const glm::vec3 toe(w * glm::vec4(b.c + glm::vec3(b.h.x, 0, 0), 1.0f));
    const double dt_toe = glm::length(toe - bw) - view.ball_radius;
    r.kick_box_m.values.push_back(d);
    if (std::getenv("MATCHCAST_CLOSEUP_SLIDES") != nullptr && m == 1)
      std::fprintf(stderr, "kickdist %+.3f seq %llu slot %d foot %d ball %.3f %.3f\n", d, static_cast<unsigned long long>(seq), slot,
                   e.foot == proto::Foot::Left ? 1 : 0, ball.x, ball.y);
    r.kick_toe_m.values.push_back(dt_toe);
    if (d < -kKickInsideM) ++r.kicks_inside;
    const double bad = d < 0 ? -d : d;
    if (bad > worst_kick) {
      worst_kick = bad;
      char what[64];
      std::snprintf(what, sizeof what, "%s foot %+.3f m", e.foot == proto::Foot::Left ? "left" : "right", d);
      r.kick_worst_where = who(frames[fi], 0, 1, pp, what);
    }
    if (fi > 0 && fi + 1 < frames.size()) {
      const PlayerPose& a = frames[fi - 1].players[static_cast<std::size_t>(slot)];
      const PlayerPose& c = frames[fi + 1].players[static_cast<std::size_t>(slot)];
      r.step_in_m.values.push_back(std::hypot(pp.x - 0.5 * (a.x + c.x), pp.y - 0.5 * (a.y + c.y)));
    }
    ++r.kicks;
  }
  if (breakdown) {
    const char* names[4] = {"air -> air", "air -> grass", "grass -> air", "grass -> grass"};
    double total = 0;
    for (double x : bd_sum) total += x;
    for (int c = 0; c < 4; ++c)
      std::fprintf(stderr, "drawn grounded pairs, root >= %d m/s, 20 Hz feet %s: %ld pairs, mean %.2f m/s, %.0f %% of the sliding\n",
                   bd_band - 1, names[c], bd_n[c], bd_n[c] ? bd_sum[c] / static_cast<double>(bd_n[c]) : 0.0, total > 0 ? 100 * bd_sum[c] / total : 0.0);
    const char* speeds[4] = {"< 1", "1-3", "3-6", "6+"};
    for (int c = 0; c < 4; ++c)
      for (int q = 0; q < 4; ++q)
        std::fprintf(stderr, "  %s, foot at %s m/s: %ld pairs, %.0f %% of the sliding\n", names[c], speeds[q], bd_speed_n[c][q],
                     total > 0 ? 100 * bd_speed_sum[c][q] / total : 0.0);
  }
  return r;
}

}  // namespace mc::anim::tools

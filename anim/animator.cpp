#include "anim/animator.hpp"

#include <algorithm>
#include <cmath>

#include "anim/body_frame.hpp"
#include "anim/kick_planner.hpp"
#include "anim/motion_source.hpp"
#include "anim/player_animation.hpp"
#include "anim/portable_math.hpp"

namespace mc::anim {
namespace {

float lerpf(double a, double b, float t) { return static_cast<float>(a + (b - a) * t); }

// A tackler moving more than this in a cycle (2 m/s at 100 ms) is up again...
constexpr float kGetUpMovePerCycle = 0.2f;
// ...and is back on his feet this long after (the tackle's blend-out, s).
constexpr float kTackleGetUpS = 0.3f;
// A kick's support foot this far from the 2D root (m) is locomotion's again
// (action_motion.cpp, kick()).
constexpr float kSupportReleaseM = 0.45f;

}  // namespace

Animator::Animator(const SkeletonDef& skeleton, const GameParams& params, AnimConfig config)
    : skeleton_(skeleton), params_(params),
      k_{params.simulator_step_ms(), params.ball_size(), params.server.number("tackle_cycles", 10),
         params.server.number("stamina_max", 8000)},
      config_(config), grid_(skeleton), drawn_legs_(skeleton), players_(std::make_unique<std::array<PlayerAnim, kMaxPlayers>>()) {
  config_.lookahead_cycles = std::clamp(config_.lookahead_cycles, 1, 50);
  config_.heading_half_window = std::clamp(config_.heading_half_window, 0, 10);
  // Past cycles needed: heading window, and the raw decision of the previous
  // cycle (which looks one further back).
  ring_.resize(static_cast<std::size_t>(config_.lookahead_cycles + config_.heading_half_window + 4));
  raw_memo_.resize(ring_.size() * kMaxPlayers);
  heading_unit_.resize(ring_.size() * kMaxPlayers);
}

Animator::~Animator() = default;

const WorldState& Animator::state_at(std::uint64_t pos) const {
  // Callers clamp pos into [pushed_ - ring size, pushed_).
  return ring_[pos % ring_.size()];
}

Action Animator::last_action(int slot) const {
  if (slot < 0 || slot >= kMaxPlayers) return Action::Stand;
  return (*players_)[static_cast<std::size_t>(slot)].action;
}

// Each cycle's decision is asked for up to six times (the smoothing window,
// the planning, the hold); it is remembered with what it was made from (the
// states before and after it, when the ring had them).
Action Animator::raw_action(std::uint64_t pos, int slot) const {
  const std::uint64_t oldest = pushed_ > ring_.size() ? pushed_ - ring_.size() : 0;
  const auto i = static_cast<std::size_t>(slot);
  const bool has_prev = pos > oldest, has_next = pos + 1 < pushed_;
  RawDecision& memo = raw_memo_[(pos % ring_.size()) * kMaxPlayers + i];
  if (memo.pos == pos && memo.has_prev == has_prev && memo.has_next == has_next) return memo.action;
  const WorldState& cur = state_at(pos);
  ClassifyInput in;
  in.cur = &cur.players[i];
  in.prev = has_prev ? &state_at(pos - 1).players[i] : nullptr;
  in.next = has_next ? &state_at(pos + 1).players[i] : nullptr;
  in.ball = &cur.ball;
  in.type = &params_.type(cur.players[i].type);
  memo = RawDecision{pos, has_prev, has_next, classify_raw(in)};
  return memo.action;
}

Action Animator::action_at(std::uint64_t pos, int slot) const {
  std::array<Action, 3> w{};
  std::size_t n = 0, centre = 0;
  const std::uint64_t oldest = pushed_ > ring_.size() ? pushed_ - ring_.size() : 0;
  if (pos > oldest + 1) w[n++] = raw_action(pos - 1, slot);  // raw(pos-1) looks at pos-2
  centre = n;
  w[n++] = raw_action(pos, slot);
  if (pos + 1 < pushed_) w[n++] = raw_action(pos + 1, slot);
  return smooth_action(std::span<const Action>(w.data(), n), centre);
}

float Animator::smoothed_heading(std::uint64_t pos, int slot) const {
  const auto i = static_cast<std::size_t>(slot);
  const PlayerState& c = state_at(pos).players[i];
  const int w = config_.heading_half_window;
  // The future side stops one cycle short of the look-ahead so that the
  // heading of the next cycle is final when a half-way frame needs it.
  const int ahead = std::min(w, config_.lookahead_cycles - 1);
  const std::uint64_t oldest = pushed_ > ring_.size() ? pushed_ - ring_.size() : 0;
  double sx = 0, sy = 0;
  for (int k = -w; k <= ahead; ++k) {
    if (k < 0 && pos < oldest + static_cast<std::uint64_t>(-k)) continue;
    const std::uint64_t j = pos + static_cast<std::uint64_t>(static_cast<std::int64_t>(k));
    if (j >= pushed_) continue;
    const PlayerState& p = state_at(j).players[i];
    if (p.active() != c.active()) continue;
    const double wt = w + 1 - std::abs(k);
    const HeadingUnit& u = heading_unit_[(j % ring_.size()) * kMaxPlayers + i];
    sx += wt * u.c;
    sy += wt * u.s;
  }
  // Opposite headings cancel: fall back to the cycle's own heading.
  if (pm::hypot(sx, sy) < 0.25) return static_cast<float>(c.body);
  return static_cast<float>(pm::atan2(sy, sx) / kDeg);
}

void Animator::push(const WorldState& state, std::vector<PoseFrame>& out, std::vector<AnimEvent>* events) {
  const std::size_t at = pushed_ % ring_.size();
  ring_[at] = state;
  for (std::size_t i = 0; i < kMaxPlayers; ++i) {
    HeadingUnit& u = heading_unit_[at * kMaxPlayers + i];
    pm::sincos(state.players[i].body * kDeg, u.s, u.c);  // one reduction, the same bits as sin and cos
  }
  ++pushed_;
  while (emitted_ + static_cast<std::uint64_t>(config_.lookahead_cycles) < pushed_)
    emit_cycle(emitted_++, out, events);
}

void Animator::finish(std::vector<PoseFrame>& out, std::vector<AnimEvent>* events) {
  while (emitted_ < pushed_) emit_cycle(emitted_++, out, events);
}

void Animator::emit_events(std::uint64_t pos, std::vector<AnimEvent>& events) const {
  const std::uint64_t oldest = pushed_ > ring_.size() ? pushed_ - ring_.size() : 0;
  if (pos <= oldest) return;
  const WorldState& a = state_at(pos);
  const WorldState& p = state_at(pos - 1);
  AnimEvent base;
  base.seq = static_cast<std::uint32_t>(2 * a.index);
  base.time = a.time;
  base.play_mode = a.play_mode;
  base.score_left = static_cast<std::uint8_t>(a.left.score);
  base.score_right = static_cast<std::uint8_t>(a.right.score);
  if (a.play_mode != p.play_mode) {
    AnimEvent e = base;
    e.type = AnimEventType::PlayMode;
    events.push_back(e);
  }
  if (a.left.score > p.left.score || a.right.score > p.right.score) {
    AnimEvent e = base;
    e.type = AnimEventType::Goal;
    e.side = a.left.score > p.left.score ? Side::Left : Side::Right;
    events.push_back(e);
  }
  for (std::size_t i = 0; i < a.players.size(); ++i) {
    const std::uint32_t now = a.players[i].state, before = p.players[i].state;
    Card card = Card::None;
    if ((now & state_bits::kRedCard) && !(before & state_bits::kRedCard)) card = Card::Red;
    else if ((now & state_bits::kYellowCard) && !(before & state_bits::kYellowCard)) card = Card::Yellow;
    if (card == Card::None) continue;
    AnimEvent e = base;
    e.type = AnimEventType::Card;
    e.side = a.players[i].side;
    e.unum = a.players[i].unum;
    e.card = card;
    events.push_back(e);
  }
}

void Animator::plan_actions(std::uint64_t pos, int slot) {
  const auto i = static_cast<std::size_t>(slot);
  PlayerAnim& ctx = (*players_)[i];
  const double step_s = 0.001 * k_.step_ms;
  const float prepare_s = static_cast<float>(config_.lookahead_cycles * step_s - 0.5 * step_s);
  const std::uint64_t last = std::min(pos + static_cast<std::uint64_t>(config_.lookahead_cycles), pushed_ - 1);
  for (std::uint64_t k = pos + 1; k <= last; ++k) {
    if (k + 1 <= ctx.last_action_pos) continue;  // seen by an earlier cycle
    const Action r = raw_action(k, slot);
    const WorldState& sk = state_at(k);
    const WorldState& sp = state_at(k - 1);
    const PlayerState& p = sk.players[i];
    const PlayerState& q = sp.players[i];
    if (r == Action::Kick) {
      ctx.last_action_pos = k + 1;
      // The bits say kick; the geometry must agree (some feeds lose the
      // fault bit): the ball was within the player's kickable distance.
      const double reach = params_.type(q.type).kickable_distance(k_.ball_size) + 0.25;
      if (pm::hypot(sp.ball.x - q.x, sp.ball.y - q.y) > reach) continue;
      const double contact = (static_cast<double>(k) - 0.5) * step_s;
      if (ctx.motion_active && merge_kick(ctx.motion, contact, k)) continue;
      KickPlanInput in;
      in.root_x = static_cast<float>(0.5 * (p.x + q.x));
      in.root_y = static_cast<float>(0.5 * (p.y + q.y));
      // The heading the player will have at contact: the per-frame filter of
      // player_animation run forward over the frames from now to the
      // contact frame (k - 1, half-way) with the targets emit_cycle will give
      // it. (A constant target one frame short left the body up to 84 deg
      // off the plan where the player turned just before the kick, and the
      // planned foot on the wrong side of the ball: issue 23.)
      {
        float h = ctx.heading;
        const auto frames = 2 * (k - pos);
        for (std::uint64_t n = 0; n < frames; ++n) {
          const std::uint64_t at = pos + n / 2;
          const float h_at = smoothed_heading(at, slot);
          const float target = n % 2 == 0 ? h_at : lerp_deg(h_at, smoothed_heading(at + 1, slot), 0.5f);
          h = wrap_deg(h + clampf(0.5f * delta_deg(target, h), -kMaxTurnPerFrameDeg, kMaxTurnPerFrameDeg));
        }
        in.heading = h;
      }
      in.ball_x = static_cast<float>(sp.ball.x);
      in.ball_y = static_cast<float>(sp.ball.y);
      in.after_x = static_cast<float>(sk.ball.x);
      in.after_y = static_cast<float>(sk.ball.y);
      in.ball_radius = static_cast<float>(k_.ball_size);
      in.contact_time_s = contact;
      in.prepare_s = prepare_s;
      in.speed = static_cast<float>(pm::hypot(p.x - q.x, p.y - q.y) / step_s);
      ctx.motion = plan_kick(in);
      ctx.motion.last_kick_pos = k;
      ctx.motion_active = true;
      ctx.ball_contact_pos = k;  // the ball waits at the foot on the half-way frame of k-1
      AnimEvent& e = ctx.kick_event;
      e = AnimEvent{};
      e.type = AnimEventType::Kick;
      e.seq = static_cast<std::uint32_t>(2 * sp.index + 1);
      e.time = sp.time;
      e.side = p.side;
      e.unum = p.unum;
      e.foot = ctx.motion.foot;
      e.contact_time_ms = static_cast<std::uint64_t>(e.seq) * kFrameIntervalMs;
      e.play_mode = sp.play_mode;
      e.score_left = static_cast<std::uint8_t>(sp.left.score);
      e.score_right = static_cast<std::uint8_t>(sp.right.score);
      ctx.kick_event_pending = true;
      continue;
    }
    const bool tackle_starts = r == Action::Tackle && raw_action(k - 1, slot) != Action::Tackle;
    if (!tackle_starts && r != Action::Catch && r != Action::Dive) continue;
    ctx.last_action_pos = k + 1;
    // Tackles, catches and dives happen on the cycle itself.
    ActionMotion m;
    m.kind = r == Action::Tackle ? MotionKind::Tackle : r == Action::Catch ? MotionKind::Catch : MotionKind::Dive;
    m.contact_time_s = static_cast<double>(k) * step_s;
    m.start_s = -std::min(0.15f, prepare_s + 0.05f);
    const BodyFrame body(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.body));
    float bx, bz;
    body.to_body(static_cast<float>(sk.ball.x), static_cast<float>(sk.ball.y), bx, bz);
    m.side = bz >= 0 ? 1.0f : -1.0f;
    m.foot = bz >= 0 ? Foot::Right : Foot::Left;
    m.ball_x = static_cast<float>(sk.ball.x);
    m.ball_y = static_cast<float>(sk.ball.y);
    const float tackle_s = static_cast<float>(k_.tackle_cycles * step_s);
    m.follow_s = m.kind == MotionKind::Tackle ? tackle_s : 0.2f;
    m.end_s = m.kind == MotionKind::Tackle ? tackle_s + 0.3f : m.kind == MotionKind::Catch ? 0.5f : 0.9f;
    // A kick whose contact is still to come is not cut short: this action
    // waits for it (the contact frame and its Kick event come first).
    const double now = static_cast<double>(pos) * step_s;
    if (ctx.motion_active && ctx.motion.kind == MotionKind::Kick && ctx.motion.contact_time_s >= now) {
      ctx.next_motion = m;
      ctx.next_pending = true;
    } else {
      ctx.motion = m;
      ctx.motion_active = true;
    }
  }
}

void Animator::emit_cycle(std::uint64_t pos, std::vector<PoseFrame>& out, std::vector<AnimEvent>* events) {
  const WorldState& a = state_at(pos);
  const bool has_next = pos + 1 < pushed_;
  const WorldState& b = has_next ? state_at(pos + 1) : a;
  const std::uint64_t oldest = pushed_ > ring_.size() ? pushed_ - ring_.size() : 0;
  const double stamina_max = k_.stamina_max;
  const float ball_r = static_cast<float>(k_.ball_size);
  const DetailLevel detail = config_.detail;
  const bool loco_on = detail == DetailLevel::Run || detail == DetailLevel::Full;
  FootstepParams lp;
  lp.cadence_cap = config_.cadence_cap;

  std::array<Action, kMaxPlayers> act{};
  std::array<bool, kMaxPlayers> hold{};
  std::array<float, kMaxPlayers> h0{}, h1{};
  for (int i = 0; i < kMaxPlayers; ++i) {
    act[static_cast<std::size_t>(i)] = action_at(pos, i);
    const Action next = has_next ? raw_action(pos + 1, i) : Action::Stand;
    hold[static_cast<std::size_t>(i)] = !has_next || next == Action::Teleport ||
                                        !b.players[static_cast<std::size_t>(i)].active();
    h0[static_cast<std::size_t>(i)] = smoothed_heading(pos, i);
    h1[static_cast<std::size_t>(i)] = hold[static_cast<std::size_t>(i)] ? h0[static_cast<std::size_t>(i)]
                                                                         : smoothed_heading(pos + 1, i);
  }
  if (events != nullptr) emit_events(pos, *events);
  const bool actions_on = detail == DetailLevel::Kick || detail == DetailLevel::Full;
  const double step_s = 0.001 * k_.step_ms;
  for (int i = 0; i < kMaxPlayers; ++i) plan_actions(pos, i);

  for (int sub = 0; sub < kFramesPerCycle; ++sub) {
    const float t = 0.5f * static_cast<float>(sub);
    PoseFrame& f = out.emplace_back();
    f.seq = static_cast<std::uint32_t>(2 * a.index + static_cast<std::uint64_t>(sub));
    f.time = a.time;
    f.stoppage = a.stoppage;
    f.substep = static_cast<std::uint8_t>(sub);
    f.server_time_ms = 0;
    f.play_mode = a.play_mode;
    f.score_left = static_cast<std::uint8_t>(std::clamp(a.left.score, 0, 255));
    f.score_right = static_cast<std::uint8_t>(std::clamp(a.right.score, 0, 255));
    f.ball.x = lerpf(a.ball.x, b.ball.x, t);
    f.ball.y = lerpf(a.ball.y, b.ball.y, t);
    f.ball.z = ball_r;
    // A kick's contact: the ball is still where it was kicked from.
    if (sub == 1 && actions_on)
      for (const PlayerAnim& pa : *players_)
        if (pa.motion_active && pa.ball_contact_pos == pos + 1) {
          f.ball.x = static_cast<float>(a.ball.x);
          f.ball.y = static_cast<float>(a.ball.y);
        }
    FrameInfo* info = nullptr;
    if (info_sink_ != nullptr) {
      info = &info_sink_->emplace_back();
      info->seq = f.seq;
    }
    for (std::size_t i = 0; i < kMaxPlayers; ++i) {
      const PlayerState& pa = a.players[i];
      const PlayerState& pb = b.players[i];
      PlayerAnim& ctx = (*players_)[i];
      PlayerPose& pose = f.players[i];
      pose.side = pa.side;
      pose.unum = pa.unum;
      pose.state = pa.state;
      const float ti = hold[i] ? 0.0f : t;
      PlayerFrameInput in;
      in.x = lerpf(pa.x, pb.x, ti);
      in.y = lerpf(pa.y, pb.y, ti);
      in.heading = lerp_deg(h0[i], h1[i], ti);
      in.body = lerp_deg(static_cast<float>(pa.body), static_cast<float>(pb.body), ti);
      in.neck = lerpf(pa.neck, pb.neck, ti);
      if (!hold[i] && (pb.x != pa.x || pb.y != pa.y)) {
        in.move_dx = static_cast<float>(pb.x - pa.x);
        in.move_dy = static_cast<float>(pb.y - pa.y);
      } else if (pos > oldest) {
        const PlayerState& pp = state_at(pos - 1).players[i];
        in.move_dx = static_cast<float>(pa.x - pp.x);
        in.move_dy = static_cast<float>(pa.y - pp.y);
      }
      in.action = act[i];
      in.stamina = static_cast<float>(std::clamp(pa.stamina / stamina_max, 0.0, 1.0));
      in.reset = (sub == 0 && act[i] == Action::Teleport) || !pa.active() || !ctx.was_active;
      in.animate_locomotion = loco_on && pa.active();
      in.dt = 0.001f * static_cast<float>(k_.step_ms) / kFramesPerCycle;
      // The action playing at this frame, if any.
      ActionSample sample;
      const double now = (static_cast<double>(pos) + 0.5 * sub) * step_s;
      // A teleport cancels what was playing; an action planned for after it
      // (a kick-off kick) keeps its plan, made from the new positions.
      if (in.reset && ctx.motion_active && ctx.motion.contact_time_s < now) ctx.motion_active = false;
      if (ctx.next_pending && (!ctx.motion_active || now > ctx.motion.contact_time_s + 1e-6)) {
        ctx.motion = ctx.next_motion;
        ctx.motion_active = true;
        ctx.next_pending = false;
      }
      if (ctx.motion_active) {
        const float tau = static_cast<float>(now - ctx.motion.contact_time_s);
        // A tackler the server lets run again (the tackle bit gone, the 2D
        // body faster than a jog) gets up now rather than at the end of
        // tackle_cycles: held on the grass, the slide's pose glided along
        // with the runner at up to 9.6 m/s (issue 23). The envelope's own
        // 0.3 s ramp brings him up, with no jump.
        if (ctx.motion.kind == MotionKind::Tackle && tau > 0 && (pa.state & (state_bits::kTackle | state_bits::kTackleFault)) == 0 &&
            pm::hypot(in.move_dx, in.move_dy) > kGetUpMovePerCycle && ctx.motion.end_s > tau + kTackleGetUpS) {
          ctx.motion.end_s = tau + kTackleGetUpS;
          ctx.motion.follow_s = std::min(ctx.motion.follow_s, tau);
        }
        // A kick whose support foot locomotion has taken back (the 2D body
        // ran on past its reach) ends its follow-through now: held up for
        // the rest of a merged kick's long follow-through, the kicking foot
        // left both feet in the air (issue 23, floating).
        if (ctx.motion.kind == MotionKind::Kick && tau > 0.12f && tau < ctx.motion.follow_s &&
            pm::hypot(ctx.motion.support_x - in.x, ctx.motion.support_y - in.y) > kSupportReleaseM) {
          const float cut = tau - ctx.motion.follow_s;
          ctx.motion.follow_s = tau;
          ctx.motion.end_s = std::max(ctx.motion.end_s + cut, tau + 0.15f);
        }
        if (tau > ctx.motion.end_s + 1e-4f) ctx.motion_active = false;
        else if (actions_on && pa.active()) {
          sample = sample_action(ctx.motion, tau, ctx.heading, in.x, in.y);
          // Mocap mode: the kicking foot and the body's swing from a captured kick.
          if (config_.motion_source && ctx.motion.kind == MotionKind::Kick && sample.weight > 0)
            config_.motion_source->kick(ctx.motion, tau, ctx.heading, in.x, in.y, sample);
        }
      }
      if (sample.weight > 0) in.layer = &sample;
      in.source = config_.motion_source.get();
      in.grid = &grid_;
      in.drawn_legs = &drawn_legs_;
      // The path ahead, frame by frame, as far as the look-ahead reaches and
      // not across a teleport.
      {
        float lx = in.x, ly = in.y;
        for (int m = 1; m <= kPathAhead; ++m) {
          const int fr = sub + m;
          const std::uint64_t c = pos + static_cast<std::uint64_t>(fr / 2);
          const bool half = fr % 2 != 0;
          if (c >= pushed_ || (half && c + 1 >= pushed_)) break;
          const PlayerState& s0 = state_at(c).players[i];
          const PlayerState& s1 = half ? state_at(c + 1).players[i] : s0;
          if (!s0.active() || !s1.active()) break;
          const float nx = lerpf(s0.x, s1.x, half ? 0.5f : 0.0f), ny = lerpf(s0.y, s1.y, half ? 0.5f : 0.0f);
          if (pm::hypot(nx - lx, ny - ly) > 1.0f) break;
          in.ahead_x[in.ahead_n] = lx = nx;
          in.ahead_y[in.ahead_n] = ly = ny;
          ++in.ahead_n;
        }
      }
      if (ctx.kick_event_pending && ctx.kick_event.seq == f.seq) {
        ctx.kick_event_pending = false;
        if (events != nullptr) events->push_back(ctx.kick_event);
      }
      bool planted[2] = {false, false};
      animate_player(ctx, in, lp, skeleton_, pose, planted);
      if (info != nullptr) {
        PlayerFrameInfo& pi = info->players[i];
        pi.action = in.action;
        pi.in_action = sample.weight > 0;
        pi.reset = in.reset;
        pi.planted[0] = planted[0];
        pi.planted[1] = planted[1];
      }
      ctx.was_active = pa.active();
    }
  }
}

}  // namespace mc::anim

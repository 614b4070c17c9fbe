// The state FrameEncoder and FrameDecoder keep in lockstep, and the one
// template that walks a frame body for both (so that the two sides cannot
// disagree on an order or a context). Internal to proto/; SPEC.md section 4
// describes the same walk in prose.
//
// Everything here restarts at each keyframe, so a decoder that starts at
// any keyframe rebuilds exactly the encoder's state.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "proto/quantizer.hpp"
#include "proto/residual_coder.hpp"

namespace mc::proto::detail {

// Adaptive contexts of one kind of frame (keyframes and deltas keep separate
// sets: their statistics differ by orders of magnitude).
struct ModelSet {
  SignedModel ball_xy, ball_z, pos_xy, pos_z, heading;
  std::array<SignedModel, kMaxDof> angle;
  Prob meta_changed = kProbInit;
  void reset();
};
// Every context at its start, a compile-time constant: reset() is one copy.
inline constexpr ModelSet kInitialModelSet{};
inline void ModelSet::reset() { *this = kInitialModelSet; }

// The last residual of each value, per player: its magnitude picks the
// activity class of the next residual of the same value.
struct LastResiduals {
  std::array<std::int32_t, 3> ball{};
  std::array<std::array<std::int32_t, 4>, kMaxPlayers> root{};       // x, y, z, heading
  std::array<std::array<std::int32_t, kMaxDof>, kMaxPlayers> angle{};
};

// Which predictor serves each kind of value (x, y, z, heading, each dof;
// shared by all players): a running cost of "hold" (the previous value) and
// "linear" (constant velocity), each the absolute error (capped at 1023) it
// would have made, decayed by 1/128 per player value. Legs driven by foot
// contacts move in jerks that hold predicts better; a turning head or a
// swinging arm is better extrapolated. Per player and faster decay was
// tried and is worse (it chases noise). Both sides learn it from decoded
// values, so it costs no bits.
//
// Frames at the cycle (substep 0) and half-way (substep 1) keep separate
// costs: anim places the root on the 2D state at substep 0 and interpolates
// at substep 1, and the best predictor differs (on a real game, linear wins
// at substep 0 and hold at substep 1).
struct PredictorCosts {
  static constexpr int kValues = 4 + kMaxDof;  // x, y, z, heading, then the dofs
  std::array<std::array<std::uint32_t, kValues>, 2> hold{}, linear{};
  int substep = 0;  // of the frame being coded, 0 or 1
  bool use_linear(std::size_t, int value) const {
    const auto s = static_cast<std::size_t>(substep);
    return linear[s][static_cast<std::size_t>(value)] <= hold[s][static_cast<std::size_t>(value)];
  }
  void learn(std::size_t, int value, std::int64_t err_hold, std::int64_t err_linear) {
    const auto upd = [](std::uint32_t& c, std::int64_t e) {
      const std::int64_t m = std::min<std::int64_t>(e < 0 ? -e : e, 1023);
      c = static_cast<std::uint32_t>(c - (c >> 7) + m);
    };
    const auto s = static_cast<std::size_t>(substep);
    upd(hold[s][static_cast<std::size_t>(value)], err_hold);
    upd(linear[s][static_cast<std::size_t>(value)], err_linear);
  }
};

// Residual prediction between dofs of the same player in the same frame:
// the residual of dof d is predicted as round(coef2[d] / 2 * residual of dof
// partner[d]), partner[d] < d. Mirrored limbs and chained joints (an arm
// swings against the other, the head turns with the neck) move together,
// so one residual says much about another. The encoder picks the table
// from the statistics of the frames it has seen and sends it in every
// keyframe; the decoder only follows it.
inline constexpr std::array<std::int8_t, 8> kPartnerCoef2 = {-4, -3, -2, -1, 1, 2, 3, 4};
struct PartnerTable {
  std::array<std::int8_t, kMaxDof> partner;  // -1: none
  std::array<std::int8_t, kMaxDof> coef2{};  // twice the coefficient
  PartnerTable() { partner.fill(-1); }
  // round(c2 * r / 2), halves away from zero.
  static std::int64_t term(int c2, std::int64_t r) {
    const std::int64_t t = c2 * r;
    return t >= 0 ? (t + 1) / 2 : -((-t + 1) / 2);
  }
};

// The table an encoder sends in its next keyframe, from what it has seen:
// base_cost[d], the bits of dof d's residuals with no partner, and
// partner_cost[(d * kMaxDof + p) * 8 + k], with partner p at kPartnerCoef2[k].
// Then those statistics fade: half weight per keyframe interval. (The
// encoder and the format study in tests/proto/bench both call it, so that
// the study measures the encoder's rule.)
inline PartnerTable choose_partners(std::vector<std::uint64_t>& base_cost, std::vector<std::uint32_t>& partner_cost,
                                    int dofs) {
  const auto n = static_cast<std::size_t>(kMaxDof);
  PartnerTable t;
  for (int d = 0; d < dofs; ++d) {
    const auto dd = static_cast<std::size_t>(d);
    // A partner must save 5% of the dof's bits: the table costs 9 bits per
    // entry per keyframe, and a marginal gain is noise.
    std::uint64_t best = base_cost[dd] - base_cost[dd] / 20;
    for (int p = 0; p < d; ++p)
      for (std::size_t k = 0; k < 8; ++k) {
        const std::uint32_t c = partner_cost[(dd * n + static_cast<std::size_t>(p)) * 8 + k];
        if (c < best) {
          best = c;
          t.partner[dd] = static_cast<std::int8_t>(p);
          t.coef2[dd] = kPartnerCoef2[k];
        }
      }
  }
  for (auto& c : partner_cost) c >>= 1;
  for (auto& c : base_cost) c >>= 1;
  return t;
}

struct CodecModel {
  // The two context sets (~56 KB), made at the first keyframe, which resets
  // them anyway: a new decoder or encoder costs no copy of them. (A replay
  // opens a decoder per reader and an encoder per player; copying the sets
  // twice was 5-8 % of the two replay fuzzers' time.) Every frame a coder
  // accepts or writes is, or follows, a keyframe: sets() is there for one
  // that is asked to walk a delta first, and returns fresh sets.
  struct Sets {
    ModelSet key, delta;
  };
  Sets& sets() {
    if (!sets_) sets_.emplace();
    return *sets_;
  }
  PartnerTable partners;
  // The angle residuals of the last delta before partner prediction (what
  // the encoder's partner statistics learn from).
  std::array<std::array<std::int32_t, kMaxDof>, kMaxPlayers> raw_angle_residual{};
  LastResiduals last;
  PredictorCosts costs;
  QuantFrame prev, prev2;  // the frames at t-1 and t-2, as decoded
  int history = 0;         // how many of prev, prev2 are valid (0..2)

  void reset_for_keyframe() {
    if (sets_) {
      sets_->key.reset();
      sets_->delta.reset();
    } else {
      sets_.emplace();
    }
    last = LastResiduals{};
    costs = PredictorCosts{};
    history = 0;
  }
  void push(const QuantFrame& f) {
    prev2 = prev;
    prev = f;
    history = std::min(history + 1, 2);
  }

  // Linear extrapolation from the two previous frames (constant velocity);
  // right after a keyframe only one frame is known, so hold it. Clamped to
  // the value's range.
  std::int32_t predict(std::int32_t a1, std::int32_t a0, std::int32_t lo, std::int32_t hi, bool linear = true) const {
    const std::int64_t p = history >= 2 && linear ? 2 * static_cast<std::int64_t>(a1) - a0 : a1;
    return static_cast<std::int32_t>(std::clamp<std::int64_t>(p, lo, hi));
  }
  // Heading lives on a circle of kHeadingSteps: extrapolate the wrapped turn.
  std::int32_t predict_heading(std::int32_t a1, std::int32_t a0, bool linear = true) const {
    return history >= 2 && linear ? wrap(a1 + wrap_signed(a1 - a0)) : a1;
  }
  // After a player value `v` is known: both predictors' errors update its costs.
  void learn(std::size_t player, int value, std::int32_t v, std::int32_t a1, std::int32_t a0, std::int32_t lo,
             std::int32_t hi) {
    if (history < 2) return;
    costs.learn(player, value, static_cast<std::int64_t>(v) - a1, static_cast<std::int64_t>(v) - predict(a1, a0, lo, hi));
  }
  void learn_heading(std::size_t player, std::int32_t v, std::int32_t a1, std::int32_t a0) {
    if (history < 2) return;
    costs.learn(player, 3, wrap_signed(static_cast<std::int64_t>(v) - a1),
                wrap_signed(static_cast<std::int64_t>(v) - predict_heading(a1, a0)));
  }
  static std::int32_t wrap(std::int64_t v) {
    const std::int64_t m = v % kHeadingSteps;
    return static_cast<std::int32_t>(m < 0 ? m + kHeadingSteps : m);
  }
  // Into [-kHeadingSteps / 2, kHeadingSteps / 2 - 1] = [-182, 181].
  static std::int32_t wrap_signed(std::int64_t v) { return wrap(v + kHeadingSteps / 2) - kHeadingSteps / 2; }

 private:
  std::optional<Sets> sets_;
};

// Zero context: the activity of the same value last time, and whether the
// previous value of the same player in this frame was non-zero.
inline int zero_ctx(int act, bool prev_nonzero) { return act * 2 + (prev_nonzero ? 1 : 0); }

// Walks a frame body. `Io` is EncodeIo or DecodeIo (frame_encoder.cpp /
// frame_decoder.cpp), each with:
//   bool value(SignedModel&, std::int32_t& v, std::int32_t pred, lo, hi, int zctx, int act, std::int32_t& residual)
//   bool heading(SignedModel&, std::int32_t& v, std::int32_t pred, int zctx, int act, std::int32_t& residual)
//   bool flag(Prob&, bool& b);  void direct(std::uint32_t& v, int bits);  void varbits(std::uint32_t& v)
// The encoder reads `v`, the decoder writes it. A false return means corrupt
// input (decoder only) and stops the walk.
template <class Io>
bool walk_keyframe(Io& io, CodecModel& m, const Quantizer& quant, QuantFrame& q) {
  ModelSet& s = m.sets().key;
  std::int32_t r = 0;
  // The partner table: per dof a direct bit, then partner (6 bits) and
  // coefficient index (3 bits).
  for (int d = 0; d < quant.dof_count(); ++d) {
    const auto k = static_cast<std::size_t>(d);
    std::uint32_t has = m.partners.partner[k] >= 0 ? 1u : 0u;
    io.direct(has, 1);
    if (!has) {
      m.partners.partner[k] = -1;
      continue;
    }
    std::uint32_t partner = static_cast<std::uint32_t>(m.partners.partner[k]);
    std::uint32_t coef = 0;
    while (coef < 7 && kPartnerCoef2[coef] != m.partners.coef2[k]) ++coef;
    io.direct(partner, 6);
    io.direct(coef, 3);
    if (!io.check(partner < static_cast<std::uint32_t>(d), "partner dof")) return false;
    m.partners.partner[k] = static_cast<std::int8_t>(partner);
    m.partners.coef2[k] = kPartnerCoef2[coef];
  }
  for (int a = 0; a < 3; ++a)
    if (!io.value(a < 2 ? s.ball_xy : s.ball_z, q.ball[a], 0, kPositionMin, kPositionMax, 0, 0, r)) return false;
  for (std::size_t i = 0; i < q.players.size(); ++i) {
    QuantPlayer& p = q.players[i];
    const QuantPlayer* before = i > 0 ? &q.players[i - 1] : nullptr;
    std::uint32_t side = p.side, unum = p.unum;
    io.direct(side, 2);
    io.direct(unum, 4);
    io.varbits(p.state);
    p.side = static_cast<std::uint8_t>(side);
    p.unum = static_cast<std::uint8_t>(unum);
    if (!io.value(s.pos_xy, p.x, 0, kPositionMin, kPositionMax, 0, 0, r)) return false;
    if (!io.value(s.pos_xy, p.y, 0, kPositionMin, kPositionMax, 0, 0, r)) return false;
    if (!io.value(s.pos_z, p.z, before ? before->z : 0, kPositionMin, kPositionMax, 0, 0, r)) return false;
    if (!io.heading(s.heading, p.heading, 0, 0, 0, r)) return false;
    // Angles: predicted by the previous player's pose (parked and standing
    // players share one), the first player by the zero-angle pose. (The
    // zero-angle pose for every player has a lower order-0 entropy but cost
    // 3.5 % more keyframe bytes: runs of equal poses are what adapts.)
    bool prev_nonzero = false;
    for (int d = 0; d < quant.dof_count(); ++d) {
      const auto k = static_cast<std::size_t>(d);
      const std::int32_t pred = before ? before->angles[k] : quant.angle_q(d, 0.0f);
      if (!io.value(s.angle[k], p.angles[k], pred, 0, quant.grid(d).steps - 1, zero_ctx(0, prev_nonzero), 0, r))
        return false;
      prev_nonzero = r != 0;
    }
  }
  return true;
}

template <class Io>
bool walk_delta(Io& io, CodecModel& m, const Quantizer& quant, QuantFrame& q, int substep) {
  ModelSet& s = m.sets().delta;
  m.costs.substep = substep & 1;
  const QuantFrame& p1 = m.prev;
  const QuantFrame& p0 = m.prev2;
  std::int32_t r = 0;
  bool prev_nonzero = false;
  for (int a = 0; a < 3; ++a) {
    std::int32_t& last = m.last.ball[static_cast<std::size_t>(a)];
    const int act = activity_class(last);
    if (!io.value(a < 2 ? s.ball_xy : s.ball_z, q.ball[a], m.predict(p1.ball[a], p0.ball[a], kPositionMin, kPositionMax),
                  kPositionMin, kPositionMax, zero_ctx(act, prev_nonzero), act, r))
      return false;
    last = r;
    prev_nonzero = r != 0;
  }
  for (std::size_t i = 0; i < q.players.size(); ++i) {
    QuantPlayer& p = q.players[i];
    const QuantPlayer& a1 = p1.players[i];
    const QuantPlayer& a0 = p0.players[i];

    bool meta = p.side != a1.side || p.unum != a1.unum || p.state != a1.state;
    io.flag(s.meta_changed, meta);
    if (meta) {
      std::uint32_t side = p.side, unum = p.unum;
      io.direct(side, 2);
      io.direct(unum, 4);
      io.varbits(p.state);
      p.side = static_cast<std::uint8_t>(side);
      p.unum = static_cast<std::uint8_t>(unum);
    } else {
      p.side = a1.side, p.unum = a1.unum, p.state = a1.state;
    }

    auto& root_last = m.last.root[i];
    std::int32_t* const root[3] = {&p.x, &p.y, &p.z};
    const std::int32_t root1[3] = {a1.x, a1.y, a1.z};
    const std::int32_t root0[3] = {a0.x, a0.y, a0.z};
    prev_nonzero = false;
    for (int c = 0; c < 3; ++c) {
      const auto k = static_cast<std::size_t>(c);
      const int act = activity_class(root_last[k]);
      const std::int32_t pred = m.predict(root1[c], root0[c], kPositionMin, kPositionMax, m.costs.use_linear(i, c));
      if (!io.value(c < 2 ? s.pos_xy : s.pos_z, *root[c], pred, kPositionMin, kPositionMax, zero_ctx(act, prev_nonzero),
                    act, r))
        return false;
      m.learn(i, c, *root[c], root1[c], root0[c], kPositionMin, kPositionMax);
      root_last[k] = r;
      prev_nonzero = r != 0;
    }
    {
      const int act = activity_class(root_last[3]);
      const std::int32_t pred = m.predict_heading(a1.heading, a0.heading, m.costs.use_linear(i, 3));
      if (!io.heading(s.heading, p.heading, pred, zero_ctx(act, prev_nonzero), act, r)) return false;
      m.learn_heading(i, p.heading, a1.heading, a0.heading);
      root_last[3] = r;
    }

    auto& angle_last = m.last.angle[i];
    prev_nonzero = false;
    for (int d = 0; d < quant.dof_count(); ++d) {
      const auto k = static_cast<std::size_t>(d);
      const std::int32_t hi = quant.grid(d).steps - 1;
      const int act = activity_class(angle_last[k]);
      const std::int32_t pred = m.predict(a1.angles[k], a0.angles[k], 0, hi, m.costs.use_linear(i, 4 + d));
      const int partner = m.partners.partner[k];
      const std::int64_t adj =
          partner >= 0 ? PartnerTable::term(m.partners.coef2[k], m.raw_angle_residual[i][static_cast<std::size_t>(partner)]) : 0;
      if (!io.value(s.angle[k], p.angles[k], static_cast<std::int32_t>(pred + adj), 0, hi, zero_ctx(act, prev_nonzero), act, r))
        return false;
      m.raw_angle_residual[i][k] = p.angles[k] - pred;
      m.learn(i, 4 + d, p.angles[k], a1.angles[k], a0.angles[k], 0, hi);
      angle_last[k] = r;
      prev_nonzero = r != 0;
    }
  }
  return true;
}

}  // namespace mc::proto::detail

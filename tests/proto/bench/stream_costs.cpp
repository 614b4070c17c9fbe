#include "tests/proto/bench/stream_costs.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "proto/quantizer.hpp"

namespace mc::proto::stats {
namespace {

struct CostIo {
  CostIo(Costs& costs, Study& s) : c(costs), study(s) {}
  Costs& c;
  Study& study;
  bool keyframe = false;
  int player = -1;   // -1: the ball
  int index = 0;     // value index within the player (0..2 root, 3.. dofs)
  bool odd = false;  // a half-way frame (substep 1)
  const QuantFrame* prev = nullptr;  // the frame before, in deltas
  std::vector<int> band;  // per player slot, this frame
  double bits = 0;   // of the current decision group

  void bit(Prob& p, bool b) {
    const double p0 = p / 2048.0;
    bits += -std::log2(b ? 1.0 - p0 : p0);
    if (!b) p = static_cast<Prob>(p + (((1u << kProbBits) - p) >> kProbShift));
    else p = static_cast<Prob>(p - (p >> kProbShift));
  }
  void signed_cost(SignedModel& m, std::int64_t value, int zero_ctx, int act) {
    bit(m.zero[static_cast<std::size_t>(zero_ctx)], value != 0);
    if (value == 0) return;
    const auto a = static_cast<std::size_t>(act);
    bit(m.sign[a], value < 0);
    const auto mag = static_cast<std::uint32_t>(value < 0 ? -value : value);
    int b = 31;
    while (((mag >> b) & 1u) == 0) --b;
    for (int i = 0; i < b; ++i) bit(m.bucket[a][static_cast<std::size_t>(std::min(i, kBucketContexts - 1))], true);
    if (b < 31) bit(m.bucket[a][static_cast<std::size_t>(std::min(b, kBucketContexts - 1))], false);
    if (b >= 1) {
      bit(m.mant[a][static_cast<std::size_t>(std::min(b, kBucketContexts - 1))], ((mag >> (b - 1)) & 1u) != 0);
      if (b >= 2) bits += b - 1;
    }
  }
  void book(int kind) {
    if (keyframe) {
      c.key_bits += bits;
    } else {
      c.delta_bits[static_cast<std::size_t>(kind)] += bits;
      if (odd) c.odd_bits[static_cast<std::size_t>(kind)] += bits;
      if (player >= 0) c.band_bits[static_cast<std::size_t>(kind)][static_cast<std::size_t>(band[static_cast<std::size_t>(player)])] += bits;
    }
    bits = 0;
  }
  bool value(SignedModel& m, std::int32_t& v, std::int32_t pred, std::int32_t, std::int32_t, int zctx, int act,
             std::int32_t& r) {
    r = v - pred;
    {
      SignedModel* model = &m;
      const int d = index - 3, leg = study.contacts.first_leg_dof;
      const bool pl = study.contacts.now != nullptr && player >= 0 && d >= leg && d < leg + 12 &&
          ((study.contacts.now[static_cast<std::size_t>(player)] >> (d < leg + 6 ? 0 : 1)) & 1) != 0;
      if (study.contacts.split && pl && !keyframe)
        model = &study.contacts.planted_legs[static_cast<std::size_t>(d)];
      const double b0 = bits;
      signed_cost(*model, r, zctx, act);
      if (study.contacts.now != nullptr && !keyframe && player >= 0 && d >= leg && d < leg + 12) {
        const int bd = band[static_cast<std::size_t>(player)];
        study.contacts.leg_bits[bd][pl ? 1 : 0] += bits - b0;
        study.contacts.leg_n[bd][pl ? 1 : 0] += 1.0 / 6.0;
      }
    }
    if (player < 0) {
      book(kBall);
    } else if (index < 3) {
      book(kRoot + index);
    } else {
      if (!keyframe && r != 0) ++c.nonzero[static_cast<std::size_t>(index - 3)];
      if (!keyframe && prev != nullptr) {
        const int dv = std::abs(v - prev->players[static_cast<std::size_t>(player)].angles[static_cast<std::size_t>(index - 3)]);
        const auto cls = static_cast<std::size_t>(std::min(dv / 10, 4));
        c.step_count[cls] += 1;
        c.step_bits[cls] += bits;
        if (index - 3 >= c.first_leg_dof) {
          c.leg_step_count[cls] += 1;
          c.leg_step_bits[cls] += bits;
        }
      }
      if (!keyframe) {
        const int m = r < 0 ? -r : r;
        const int cls = m == 0 ? 0 : m == 1 ? 1 : m == 2 ? 2 : m <= 4 ? 3 : m <= 8 ? 4 : m <= 16 ? 5 : 6;
        c.mag_count[static_cast<std::size_t>(cls)] += 1;
        c.mag_bits[static_cast<std::size_t>(cls)] += bits;
      }
      book(kDof0 + index - 3);
    }
    ++index;
    return true;
  }
  bool heading(SignedModel& m, std::int32_t& v, std::int32_t pred, int zctx, int act, std::int32_t& r) {
    r = detail::CodecModel::wrap_signed(static_cast<std::int64_t>(v) - pred);
    signed_cost(m, r, zctx, act);
    book(kHeading);
    return true;
  }
  // The meta flag opens a player in deltas; keyframes open one with direct bits.
  bool flag(Prob& p, bool& b) {
    ++player;
    index = 0;
    bit(p, b);
    book(kMeta);
    if (study.contacts.now != nullptr && !keyframe) {
      const auto slot = static_cast<std::size_t>(player);
      const int now = study.contacts.now[slot] & 3, before = study.contacts.before != nullptr ? study.contacts.before[slot] & 3 : 0;
      const double b0 = bits;
      for (int foot = 0; foot < 2; ++foot) {
        const int ctx = foot * 8 + ((before >> foot) & 1) * 4 + ((before >> (1 - foot)) & 1) * 2 + (foot == 1 ? (now & 1) : 0);
        bit(study.contacts.bit_ctx[static_cast<std::size_t>(ctx)], ((now >> foot) & 1) != 0);
      }
      study.contacts.bits += bits - b0;
      book(kMeta);
    }
    return true;
  }
  bool check(bool, const char*) { return true; }
  void direct(std::uint32_t&, int n) {
    bits += n;
    book(kMeta);
  }
  void varbits(std::uint32_t& v) {
    int len = 0;
    while (len < 31 && (v >> len) != 0) ++len;
    bits += 5 + (len > 1 ? len - 1 : 0);
    book(kMeta);
  }
};

}  // namespace

std::uint32_t cost_bits(std::int64_t r) {  // FrameEncoder's partner estimate
  if (r == 0) return 1;
  const std::uint64_t m = static_cast<std::uint64_t>(r < 0 ? -r : r);
  return 3 + 2 * (static_cast<std::uint32_t>(std::bit_width(m)) - 1);
}

bool load(const std::string& path, Game& g) {
  std::FILE* in = std::fopen(path.c_str(), "rb");
  std::uint64_t n = 0, len = 0;
  if (!in || std::fread(&len, 8, 1, in) != 1) return false;
  std::string hello_text(len, '\0');
  if (std::fread(hello_text.data(), 1, len, in) != len || std::fread(&n, 8, 1, in) != 1) return false;
  Hello h;
  std::string error;
  if (!hello_from_json(hello_text, h, error)) return false;
  g.skeleton = h.skeleton;
  g.frames.resize(n);
  const bool ok = std::fread(g.frames.data(), sizeof(PoseFrame), n, in) == n;
  std::fclose(in);
  return ok;
}

Costs measure(const Game& g, int keyframe_interval, Study& study) {
  const Quantizer quant(g.skeleton);
  const int dofs = quant.dof_count();
  const int kinds = kDof0 + dofs;
  Costs c;
  for (int d = 0, j = 0; j < static_cast<int>(g.skeleton.joints.size()); d += static_cast<int>(g.skeleton.joints[static_cast<std::size_t>(j)].dofs.size()), ++j)
    if (g.skeleton.joints[static_cast<std::size_t>(j)].name == "r_thigh") c.first_leg_dof = study.contacts.first_leg_dof = d;
  c.delta_bits.assign(static_cast<std::size_t>(kinds), 0);
  c.band_bits.assign(static_cast<std::size_t>(kinds), {});
  c.odd_bits.assign(static_cast<std::size_t>(kinds), 0);
  c.flicker.assign(static_cast<std::size_t>(dofs), 0);
  c.moves.assign(static_cast<std::size_t>(dofs), 0);
  c.zigzag.assign(static_cast<std::size_t>(dofs), 0);
  c.acc2.assign(static_cast<std::size_t>(dofs), {});
  c.nonzero.assign(static_cast<std::size_t>(dofs), 0);
  detail::CodecModel model;
  const auto n = static_cast<std::size_t>(kMaxDof);
  std::vector<std::uint32_t> partner_cost(n * n * 8, 0);
  std::vector<std::uint64_t> base_cost(n, 0);
  int since_key = 0;
  std::uint32_t last_seq = 0;
  std::vector<QuantFrame> q(g.frames.size());
  for (std::size_t t = 0; t < g.frames.size(); ++t) q[t] = quant.quantize(g.frames[t]);

  for (std::size_t t = 0; t < g.frames.size(); ++t) {
    const PoseFrame& f = g.frames[t];
    const bool key = t == 0 || since_key >= keyframe_interval || f.seq != last_seq + 1;
    if (study.contacts.on) {
      study.contacts.now = &study.contacts.flags[t * kMaxPlayers];
      study.contacts.before = t > 0 ? &study.contacts.flags[(t - 1) * kMaxPlayers] : nullptr;
      if (key) study.contacts.reset();
    }
    CostIo io(c, study);
    io.keyframe = key;
    io.odd = (f.substep & 1) != 0;
    io.band.assign(f.players.size(), 0);
    for (std::size_t i = 0; i < f.players.size(); ++i) {
      if (t == 0) continue;
      const auto& a = g.frames[t - 1].players[i];
      const auto& b = f.players[i];
      const double v = std::hypot(double(b.x) - a.x, double(b.y) - a.y) * 20.0;
      io.band[i] = band_of(v);
    }
    QuantFrame qf = q[t];
    if (key) {
      model.reset_for_keyframe();
      detail::PartnerTable pt = detail::choose_partners(base_cost, partner_cost, dofs);  // the encoder's rule
      if (study.no_partners) pt = detail::PartnerTable{};
      model.partners = pt;
      // Keyframe: 32 fingerprint bits, then the walk (players opened by direct bits).
      io.bits += 32;
      io.book(kMeta);
      struct KeyIo : CostIo {
        explicit KeyIo(const CostIo& o) : CostIo(o) {}
        void direct(std::uint32_t& v, int bits_n) {
          if (bits_n == 2) {  // side: a new player
            ++player;
            index = 0;
          }
          CostIo::direct(v, bits_n);
        }
        bool value(SignedModel& m, std::int32_t& v, std::int32_t pred, std::int32_t lo, std::int32_t hi, int zctx,
                   int act, std::int32_t& r) {
          return CostIo::value(m, v, pred, lo, hi, zctx, act, r);
        }
      };
      KeyIo kio(io);
      detail::walk_keyframe(kio, model, quant, qf);
      since_key = 1;
      ++c.keys;
    } else {
      io.prev = &model.prev;
      detail::walk_delta(io, model, quant, qf, f.substep);
      if (study.partner_study && since_key >= 2 && since_key % 2 == 0)
        for (std::size_t i = 0; i < kMaxPlayers; ++i)
          for (int d = 0; d < dofs; ++d) c.raw.push_back(model.raw_angle_residual[i][static_cast<std::size_t>(d)]);
      if (since_key % 4 == 1) {  // FrameEncoder::learn_partners
        for (std::size_t i = 0; i < kMaxPlayers; ++i) {
          const auto& r = model.raw_angle_residual[i];
          for (int d = 0; d < dofs; ++d) {
            const std::int64_t rd = r[static_cast<std::size_t>(d)];
            base_cost[static_cast<std::size_t>(d)] += cost_bits(rd);
            for (int p = 0; p < d; ++p) {
              std::uint32_t* cc = &partner_cost[(static_cast<std::size_t>(d) * n + static_cast<std::size_t>(p)) * 8];
              for (std::size_t k = 0; k < 8; ++k)
                cc[k] += cost_bits(rd - detail::PartnerTable::term(detail::kPartnerCoef2[k], r[static_cast<std::size_t>(p)]));
            }
          }
        }
      }
      ++since_key;
      ++c.deltas;
      if (io.odd) ++c.odd_deltas;
      for (int b : io.band) c.band_player_frames[static_cast<std::size_t>(b)] += 1;
    }
    model.push(qf);
    last_seq = f.seq;
  }
  // Flicker: a -> b -> a on consecutive frames (same player, no teleport).
  for (std::size_t t = 1; t + 1 < q.size(); ++t)
    for (std::size_t i = 0; i < kMaxPlayers; ++i)
      for (int d = 0; d < dofs; ++d) {
        const auto k = static_cast<std::size_t>(d);
        const int a = q[t - 1].players[i].angles[k], b = q[t].players[i].angles[k], e = q[t + 1].players[i].angles[k];
        if (a != b) ++c.moves[k];
        if (a != b && a == e) ++c.flicker[k];
        if (t >= 2) {
          const int z = q[t - 2].players[i].angles[k];
          const int acc0 = b - 2 * a + z, acc1 = e - 2 * b + a;
          if (acc0 * acc1 < 0 && std::min(std::abs(acc0), std::abs(acc1)) >= 4) ++c.zigzag[k];
          if (std::abs(acc0) < 60) c.acc2[k][static_cast<std::size_t>(g.frames[t - 1].substep & 1)] += double(acc0) * acc0;
          if (d == 0) {
            const auto& P = [&](std::size_t u) { return q[u].players[i]; };
            const double ax = P(t).x - 2.0 * P(t - 1).x + P(t - 2).x, ay = P(t).y - 2.0 * P(t - 1).y + P(t - 2).y;
            if (std::abs(ax) < 100 && std::abs(ay) < 100) {
              c.root_acc2[0][static_cast<std::size_t>(g.frames[t - 1].substep & 1)] += ax * ax;
              c.root_acc2[1][static_cast<std::size_t>(g.frames[t - 1].substep & 1)] += ay * ay;
            }
          }
        }
      }
  return c;
}

}  // namespace mc::proto::stats

// Where a pose stream's bits go (a measurement, not a test): walks frames
// saved by `proto_pose_stream_bench --save-frames PATH` through the codec's
// own walk (codec_model.hpp) with an Io that counts the ideal cost of every
// range-coded decision (-log2 p, the adaptive probabilities updated exactly
// as the coder does, direct bits at 1 bit) instead of writing it. The
// partner table is chosen as FrameEncoder does (same statistics, same
// schedule), so the total matches the encoder's bodies within the range
// coder's flush bytes. Prints, for deltas, the bits per frame of every value
// kind (ball, meta, root, heading, each dof), by the player's horizontal
// speed band, and a flicker count per dof: a quantized angle that leaves a
// value and comes back to it on the next frame (a -> b -> a), the jitter a
// viewer sees as a twitch.
//
//   proto_pose_stream_stats [--keyframe-interval F] [--no-partners] [--partner-study]
//                           [--trace SLOT FROM TO DOF,DOF..] [--contacts PATH [--contacts-measure-only]]
//                           FRAMES [FRAMES_B]
// Also: zigzag per dof (the second difference changing sign on consecutive
// frames, both at least 4 steps: a 5-10 Hz shake, which smooth motion at
// 20 Hz rarely makes), the residuals by magnitude, the values by how far
// they moved in the frame, and the second differences at cycle frames
// against half-way frames (a 10 Hz pattern shows as a ratio far from 1).
// --trace prints one player slot's angles (and grid indices) frame by frame;
// --partner-study estimates what fixed single and paired partners would
// save; --no-partners codes without the partner table (what it is worth).
// With two files (same game, two animations) the figures are side by side
// with B - A.
// --contacts PATH (one FRAMES file; PATH from `proto_pose_stream_bench
// --save-contacts`, the same run as the frames) measures a per-foot contact
// bit in every delta (not in the wire format): each foot's planted flag as
// an adaptive bit (context: both feet's flags in the frame before, and for
// the left foot the right foot's flag now), booked under meta, and the
// legs' dofs of a planted foot coded in their own adaptive models (the
// swinging legs keep the codec's). Both sets reset at keyframes, as the
// codec's do. It also prints the legs' bits by speed band, swinging and
// planted; --contacts-measure-only keeps the codec's models for all legs
// (the legs' bits as the codec spends them, the contact bits still counted).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "proto/codec_model.hpp"
#include "proto/hello.hpp"
#include "proto/pose_frame.hpp"
#include "proto/quantizer.hpp"

using namespace mc;
using namespace mc::proto;

namespace {

bool g_study = false, g_no_partners = false;

// --contacts: the planted feet of the frame being measured and of the one
// before (bit 0 right, bit 1 left), the planted legs' models, the contact
// bits' contexts.
struct ContactStudy {
  bool on = false;
  std::vector<std::uint8_t> flags;  // [frame][slot]
  const std::uint8_t* now = nullptr;
  const std::uint8_t* before = nullptr;
  std::array<SignedModel, kMaxDof> planted_legs;
  std::array<Prob, 16> bit_ctx{};
  int first_leg_dof = 1000;
  double bits = 0;  // the contact bits, all deltas
  double leg_bits[5][2] = {}, leg_n[5][2] = {};  // [speed band][planted]: bits and leg-frames of the deltas
  bool split = true;  // false: --contacts-measure-only
  void reset() {
    for (auto& m : planted_legs) m.reset();
    bit_ctx.fill(kProbInit);
  }
} g_contacts;
constexpr int kBands = 5;
const char* kBandName[kBands] = {"<0.3 m/s", "0.3-2", "2-4", "4-6", "6+"};
int band_of(double speed) { return speed < 0.3 ? 0 : speed < 2 ? 1 : speed < 4 ? 2 : speed < 6 ? 3 : 4; }

// Value kinds: 0 ball, 1 meta, 2..4 root x y z, 5 heading, 6.. dofs.
constexpr int kBall = 0, kMeta = 1, kRoot = 2, kHeading = 5, kDof0 = 6;

struct Costs {
  std::vector<double> delta_bits;                       // [kind]
  std::vector<double> odd_bits;                         // [kind], half-way frames (substep 1)
  std::size_t odd_deltas = 0;
  std::vector<std::array<double, kBands>> band_bits;    // [kind][band]
  std::array<double, kBands> band_player_frames{};      // player-deltas per band
  std::vector<std::size_t> flicker;                     // [dof] a -> b -> a
  std::vector<std::size_t> moves;                       // [dof] frames where the index changed
  std::vector<std::size_t> zigzag;                      // [dof] acceleration alternating, both >= 4 steps
  std::vector<std::array<double, 2>> acc2;              // [dof][parity] sum of squared second differences (steps)
  std::array<std::array<double, 2>, 2> root_acc2{};     // [x|y][parity], cm
  std::vector<std::size_t> nonzero;                     // [dof] non-zero coded residuals
  double key_bits = 0;
  std::vector<std::int32_t> raw;  // raw angle residuals of every 2nd delta, [sample][player][dof] (--partner-study)
  // Dof residuals of deltas by magnitude class 0, 1, 2, 3-4, 5-8, 9-16, 17+: count and bits.
  std::array<double, 7> mag_count{}, mag_bits{};
  // Dof values of deltas by how far they moved since the last frame (steps): 0-9, 10-19, 20-29, 30-39, 40+.
  std::array<double, 5> step_count{}, step_bits{};
  std::array<double, 5> leg_step_count{}, leg_step_bits{};  // the same, the legs' dofs only
  int first_leg_dof = 1000;
  std::size_t deltas = 0, keys = 0;
};

struct CostIo {
  explicit CostIo(Costs& costs) : c(costs) {}
  Costs& c;
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
      const int d = index - 3, leg = g_contacts.first_leg_dof;
      const bool pl = g_contacts.now != nullptr && player >= 0 && d >= leg && d < leg + 12 &&
          ((g_contacts.now[static_cast<std::size_t>(player)] >> (d < leg + 6 ? 0 : 1)) & 1) != 0;
      if (g_contacts.split && pl && !keyframe)
        model = &g_contacts.planted_legs[static_cast<std::size_t>(d)];
      const double b0 = bits;
      signed_cost(*model, r, zctx, act);
      if (g_contacts.now != nullptr && !keyframe && player >= 0 && d >= leg && d < leg + 12) {
        const int bd = band[static_cast<std::size_t>(player)];
        g_contacts.leg_bits[bd][pl ? 1 : 0] += bits - b0;
        g_contacts.leg_n[bd][pl ? 1 : 0] += 1.0 / 6.0;
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
    if (g_contacts.now != nullptr && !keyframe) {
      const auto slot = static_cast<std::size_t>(player);
      const int now = g_contacts.now[slot] & 3, before = g_contacts.before != nullptr ? g_contacts.before[slot] & 3 : 0;
      const double b0 = bits;
      for (int foot = 0; foot < 2; ++foot) {
        const int ctx = foot * 8 + ((before >> foot) & 1) * 4 + ((before >> (1 - foot)) & 1) * 2 + (foot == 1 ? (now & 1) : 0);
        bit(g_contacts.bit_ctx[static_cast<std::size_t>(ctx)], ((now >> foot) & 1) != 0);
      }
      g_contacts.bits += bits - b0;
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

std::uint32_t cost_bits(std::int64_t r) {  // FrameEncoder's partner estimate
  if (r == 0) return 1;
  const std::uint64_t m = static_cast<std::uint64_t>(r < 0 ? -r : r);
  return 3 + 2 * (static_cast<std::uint32_t>(std::bit_width(m)) - 1);
}

struct Game {
  SkeletonDef skeleton;
  std::vector<PoseFrame> frames;
};

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

Costs measure(const Game& g, int keyframe_interval) {
  const Quantizer quant(g.skeleton);
  const int dofs = quant.dof_count();
  const int kinds = kDof0 + dofs;
  Costs c;
  for (int d = 0, j = 0; j < static_cast<int>(g.skeleton.joints.size()); d += static_cast<int>(g.skeleton.joints[static_cast<std::size_t>(j)].dofs.size()), ++j)
    if (g.skeleton.joints[static_cast<std::size_t>(j)].name == "r_thigh") c.first_leg_dof = g_contacts.first_leg_dof = d;
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
    if (g_contacts.on) {
      g_contacts.now = &g_contacts.flags[t * kMaxPlayers];
      g_contacts.before = t > 0 ? &g_contacts.flags[(t - 1) * kMaxPlayers] : nullptr;
      if (key) g_contacts.reset();
    }
    CostIo io(c);
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
      detail::PartnerTable pt;  // FrameEncoder::choose_partners
      for (int d = 0; d < dofs; ++d) {
        const auto dd = static_cast<std::size_t>(d);
        std::uint64_t best = base_cost[dd] - base_cost[dd] / 20;
        for (int p = 0; p < d; ++p)
          for (std::size_t k = 0; k < 8; ++k) {
            const std::uint32_t cc = partner_cost[(dd * n + static_cast<std::size_t>(p)) * 8 + k];
            if (cc < best) {
              best = cc;
              pt.partner[dd] = static_cast<std::int8_t>(p);
              pt.coef2[dd] = detail::kPartnerCoef2[k];
            }
          }
      }
      if (g_no_partners) pt = detail::PartnerTable{};
      model.partners = pt;
      for (auto& x : partner_cost) x >>= 1;
      for (auto& x : base_cost) x >>= 1;
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
      if (g_study && since_key >= 2 && since_key % 2 == 0)
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

std::string dof_name(const SkeletonDef& s, int dof);

// Estimated bits (FrameEncoder's cost_bits) of each dof's raw residuals with
// no partner, the best single partner and the best pair of partners, each
// fixed over the whole game: what a second partner could gain.
void partner_study(const SkeletonDef& sk, const Costs& c) {
  const int dofs = sk.dof_count();
  const std::size_t stride = kMaxPlayers * static_cast<std::size_t>(dofs);
  const std::size_t rows = c.raw.size() / static_cast<std::size_t>(dofs);
  const auto at = [&](std::size_t row, int d) { return static_cast<std::int64_t>(c.raw[row * static_cast<std::size_t>(dofs) + static_cast<std::size_t>(d)]); };
  (void)stride;
  double tot0 = 0, tot1 = 0, tot2 = 0;
  std::printf("\npartner study (estimated bits per delta frame, all players)\n%-16s %8s %8s %-22s %8s %s\n", "dof", "none", "single",
              "", "pair", "");
  const double frames = double(rows) / kMaxPlayers;
  for (int d = 0; d < dofs; ++d) {
    double base = 0;
    for (std::size_t r = 0; r < rows; ++r) base += cost_bits(at(r, d));
    // Single partners, ranked.
    std::vector<std::tuple<double, int, int>> single;
    for (int p = 0; p < d; ++p)
      for (int k = 0; k < 8; ++k) {
        double s = 0;
        for (std::size_t r = 0; r < rows; ++r)
          s += cost_bits(at(r, d) - detail::PartnerTable::term(detail::kPartnerCoef2[static_cast<std::size_t>(k)], at(r, p)));
        single.emplace_back(s, p, k);
      }
    std::sort(single.begin(), single.end());
    double best1 = base;
    std::string best1_name = "-";
    if (!single.empty() && std::get<0>(single[0]) < base * 0.95) {
      best1 = std::get<0>(single[0]);
      best1_name = dof_name(sk, std::get<1>(single[0])) + "*" + std::to_string(detail::kPartnerCoef2[static_cast<std::size_t>(std::get<2>(single[0]))]) + "/2";
    }
    // Pairs among the 6 best distinct single partners.
    std::vector<int> cand;
    for (const auto& [s, p, k] : single)
      if (std::find(cand.begin(), cand.end(), p) == cand.end() && cand.size() < 6) cand.push_back(p);
    double best2 = best1;
    std::string best2_name = "-";
    for (std::size_t a = 0; a < cand.size(); ++a)
      for (std::size_t b = a + 1; b < cand.size(); ++b)
        for (int ka = 0; ka < 8; ++ka)
          for (int kb = 0; kb < 8; ++kb) {
            const int ca = detail::kPartnerCoef2[static_cast<std::size_t>(ka)], cb = detail::kPartnerCoef2[static_cast<std::size_t>(kb)];
            double s = 0;
            for (std::size_t r = 0; r < rows && s < best2; ++r)
              s += cost_bits(at(r, d) - detail::PartnerTable::term(1, ca * at(r, cand[a]) + cb * at(r, cand[b])));
            if (s < best2 * 0.97) {
              best2 = s;
              best2_name = dof_name(sk, cand[a]) + "*" + std::to_string(ca) + "/2+" + dof_name(sk, cand[b]) + "*" + std::to_string(cb) + "/2";
            }
          }
    tot0 += base, tot1 += best1, tot2 += best2;
    std::printf("%-16s %8.2f %8.2f %-22s %8.2f %s\n", dof_name(sk, d).c_str(), base / 8 / frames, best1 / 8 / frames,
                best1_name.c_str(), best2 / 8 / frames, best2_name.c_str());
  }
  std::printf("%-16s %8.2f %8.2f %-22s %8.2f\n", "total B/frame", tot0 / 8 / frames, tot1 / 8 / frames, "", tot2 / 8 / frames);
}

std::string dof_name(const SkeletonDef& s, int dof) {
  int d = 0;
  for (const auto& j : s.joints)
    for (char axis : j.dofs)
      if (d++ == dof) return j.name + "." + axis;
  return "?";
}

}  // namespace

int main(int argc, char** argv) {
  int keyframe_interval = 20;
  int trace_slot = -1, trace_from = 0, trace_to = 0;
  std::string trace_dofs, contacts_path;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--keyframe-interval" && i + 1 < argc) keyframe_interval = std::stoi(argv[++i]);
    else if (a == "--partner-study") g_study = true;
    else if (a == "--no-partners") g_no_partners = true;
    else if (a == "--contacts" && i + 1 < argc) contacts_path = argv[++i];
    else if (a == "--contacts-measure-only") g_contacts.split = false;
    else if (a == "--trace" && i + 4 < argc) {
      trace_slot = std::stoi(argv[++i]);
      trace_from = std::stoi(argv[++i]);
      trace_to = std::stoi(argv[++i]);
      trace_dofs = argv[++i];
    }
    else files.push_back(a);
  }
  if (files.empty() || files.size() > 2 || (!contacts_path.empty() && files.size() != 1)) {
    std::fprintf(stderr,
                 "usage: %s [--keyframe-interval F] [--no-partners] [--partner-study] [--trace SLOT FROM TO DOFS]\n"
                 "       [--contacts PATH [--contacts-measure-only]] FRAMES [FRAMES_B]\n",
                 argv[0]);
    return 2;
  }
  std::vector<Game> games(files.size());
  std::vector<Costs> costs;
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (!load(files[i], games[i])) {
      std::fprintf(stderr, "cannot read %s\n", files[i].c_str());
      return 1;
    }
    if (!contacts_path.empty()) {
      std::FILE* in = std::fopen(contacts_path.c_str(), "rb");
      std::uint64_t n = 0;
      if (in == nullptr || std::fread(&n, 8, 1, in) != 1 || n != games[i].frames.size()) {
        if (in != nullptr) std::fclose(in);
        std::fprintf(stderr, "cannot read %s, or not the frames' contacts\n", contacts_path.c_str());
        return 1;
      }
      g_contacts.flags.resize(n * kMaxPlayers);
      const bool ok = std::fread(g_contacts.flags.data(), 1, g_contacts.flags.size(), in) == g_contacts.flags.size();
      std::fclose(in);
      if (!ok) return 1;
      g_contacts.on = true;
    }
    costs.push_back(measure(games[i], keyframe_interval));
  }
  if (trace_slot >= 0) {  // quantized values of some dofs (comma-separated names) of one slot
    const Quantizer quant(games[0].skeleton);
    std::vector<int> ds;
    std::string rest = trace_dofs + ",";
    for (std::size_t at; (at = rest.find(',')) != std::string::npos; rest.erase(0, at + 1))
      for (int d = 0; d < quant.dof_count(); ++d)
        if (dof_name(games[0].skeleton, d) == rest.substr(0, at)) ds.push_back(d);
    for (std::size_t gi = 0; gi < games.size(); ++gi) {
      std::printf("%s frame sub speed", gi ? "B" : "A");
      for (int d : ds) std::printf(" %14s", dof_name(games[0].skeleton, d).c_str());
      std::printf("\n");
      const auto& fr = games[gi].frames;
      for (int t = std::max(1, trace_from); t <= trace_to && t < static_cast<int>(fr.size()); ++t) {
        const auto& p = fr[static_cast<std::size_t>(t)].players[static_cast<std::size_t>(trace_slot)];
        const auto& p0 = fr[static_cast<std::size_t>(t - 1)].players[static_cast<std::size_t>(trace_slot)];
        const QuantFrame q = quant.quantize(fr[static_cast<std::size_t>(t)]);
        std::printf("  %5d %d %5.2f", t, fr[static_cast<std::size_t>(t)].substep,
                    std::hypot(double(p.x) - p0.x, double(p.y) - p0.y) * 20.0);
        for (int d : ds)
          std::printf(" %7.2f (%4d)", p.angles[static_cast<std::size_t>(d)],
                      q.players[static_cast<std::size_t>(trace_slot)].angles[static_cast<std::size_t>(d)]);
        std::printf("\n");
      }
    }
    return 0;
  }
  if (g_study) {
    for (std::size_t i = 0; i < costs.size(); ++i) partner_study(games[i].skeleton, costs[i]);
    return 0;
  }
  const bool two = costs.size() == 2;
  const SkeletonDef& sk = games[0].skeleton;
  const int dofs = sk.dof_count();
  for (std::size_t i = 0; i < files.size(); ++i)
    std::printf("%s: %s, %zu frames, %zu keyframes (%.1f B each), %zu deltas\n", two ? (i ? "B" : "A") : "file",
                files[i].c_str(), games[i].frames.size(), costs[i].keys, costs[i].key_bits / 8 / double(costs[i].keys),
                costs[i].deltas);
  const auto per_delta = [](const Costs& c, double bits) { return bits / 8.0 / double(c.deltas); };
  double total[2] = {0, 0};
  std::printf("\ndelta bytes per frame by value (flicker: a->b->a, zigzag: the acceleration changing sign, both >= 4 steps; per 1000 player-frames)\n");
  std::printf("%-18s %9s %6s %6s %8s %8s", "value", "A B/fr", "even", "odd", "A flick", "A zigzag");
  if (two) std::printf(" %9s %6s %6s %8s %8s %9s", "B B/fr", "even", "odd", "B flick", "B zigzag", "B-A B/fr");
  std::printf("\n");
  const int kinds = kDof0 + dofs;
  for (int k = 0; k < kinds; ++k) {
    std::string name = k == kBall ? "ball" : k == kMeta ? "meta" : k == kHeading ? "heading"
                       : k < kHeading ? std::string("root.") + "xyz"[k - kRoot] : dof_name(sk, k - kDof0);
    std::printf("%-18s", name.c_str());
    for (std::size_t i = 0; i < costs.size(); ++i) {
      const Costs& c = costs[i];
      const double b = per_delta(c, c.delta_bits[static_cast<std::size_t>(k)]);
      total[i] += b;
      const double odd = c.odd_bits[static_cast<std::size_t>(k)] / 8.0 / double(c.odd_deltas);
      const double even = (c.delta_bits[static_cast<std::size_t>(k)] - c.odd_bits[static_cast<std::size_t>(k)]) / 8.0 /
                          double(c.deltas - c.odd_deltas);
      std::printf(" %9.2f %6.2f %6.2f", b, even, odd);
      if (k >= kDof0) {
        const double pf = double(c.deltas) * kMaxPlayers / 1000.0;
        std::printf(" %8.2f %8.1f", double(c.flicker[static_cast<std::size_t>(k - kDof0)]) / pf,
                    double(c.zigzag[static_cast<std::size_t>(k - kDof0)]) / pf);
      } else {
        std::printf(" %8s %8s", "", "");
      }
    }
    if (two)
      std::printf(" %+9.2f", per_delta(costs[1], costs[1].delta_bits[static_cast<std::size_t>(k)]) -
                                 per_delta(costs[0], costs[0].delta_bits[static_cast<std::size_t>(k)]));
    std::printf("\n");
  }
  if (g_contacts.on)
    std::printf("(--contacts: meta holds the contact bits, %.2f B a delta frame; the planted legs' dofs are coded apart)\n",
                g_contacts.bits / 8.0 / double(costs[0].deltas));
  if (g_contacts.on) {
    std::printf("legs by speed band, swinging and planted: leg-frames, bits a leg-frame, B a delta frame\n");
    for (int b = 0; b < kBands; ++b) {
      const auto& n = g_contacts.leg_n[b];
      const auto& bits = g_contacts.leg_bits[b];
      std::printf("%-9s swinging %7.0f %6.2f %6.2f   planted %7.0f %6.2f %6.2f\n", kBandName[b], n[0],
                  bits[0] / std::max(1.0, n[0]), bits[0] / 8.0 / double(costs[0].deltas), n[1],
                  bits[1] / std::max(1.0, n[1]), bits[1] / 8.0 / double(costs[0].deltas));
    }
  }
  std::printf("%-18s %9.2f %6s %6s %8s %8s", "total (body)", total[0], "", "", "", "");
  if (two) std::printf(" %9.2f %6s %6s %8s %8s %+9.2f", total[1], "", "", "", "", total[1] - total[0]);
  std::printf("\n");

  std::printf("\nsquared second difference at cycle frames (substep 0) / half-way frames (substep 1)\n");
  for (std::size_t i = 0; i < costs.size(); ++i) {
    const Costs& c = costs[i];
    std::printf("%s root.x %.2f root.y %.2f;", two ? (i ? "B" : "A") : "", c.root_acc2[0][0] / c.root_acc2[0][1], c.root_acc2[1][0] / c.root_acc2[1][1]);
    for (int d = 0; d < dofs; ++d) {
      const auto& a2 = c.acc2[static_cast<std::size_t>(d)];
      if (a2[1] > 0 && (a2[0] + a2[1]) / double(c.deltas) > 5) std::printf(" %s %.2f", dof_name(sk, d).c_str(), a2[0] / a2[1]);
    }
    std::printf("\n");
  }
  std::printf("\ndof residuals of deltas by magnitude (grid steps): count per delta frame, bytes per delta frame\n");
  const char* cls_name[7] = {"0", "1", "2", "3-4", "5-8", "9-16", "17+"};
  for (int k = 0; k < 7; ++k) {
    std::printf("%-6s", cls_name[k]);
    for (std::size_t i = 0; i < costs.size(); ++i)
      std::printf("   %s %8.1f %8.2f B", two ? (i ? "B" : "A") : "", costs[i].mag_count[static_cast<std::size_t>(k)] / double(costs[i].deltas),
                  costs[i].mag_bits[static_cast<std::size_t>(k)] / 8.0 / double(costs[i].deltas));
    std::printf("\n");
  }

  std::printf("\ndof values of deltas by their change since the last frame (deg): count per delta frame, bytes per delta frame\n");
  const char* step_name[5] = {"0-9", "10-19", "20-29", "30-39", "40+"};
  for (int k = 0; k < 5; ++k) {
    std::printf("%-6s", step_name[k]);
    for (std::size_t i = 0; i < costs.size(); ++i)
      std::printf("   %s %8.1f %8.2f B (legs %6.1f %7.2f B)", two ? (i ? "B" : "A") : "",
                  costs[i].step_count[static_cast<std::size_t>(k)] / double(costs[i].deltas),
                  costs[i].step_bits[static_cast<std::size_t>(k)] / 8.0 / double(costs[i].deltas),
                  costs[i].leg_step_count[static_cast<std::size_t>(k)] / double(costs[i].deltas),
                  costs[i].leg_step_bits[static_cast<std::size_t>(k)] / 8.0 / double(costs[i].deltas));
    std::printf("\n");
  }

  // By speed band: bits per player-frame of groups of values.
  struct Group {
    const char* name;
    int from, to;  // kinds [from, to)
  };
  auto joint_range = [&](const char* first, const char* last_excl) {
    int d = 0, a = -1, b = dofs;
    for (const auto& j : sk.joints) {
      if (j.name == first) a = d;
      if (last_excl && j.name == last_excl) b = d;
      d += static_cast<int>(j.dofs.size());
    }
    return std::pair<int, int>{kDof0 + a, kDof0 + b};
  };
  const auto pelvis = joint_range("pelvis", "torso"), spine = joint_range("torso", "r_upper_arm"),
             arms = joint_range("r_upper_arm", "r_thigh"), legs = joint_range("r_thigh", nullptr);
  const Group groups[] = {{"root+heading", kRoot, kDof0},       {"pelvis", pelvis.first, pelvis.second},
                          {"torso/neck/head", spine.first, spine.second}, {"arms", arms.first, arms.second},
                          {"legs", legs.first, legs.second}};
  for (std::size_t i = 0; i < costs.size(); ++i) {
    const Costs& c = costs[i];
    std::printf("\n%s: bits per player-frame by speed band (share of player-frames)\n", two ? (i ? "B" : "A") : "file");
    std::printf("%-16s", "group");
    for (int b = 0; b < kBands; ++b) std::printf(" %14s", kBandName[b]);
    std::printf("\n%-16s", "share");
    double all = 0;
    for (double x : c.band_player_frames) all += x;
    for (int b = 0; b < kBands; ++b) std::printf(" %13.1f%%", 100.0 * c.band_player_frames[static_cast<std::size_t>(b)] / all);
    std::printf("\n");
    for (const auto& gr : groups) {
      std::printf("%-16s", gr.name);
      for (int b = 0; b < kBands; ++b) {
        double s = 0;
        for (int k = gr.from; k < gr.to; ++k) s += c.band_bits[static_cast<std::size_t>(k)][static_cast<std::size_t>(b)];
        const double pf = c.band_player_frames[static_cast<std::size_t>(b)];
        std::printf(" %14.2f", pf > 0 ? s / pf : 0.0);
      }
      std::printf("\n");
    }
    std::printf("%-16s", "B/frame share");
    for (int b = 0; b < kBands; ++b) {
      double s = 0;
      for (int k = kRoot; k < kDof0 + dofs; ++k) s += c.band_bits[static_cast<std::size_t>(k)][static_cast<std::size_t>(b)];
      std::printf(" %14.2f", s / 8.0 / double(c.deltas));
    }
    std::printf("\n");
  }
  return 0;
}

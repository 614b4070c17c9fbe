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
//   proto_pose_stream_stats [--keyframe-interval F] FRAMES [FRAMES_B]
// With two files (same game, two animations) the figures are side by side
// with B - A.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "proto/codec_model.hpp"
#include "proto/hello.hpp"
#include "proto/pose_frame.hpp"
#include "proto/quantizer.hpp"

using namespace mc;
using namespace mc::proto;

namespace {

constexpr int kBands = 5;
const char* kBandName[kBands] = {"<0.3 m/s", "0.3-2", "2-4", "4-6", "6+"};
int band_of(double speed) { return speed < 0.3 ? 0 : speed < 2 ? 1 : speed < 4 ? 2 : speed < 6 ? 3 : 4; }

// Value kinds: 0 ball, 1 meta, 2..4 root x y z, 5 heading, 6.. dofs.
constexpr int kBall = 0, kMeta = 1, kRoot = 2, kHeading = 5, kDof0 = 6;

struct Costs {
  std::vector<double> delta_bits;                       // [kind]
  std::vector<std::array<double, kBands>> band_bits;    // [kind][band]
  std::array<double, kBands> band_player_frames{};      // player-deltas per band
  std::vector<std::size_t> flicker;                     // [dof] a -> b -> a
  std::vector<std::size_t> moves;                       // [dof] frames where the index changed
  std::vector<std::size_t> nonzero;                     // [dof] non-zero coded residuals
  double key_bits = 0;
  std::size_t deltas = 0, keys = 0;
};

struct CostIo {
  explicit CostIo(Costs& costs) : c(costs) {}
  Costs& c;
  bool keyframe = false;
  int player = -1;   // -1: the ball
  int index = 0;     // value index within the player (0..2 root, 3.. dofs)
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
      if (player >= 0) c.band_bits[static_cast<std::size_t>(kind)][static_cast<std::size_t>(band[static_cast<std::size_t>(player)])] += bits;
    }
    bits = 0;
  }
  bool value(SignedModel& m, std::int32_t& v, std::int32_t pred, std::int32_t, std::int32_t, int zctx, int act,
             std::int32_t& r) {
    r = v - pred;
    signed_cost(m, r, zctx, act);
    if (player < 0) {
      book(kBall);
    } else if (index < 3) {
      book(kRoot + index);
    } else {
      if (!keyframe && r != 0) ++c.nonzero[static_cast<std::size_t>(index - 3)];
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
  c.delta_bits.assign(static_cast<std::size_t>(kinds), 0);
  c.band_bits.assign(static_cast<std::size_t>(kinds), {});
  c.flicker.assign(static_cast<std::size_t>(dofs), 0);
  c.moves.assign(static_cast<std::size_t>(dofs), 0);
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
    CostIo io(c);
    io.keyframe = key;
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
      detail::walk_delta(io, model, quant, qf, f.substep);
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
      }
  return c;
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
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--keyframe-interval" && i + 1 < argc) keyframe_interval = std::stoi(argv[++i]);
    else files.push_back(a);
  }
  if (files.empty() || files.size() > 2) {
    std::fprintf(stderr, "usage: %s [--keyframe-interval F] FRAMES [FRAMES_B]\n", argv[0]);
    return 2;
  }
  std::vector<Game> games(files.size());
  std::vector<Costs> costs;
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (!load(files[i], games[i])) {
      std::fprintf(stderr, "cannot read %s\n", files[i].c_str());
      return 1;
    }
    costs.push_back(measure(games[i], keyframe_interval));
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
  std::printf("\ndelta bytes per frame by value (flicker: a->b->a per 1000 player-frames; moves: changes per 1000)\n");
  std::printf("%-18s %9s %8s %8s", "value", "A B/fr", "A flick", "A moves");
  if (two) std::printf(" %9s %8s %8s %9s", "B B/fr", "B flick", "B moves", "B-A B/fr");
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
      std::printf(" %9.2f", b);
      if (k >= kDof0) {
        const double pf = double(c.deltas) * kMaxPlayers / 1000.0;
        std::printf(" %8.2f %8.1f", double(c.flicker[static_cast<std::size_t>(k - kDof0)]) / pf,
                    double(c.moves[static_cast<std::size_t>(k - kDof0)]) / pf);
      } else {
        std::printf(" %8s %8s", "", "");
      }
    }
    if (two)
      std::printf(" %+9.2f", per_delta(costs[1], costs[1].delta_bits[static_cast<std::size_t>(k)]) -
                                 per_delta(costs[0], costs[0].delta_bits[static_cast<std::size_t>(k)]));
    std::printf("\n");
  }
  std::printf("%-18s %9.2f", "total (body)", total[0]);
  if (two) std::printf(" %8s %8s %9.2f %8s %8s %+9.2f", "", "", total[1], "", "", total[1] - total[0]);
  std::printf("\n");

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

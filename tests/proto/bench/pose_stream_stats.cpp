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
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "proto/codec_model.hpp"
#include "proto/quantizer.hpp"
#include "tests/proto/bench/stream_costs.hpp"

using namespace mc;
using namespace mc::proto;
using namespace mc::proto::stats;

namespace {

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
  Study study;
  int keyframe_interval = 20;
  int trace_slot = -1, trace_from = 0, trace_to = 0;
  std::string trace_dofs, contacts_path;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--keyframe-interval" && i + 1 < argc) keyframe_interval = std::stoi(argv[++i]);
    else if (a == "--partner-study") study.partner_study = true;
    else if (a == "--no-partners") study.no_partners = true;
    else if (a == "--contacts" && i + 1 < argc) contacts_path = argv[++i];
    else if (a == "--contacts-measure-only") study.contacts.split = false;
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
      study.contacts.flags.resize(n * kMaxPlayers);
      const bool ok = std::fread(study.contacts.flags.data(), 1, study.contacts.flags.size(), in) == study.contacts.flags.size();
      std::fclose(in);
      if (!ok) return 1;
      study.contacts.on = true;
    }
    costs.push_back(measure(games[i], keyframe_interval, study));
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
  if (study.partner_study) {
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
  if (study.contacts.on)
    std::printf("(--contacts: meta holds the contact bits, %.2f B a delta frame; the planted legs' dofs are coded apart)\n",
                study.contacts.bits / 8.0 / double(costs[0].deltas));
  if (study.contacts.on) {
    std::printf("legs by speed band, swinging and planted: leg-frames, bits a leg-frame, B a delta frame\n");
    for (int b = 0; b < kBands; ++b) {
      const auto& n = study.contacts.leg_n[b];
      const auto& bits = study.contacts.leg_bits[b];
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

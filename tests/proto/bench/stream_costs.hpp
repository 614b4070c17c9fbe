// The cost-counting walk behind proto_pose_stream_stats (a measurement,
// not a test): frames saved by `proto_pose_stream_bench --save-frames`
// walked through the codec's own walk (codec_model.hpp) with an Io that
// books the ideal cost of every range-coded decision by value kind, speed
// band and dof, plus the motion figures (flicker, zigzag, moves). The CLI
// and its report are pose_stream_stats.cpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "proto/codec_model.hpp"
#include "proto/hello.hpp"
#include "proto/pose_frame.hpp"

namespace mc::proto::stats {

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
};
inline constexpr int kBands = 5;
inline const char* const kBandName[kBands] = {"<0.3 m/s", "0.3-2", "2-4", "4-6", "6+"};
inline int band_of(double speed) { return speed < 0.3 ? 0 : speed < 2 ? 1 : speed < 4 ? 2 : speed < 6 ? 3 : 4; }

// Value kinds: 0 ball, 1 meta, 2..4 root x y z, 5 heading, 6.. dofs.
inline constexpr int kBall = 0, kMeta = 1, kRoot = 2, kHeading = 5, kDof0 = 6;


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

// What the walk measures besides the codec's own coding.
struct Study {
  bool partner_study = false;  // keep raw residuals for the partner study
  bool no_partners = false;    // code without the partner table
  ContactStudy contacts;       // --contacts
};

struct Game {
  SkeletonDef skeleton;
  std::vector<PoseFrame> frames;
};

// Reads a `--save-frames` file: the hello's skeleton and the frames.
bool load(const std::string& path, Game& g);
// Walks every frame (a keyframe every keyframe_interval) and books its cost.
Costs measure(const Game& g, int keyframe_interval, Study& study);
// FrameEncoder's estimate of a residual's cost, for the partner study.
std::uint32_t cost_bits(std::int64_t r);

}  // namespace mc::proto::stats

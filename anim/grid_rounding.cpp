#include "anim/grid_rounding.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "anim/body_frame.hpp"
#include "anim/ground_contact.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/portable_math.hpp"
#include "anim/sincos_deg.hpp"

namespace mc::anim {
namespace {

// A sole higher than this above the grass is not on it in this frame, nor
// (rounded) in the stream: 3 cm is the clients' "on the grass", and the
// stream's rounding may lower a sole by 2 cm. A foot in the air that
// travels is kept 5 cm up (swing_clearance.hpp), so this leaves out most
// swings: rounding every leg whose ankle is below 25 cm instead took a
// third more instructions for the same figures.
constexpr float kMayBeGroundedM = 0.05f;

// A dof's grid point further from its value must buy this much of the
// ankle's squared error (3 mm, squared): each one costs the stream bits.
// Measured with every leg below 25 cm rounded, the recording of a full game
// grew 1.1 % choosing freely and 0.9 % with this price, for the same
// figures; 1 mm saved nothing, 5.5 mm half as much growth but gave back a
// tenth of the gain.
constexpr float kFarPointCost = 1e-5f;

// A dof's two grid points either side of its value (the same point twice
// at a limit), and the value's step to each (rad).
struct GridPair {
  std::int32_t q[2] = {0, 0};
  float step_rad[2] = {0, 0};
};

// The integer below v, and the nearest (halves away from zero), without a
// call into the maths library (this runs for most players on every frame).
std::int32_t floor_int(float v) {
  const auto i = static_cast<std::int32_t>(v);
  return v < static_cast<float>(i) ? i - 1 : i;
}
std::int32_t round_int(float v) { return static_cast<std::int32_t>(v + (v < 0 ? -0.5f : 0.5f)); }

GridPair pair_of(const proto::DofGrid& g, float deg) {
  constexpr float kPerStep = 1.0f / static_cast<float>(proto::kAngleStepMilliDeg);
  const float lo = static_cast<float>(g.lo_mdeg), hi = static_cast<float>(g.hi_mdeg);
  const std::int32_t below = floor_int((deg * 1000.0f - lo) * kPerStep);
  GridPair p;
  for (int k = 0; k < 2; ++k) {
    p.q[k] = std::clamp(below + k, 0, g.steps - 1);
    const float mdeg = std::min(lo + static_cast<float>(p.q[k] * proto::kAngleStepMilliDeg), hi);
    p.step_rad[k] = (0.001f * mdeg - deg) * kDeg;
  }
  return p;
}

glm::vec3 col(const glm::mat4& m, int c) { return glm::vec3(m[c]); }

// Of 16 choices, one of two grid points for each of 4 dofs, the one whose
// moves of the ankle (moves[dof][point]) added to `base` leave it nearest,
// counting each point's cost (cost[dof][point]) as squared error.
// As pairs: |A + B|^2 = |A|^2 + |B|^2 + 2 A.B, with A the base and the
// first two dofs' moves, B the last two's (half the work of the 16 sums).
void best_of_16(const glm::vec3& base, const glm::vec3 (&moves)[4][2], const float (&cost)[4][2], int pick[4]) {
  glm::vec3 a[4], b[4];
  float aa[4], bb[4];
  for (int k = 0; k < 4; ++k) {
    a[k] = base + moves[0][k >> 1] + moves[1][k & 1];
    b[k] = moves[2][k >> 1] + moves[3][k & 1];
    aa[k] = glm::dot(a[k], a[k]) + cost[0][k >> 1] + cost[1][k & 1];
    bb[k] = glm::dot(b[k], b[k]) + cost[2][k >> 1] + cost[3][k & 1];
  }
  float best = INFINITY;
  int best_a = 0, best_b = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const float d = aa[i] + bb[j] + 2.0f * glm::dot(a[i], b[j]);
      if (d < best) {
        best = d;
        best_a = i;
        best_b = j;
      }
    }
  pick[0] = best_a >> 1, pick[1] = best_a & 1, pick[2] = best_b >> 1, pick[3] = best_b & 1;
}

// One leg: of its hip's and knee's grid pairs, the choice whose first-order
// move of the ankle, added to `fixed`, is shortest.
void round_leg(const proto::Quantizer& grid, const glm::mat4* m, int thigh, int hip_dof, const glm::vec3& fixed,
               float* angles) {
  const glm::mat4& mt = m[thigh];
  const glm::vec3 hip = col(mt, 3), knee = col(m[thigh + 1], 3), ankle = col(m[thigh + 2], 3);
  // The hip's dofs are z, x, y: z turns about the pelvis's z, x about the
  // thigh's x before its y turn, y about the thigh's own y; the knee about
  // its z (the thigh's).
  float s2 = 0, c2 = 1;
  sincos_deg(angles[hip_dof + 2], s2, c2);
  const glm::vec3 axes[4] = {col(m[kPelvis], 2), c2 * col(mt, 0) + s2 * col(mt, 2), col(mt, 1), col(mt, 2)};
  GridPair pairs[4];
  glm::vec3 moves[4][2];
  float cost[4][2];
  for (int j = 0; j < 4; ++j) {
    const glm::vec3 lever = glm::cross(axes[j], ankle - (j < 3 ? hip : knee));
    pairs[j] = pair_of(grid.grid(hip_dof + j), angles[hip_dof + j]);
    for (int k = 0; k < 2; ++k) moves[j][k] = pairs[j].step_rad[k] * lever;
    const int far = std::fabs(pairs[j].step_rad[0]) > std::fabs(pairs[j].step_rad[1]) ? 0 : 1;
    cost[j][far] = kFarPointCost;
    cost[j][1 - far] = 0;
  }
  int pick[4] = {0, 0, 0, 0};
  best_of_16(fixed, moves, cost, pick);
  for (int j = 0; j < 4; ++j) angles[hip_dof + j] = grid.angle_value(hip_dof + j, pairs[j].q[pick[j]]);
}

}  // namespace

void round_legs_to_grid(const proto::Quantizer& grid, const SkeletonDef& skeleton, const glm::mat4* m, PlayerPose& pose,
                        int kicking_leg) {
  // Only a foot that may be on the grass needs its ankle kept: the others
  // are left for the encoder to round.
  const glm::mat4& mp = m[kPelvis];
  const float to_grass = pose.z - mp[3].y;  // `m`'s heights -> above the grass
  bool low[2];
  for (int i = 0; i < 2; ++i) {
    const auto foot = static_cast<std::size_t>(i == 0 ? kRFoot : kLFoot);
    low[i] = i == kicking_leg || segment_lowest_ms(skeleton.joints[foot].segment, m[foot]) + to_grass < kMayBeGroundedM;
  }
  if (!low[0] && !low[1]) return;
  // A value that is not a number (never made by the animator) is left to
  // the encoder, which codes it as 0: the float-to-integer steps below
  // have no answer for it.
  float sum = pose.x + pose.y + pose.z + pose.heading;
  for (int d : {dof::kPelvis, dof::kPelvis + 1, dof::kPelvis + 2, dof::kRHip, dof::kRHip + 1, dof::kRHip + 2,
                dof::kRKnee, dof::kLHip, dof::kLHip + 1, dof::kLHip + 2, dof::kLKnee})
    sum += pose.angles[static_cast<std::size_t>(d)];
  if (!std::isfinite(sum)) return;
  // The root, the heading and the pelvis to their nearest grid points, and
  // what that does to a body-space point (X forward, Z right): the root's
  // step turned into the body, the heading's (rad) turning it about the
  // vertical, and each of the pelvis's dofs (y, z, x: y about the body's
  // up, z about the pelvis's z before its x turn, x about its own x)
  // turning it about the pelvis. (Choosing these for both ankles as well,
  // from their 16 pairs, halved the largest error left in the test's
  // poses but moved no figure of the full games.)
  const float x = pose.x, y = pose.y, z = pose.z, heading = pose.heading;
  auto on_grid = [](float metres) {
    const std::int32_t q = std::clamp(round_int(metres * 100.0f), proto::kPositionMin, proto::kPositionMax);
    return static_cast<float>(q * proto::kPositionStepM);
  };
  pose.x = on_grid(x);
  pose.y = on_grid(y);
  pose.z = on_grid(z);
  const std::int32_t hq = round_int(heading * static_cast<float>(1.0 / proto::kHeadingStepDeg));
  pose.heading = proto::Quantizer::heading_value((hq % proto::kHeadingSteps + proto::kHeadingSteps) % proto::kHeadingSteps);
  float dh_deg = pose.heading - heading;
  if (dh_deg > 180.0f) dh_deg -= 360.0f;
  else if (dh_deg < -180.0f) dh_deg += 360.0f;
  const float dh = dh_deg * kDeg;
  float s = 0, c = 1;
  sincos_deg(heading, s, c);
  const float dx = pose.x - x, dy = pose.y - y;
  const glm::vec3 root_step(dx * c + dy * s, pose.z - z, -dx * s + dy * c);
  float* a = pose.angles.data();
  float sx = 0, cx = 1;
  sincos_deg(a[dof::kPelvis + 2], sx, cx);
  const glm::vec3 pelvis_axes[3] = {glm::vec3(0, 1, 0), cx * col(mp, 2) + sx * col(mp, 1), col(mp, 0)};
  float pelvis_step[3];
  for (int j = 0; j < 3; ++j) {
    const GridPair p = pair_of(grid.grid(dof::kPelvis + j), a[dof::kPelvis + j]);
    const int near = std::fabs(p.step_rad[0]) <= std::fabs(p.step_rad[1]) ? 0 : 1;
    pelvis_step[j] = p.step_rad[near];
    a[dof::kPelvis + j] = grid.angle_value(dof::kPelvis + j, p.q[near]);
  }
  // Then each low leg's hip and knee make up what those moved its ankle.
  for (int i = 0; i < 2; ++i) {
    if (!low[i]) continue;
    const int thigh = i == 0 ? kRThigh : kLThigh;
    const glm::vec3 ankle = col(m[thigh + 2], 3);
    glm::vec3 fixed = root_step + dh * glm::vec3(-ankle.z, 0, ankle.x);
    for (int j = 0; j < 3; ++j) fixed += pelvis_step[j] * glm::cross(pelvis_axes[j], ankle - col(mp, 3));
    round_leg(grid, m, thigh, i == 0 ? dof::kRHip : dof::kLHip, fixed, a);
  }
}

}  // namespace mc::anim

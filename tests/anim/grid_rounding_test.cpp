#include "anim/grid_rounding.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "anim/body_frame.hpp"
#include "anim/ground_contact.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/local_to_model_job.hpp"
#include "proto/quantizer.hpp"

namespace mc::anim {
namespace {

// The joints of `p` in body space.
std::vector<glm::mat4> posed(const PlayerPose& p) {
  std::vector<glm::mat4> m(human_skeleton().joints.size());
  LocalToModelJob fk{&human_skeleton(), std::span<const float>(p.angles.data(), dof::kCount), glm::vec3(0, p.z, 0), m};
  EXPECT_TRUE(fk.Run());
  return m;
}

// A foot's ankle on the field (x, y, height), as the clients place it.
glm::vec3 field_ankle(const PlayerPose& p, int foot) {
  const glm::vec3 b(posed(p)[static_cast<std::size_t>(foot)][3]);
  const BodyFrame body(p.x, p.y, p.heading);
  glm::vec3 f(0, 0, b.y);
  body.to_field(b.x, b.z, f.x, f.y);
  return f;
}

// What the stream carries of `p`: every value rounded to the grid.
PlayerPose carried(const proto::Quantizer& grid, const PlayerPose& p) {
  PoseFrame in, out;
  in.players[0] = p;
  grid.dequantize(grid.quantize(in), out);
  return out.players[0];
}

// A foot whose sole is low enough to be on the grass, rounded or not.
float sole(const PlayerPose& p, int foot) {
  return segment_lowest_ms(human_skeleton().joints[static_cast<std::size_t>(foot)].segment,
                           posed(p)[static_cast<std::size_t>(foot)]);
}
bool low(const PlayerPose& p, int foot) { return sole(p, foot) < 0.05f; }

// Running poses: the pelvis, the hips and the knees anywhere a stride takes
// them, the root anywhere on the field facing anywhere, and at a height
// that puts the lower sole between 1 cm under the grass and 8 cm over it.
std::vector<PlayerPose> running_poses(int n) {
  std::mt19937 rng(23);
  auto u = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
  std::vector<PlayerPose> poses;
  for (int i = 0; i < n; ++i) {
    PlayerPose p;
    p.x = u(-52, 52);
    p.y = u(-34, 34);
    p.heading = u(-180, 180);
    for (int k = 0; k < 3; ++k) p.angles[static_cast<std::size_t>(dof::kPelvis + k)] = u(-12, 12);
    for (int hip : {dof::kRHip, dof::kLHip}) {
      p.angles[static_cast<std::size_t>(hip)] = u(-30, 70);
      p.angles[static_cast<std::size_t>(hip + 1)] = u(-10, 10);
      p.angles[static_cast<std::size_t>(hip + 2)] = u(-15, 15);
      p.angles[static_cast<std::size_t>(hip + 3)] = u(-110, -2);
      p.angles[static_cast<std::size_t>(hip + 4)] = u(-40, 20);
    }
    p.z = 1.0f;
    const float lowest = std::min(sole(p, kRFoot), sole(p, kLFoot));
    p.z += u(-0.01f, 0.08f) - lowest;
    poses.push_back(p);
  }
  return poses;
}

// A foot whose ankle is low enough for its sole to be on the grass.

TEST(GridRounding, LeavesTheLowLegsOnTheGridWithinAStepOfTheirValues) {
  const proto::Quantizer grid(human_skeleton());
  int rounded = 0, left = 0;
  for (const PlayerPose& p : running_poses(300)) {
    PlayerPose r = p;
    const std::vector<glm::mat4> m = posed(p);
    round_legs_to_grid(grid, human_skeleton(), m.data(), r);
    const PlayerPose c = carried(grid, r);
    const bool low_leg[2] = {low(p, kRFoot), low(p, kLFoot)};
    if (!low_leg[0] && !low_leg[1]) {
      // No foot near the grass: all is left for the encoder.
      ++left;
      EXPECT_EQ(r.x, p.x);
      EXPECT_EQ(r.heading, p.heading);
      EXPECT_EQ(r.angles, p.angles);
      continue;
    }
    ++rounded;
    // On the grid: the encoder's rounding is exact for what was rounded.
    EXPECT_EQ(c.x, r.x);
    EXPECT_EQ(c.y, r.y);
    EXPECT_EQ(c.z, r.z);
    EXPECT_EQ(c.heading, r.heading);
    std::vector<int> dofs = {dof::kPelvis, dof::kPelvis + 1, dof::kPelvis + 2};
    for (int leg = 0; leg < 2; ++leg) {
      const int hip = leg == 0 ? dof::kRHip : dof::kLHip;
      for (int d = hip; d <= hip + 3; ++d) {
        if (low_leg[leg]) dofs.push_back(d);
        else EXPECT_EQ(r.angles[static_cast<std::size_t>(d)], p.angles[static_cast<std::size_t>(d)]) << "dof " << d;
      }
    }
    for (int d : dofs) {
      const auto k = static_cast<std::size_t>(d);
      EXPECT_EQ(c.angles[k], r.angles[k]) << "dof " << d;
      EXPECT_LE(std::fabs(r.angles[k] - p.angles[k]), proto::kAngleStepDeg + 1e-4) << "dof " << d;
    }
    // The root and the heading to their nearest grid points.
    EXPECT_LE(std::fabs(r.x - p.x), 0.005f + 1e-5f);
    EXPECT_LE(std::fabs(r.z - p.z), 0.005f + 1e-5f);
    EXPECT_LE(std::fabs(delta_deg(r.heading, p.heading)), 0.5f * proto::kHeadingStepDeg + 1e-4f);
    // The rest is left for the encoder.
    EXPECT_EQ(r.angles[static_cast<std::size_t>(dof::kRAnkle)], p.angles[static_cast<std::size_t>(dof::kRAnkle)]);
  }
  // The poses have both kinds.
  EXPECT_GT(rounded, 100);
  EXPECT_GT(left, 10);
}

TEST(GridRounding, KeepsTheLowAnklesNearerThanRoundingEachValueOnItsOwn) {
  const proto::Quantizer grid(human_skeleton());
  double chosen_sum = 0, nearest_sum = 0, chosen_max = 0, nearest_max = 0;
  int worse = 0, n = 0;
  for (const PlayerPose& p : running_poses(800)) {
    PlayerPose r = p;
    const std::vector<glm::mat4> m = posed(p);
    round_legs_to_grid(grid, human_skeleton(), m.data(), r);
    const PlayerPose chosen = carried(grid, r), nearest = carried(grid, p);
    for (int foot : {kRFoot, kLFoot}) {
      if (!low(p, foot)) continue;
      const glm::vec3 want = field_ankle(p, foot);
      const double e_chosen = glm::length(field_ankle(chosen, foot) - want);
      const double e_nearest = glm::length(field_ankle(nearest, foot) - want);
      chosen_sum += e_chosen;
      nearest_sum += e_nearest;
      chosen_max = std::max(chosen_max, e_chosen);
      nearest_max = std::max(nearest_max, e_nearest);
      if (e_chosen > e_nearest + 1e-4) ++worse;
      ++n;
    }
  }
  ASSERT_GT(n, 300);
  const double chosen_mean = chosen_sum / n, nearest_mean = nearest_sum / n;
  std::printf("low ankles' error: chosen mean %.2f mm max %.2f mm; nearest mean %.2f mm max %.2f mm; worse %d of %d\n",
              1000 * chosen_mean, 1000 * chosen_max, 1000 * nearest_mean, 1000 * nearest_max, worse, n);
  // Rounded each on its own, the values move an ankle by about a centimetre.
  EXPECT_GT(nearest_mean, 0.006);
  // Chosen, by about half of that (a far grid point must buy 3 mm), and
  // never by more than rounded on their own (that is one of the choices).
  EXPECT_LT(chosen_mean, 0.55 * nearest_mean);
  EXPECT_LT(chosen_max, 0.7 * nearest_max);
  EXPECT_EQ(worse, 0);
}

TEST(GridRounding, LeavesAPoseWithANonNumberToTheEncoder) {
  const proto::Quantizer grid(human_skeleton());
  PlayerPose p = running_poses(1)[0];
  const std::vector<glm::mat4> m = posed(p);
  ASSERT_TRUE(low(p, kRFoot) || low(p, kLFoot));
  for (int which = 0; which < 3; ++which) {
    PlayerPose bad = p;
    float& v = which == 0 ? bad.x : which == 1 ? bad.heading : bad.angles[static_cast<std::size_t>(dof::kRKnee)];
    v = std::nanf("");
    PlayerPose r = bad;
    round_legs_to_grid(grid, human_skeleton(), m.data(), r);
    const float before[4] = {bad.x, bad.y, bad.z, bad.heading}, after[4] = {r.x, r.y, r.z, r.heading};
    EXPECT_EQ(std::memcmp(before, after, sizeof before), 0) << "the root left as it was, case " << which;
    EXPECT_EQ(std::memcmp(bad.angles.data(), r.angles.data(), sizeof r.angles), 0) << "the angles too, case " << which;
  }
}

}  // namespace
}  // namespace mc::anim

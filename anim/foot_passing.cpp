#include "anim/foot_passing.hpp"

#include <cmath>
#include <initializer_list>

#include "anim/portable_math.hpp"

namespace mc::anim {

void pass_other_foot(const BodyFrame& body, const PassingStep& step, float& x, float& y) {
  float was_bx, was_bz, obx, obz, fbx, fbz;
  body.to_body(step.from_x, step.from_y, was_bx, was_bz);
  body.to_body(step.other_x, step.other_y, obx, obz);
  body.to_body(x, y, fbx, fbz);
  const float side = step.side;
  const auto beside = [&](float bx) { return std::fabs(bx - obx) < kPassLength; };
  const auto side_gap = [&](float bz) { return side * (bz - obz); };
  // Its way past a foot that stood on the grass as the frame began, one
  // lifting on this frame too (game 2 seq 4284, right 10: the left foot
  // crossed over the right one as it lifted, 0.5 m in one frame).
  bool through = false;
  if (step.other_stood) {
    float sbx, sbz;
    body.to_body(step.stood_x, step.stood_y, sbx, sbz);
    for (float t : {0.25f, 0.5f, 0.75f, 1.0f}) {
      const float bx = was_bx + (fbx - was_bx) * t, bz = was_bz + (fbz - was_bz) * t;
      through = through || (std::fabs(bx - sbx) < kPassLength && side * (bz - sbz) < 0.0f);
    }
    // It passes on its own side of both places of the other foot.
    if (through) {
      obx = sbx;
      obz = side * (sbz - obz) > 0.0f ? sbz : obz;
    }
  }
  if (!through && !(beside(fbx) && side_gap(fbz) < step.min_gap)) return;
  // A foot left crossed behind (or before) the other one by a fast turn
  // uncrosses a pass length off, and passes on the next frame: pushed
  // aside within the pass length, its leg swept through the other one
  // (game 2 seq 11568, right 5; seq 3886, right 5, crossed 0.31 m behind).
  if (side_gap(was_bz) < 0.0f && beside(fbx)) fbx = obx + std::copysign(kPassLength, was_bx - obx);
  fbz = obz + side * step.min_gap;
  body.to_field(fbx, fbz, x, y);
  // Still no faster past the hip than the swing's bound.
  const float qx = x - step.from_x - step.root_dx, qy = y - step.from_y - step.root_dy, qn = pm::hypot(qx, qy);
  if (qn > step.past_hip) {
    x = step.from_x + step.root_dx + qx * step.past_hip / qn;
    y = step.from_y + step.root_dy + qy * step.past_hip / qn;
  }
}

}  // namespace mc::anim

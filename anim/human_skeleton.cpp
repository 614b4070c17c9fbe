#include "anim/human_skeleton.hpp"

namespace mc::anim {
namespace {

using L = std::vector<std::array<float, 2>>;

Segment box(float sx, float sy, float sz, float cx, float cy, float cz) {
  return Segment{SegmentShape::Box, {sx, sy, sz}, {cx, cy, cz}};
}

SkeletonDef build() {
  using namespace dims;
  SkeletonDef s;
  s.name = "matchcast-human-16";
  auto add = [&](const char* name, int parent, std::array<float, 3> off, const char* dofs, L limits,
                 Segment seg) {
    s.joints.push_back(JointDef{name, parent, off, dofs, std::move(limits), seg});
  };
  // The pelvis limits are wide: they orient the whole body for tackles and dives.
  add("pelvis", -1, {0, 0, 0}, "yzx", {{-60, 60}, {-100, 60}, {-95, 95}},
      box(0.20f, 0.16f, 0.30f, 0, 0, 0));
  add("torso", kPelvis, {0, 0.08f, 0}, "yzx", {{-45, 45}, {-60, 30}, {-35, 35}},
      box(0.22f, 0.44f, 0.36f, 0, 0.22f, 0));
  add("neck", kTorso, {0, 0.44f, 0}, "yzx", {{-80, 80}, {-45, 45}, {-30, 30}},
      box(0.08f, 0.10f, 0.08f, 0, 0.05f, 0));
  add("head", kNeck, {0, 0.10f, 0}, "yzx", {{-80, 80}, {-45, 45}, {-30, 30}},
      Segment{SegmentShape::Sphere, {0.11f, 0.11f, 0.11f}, {0.02f, 0.10f, 0}});
  // Arms: the right arm abducts with a negative X angle, the left with a positive one.
  add("r_upper_arm", kTorso, {0, 0.40f, 0.19f}, "zxy", {{-70, 180}, {-180, 30}, {-90, 90}},
      box(0.09f, 0.29f, 0.09f, 0, -0.145f, 0));
  add("r_lower_arm", kRUpperArm, {0, -0.29f, 0}, "z", {{0, 150}},
      box(0.07f, 0.26f, 0.07f, 0, -0.13f, 0));
  add("r_hand", kRLowerArm, {0, -0.26f, 0}, "zx", {{-70, 80}, {-30, 30}},
      box(0.05f, 0.18f, 0.08f, 0, -0.09f, 0));
  add("l_upper_arm", kTorso, {0, 0.40f, -0.19f}, "zxy", {{-70, 180}, {-30, 180}, {-90, 90}},
      box(0.09f, 0.29f, 0.09f, 0, -0.145f, 0));
  add("l_lower_arm", kLUpperArm, {0, -0.29f, 0}, "z", {{0, 150}},
      box(0.07f, 0.26f, 0.07f, 0, -0.13f, 0));
  add("l_hand", kLLowerArm, {0, -0.26f, 0}, "zx", {{-70, 80}, {-30, 30}},
      box(0.05f, 0.18f, 0.08f, 0, -0.09f, 0));
  // Legs: flexion about Z, ab/adduction about X, twist about Y last.
  add("r_thigh", kPelvis, {0, -kHipDrop, kHipHalfWidth}, "zxy", {{-40, 130}, {-50, 35}, {-45, 45}},
      box(0.14f, kThigh, 0.14f, 0, -kThigh / 2, 0));
  add("r_shin", kRThigh, {0, -kThigh, 0}, "z", {{-155, 0}},
      box(0.10f, kShin, 0.10f, 0, -kShin / 2, 0));
  add("r_foot", kRShin, {0, -kShin, 0}, "zx", {{-60, 35}, {-30, 30}},
      box(kFootFront + kFootBack, kAnkleHeight, 0.10f, (kFootFront - kFootBack) / 2, -kAnkleHeight / 2, 0));
  add("l_thigh", kPelvis, {0, -kHipDrop, -kHipHalfWidth}, "zxy", {{-40, 130}, {-35, 50}, {-45, 45}},
      box(0.14f, kThigh, 0.14f, 0, -kThigh / 2, 0));
  add("l_shin", kLThigh, {0, -kThigh, 0}, "z", {{-155, 0}},
      box(0.10f, kShin, 0.10f, 0, -kShin / 2, 0));
  add("l_foot", kLShin, {0, -kShin, 0}, "zx", {{-60, 35}, {-30, 30}},
      box(kFootFront + kFootBack, kAnkleHeight, 0.10f, (kFootFront - kFootBack) / 2, -kAnkleHeight / 2, 0));
  return s;
}

}  // namespace

const SkeletonDef& human_skeleton() {
  static const SkeletonDef kSkeleton = build();
  return kSkeleton;
}

}  // namespace mc::anim

// Skeleton definition: the description of an articulated body that travels
// once to every client (in the stream's hello), so that clients draw any
// skeleton without knowing it in advance.
//
// Shape of the data (after ozz-animation): a parent-index array plus rest
// offsets, not a tree of objects. Joints are ordered so that a parent always
// comes before its children; joint 0 is the root (pelvis).
//
// Body space: right-handed, Y up, the body faces +X at rest, +Z is the
// body's right side. A joint's local rotation is the product of elementary
// rotations about its own axes, in the order its `dofs` string lists them:
//   R_local = R_dofs[0](a0) * R_dofs[1](a1) * ...   (intrinsic)
// and its model-space transform is
//   M_j = M_parent * Translate(offset_ls) * R_local.
// A positive angle about +Z (the right axis) turns +X (forward) towards +Y
// (up): positive hip flexion swings the foot forward, knee flexion is negative.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace mc {

enum class SegmentShape : unsigned char { Box = 0, Sphere = 1 };

struct Segment {
  SegmentShape shape = SegmentShape::Box;
  std::array<float, 3> size{};    // m; box extents (x, y, z), sphere uses size[0] as radius
  std::array<float, 3> center{};  // m, centre of the shape in the joint's local space
};

struct JointDef {
  std::string name;
  int parent = -1;                            // index into SkeletonDef::joints, -1 for the root
  std::array<float, 3> offset_ls{};           // m, rest translation in the parent's local space
  std::string dofs;                           // rotation axes, a subset of "xyz" in application order
  std::vector<std::array<float, 2>> limits;   // deg, [min, max] per dof, same order as `dofs`
  Segment segment;                            // what to draw for this joint's bone
};

struct SkeletonDef {
  std::string name;
  std::vector<JointDef> joints;

  // Total rotational degrees of freedom: the length of a pose's angle vector.
  int dof_count() const {
    int n = 0;
    for (const auto& j : joints) n += static_cast<int>(j.dofs.size());
    return n;
  }
  // Index of the joint with this name, or -1.
  int find(const std::string& joint_name) const {
    for (std::size_t i = 0; i < joints.size(); ++i)
      if (joints[i].name == joint_name) return static_cast<int>(i);
    return -1;
  }
};

}  // namespace mc

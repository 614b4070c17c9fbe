// Forward kinematics: joint angles (local space) -> joint transforms in model
// space, in one forward pass over the parent-index array (ozz LocalToModelJob).
//
// Model space is the player's body space (proto/skeleton.hpp): origin on the
// grass under the pelvis, Y up, facing +X, +Z right. Field placement (x, y,
// heading) is not applied here; see body_frame.hpp for that.
#pragma once

#include <cstdint>
#include <span>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "proto/skeleton.hpp"

namespace mc::anim {

// Rotation of one joint's dofs: R = R_dofs[0](a0) * R_dofs[1](a1) * ...
// `dofs` is a subset of "xyz", `deg` holds one angle per dof (degrees).
glm::mat3 joint_rotation(const std::string& dofs, const float* deg);

// The same rotation from each angle's sine and cosine.
glm::mat3 joint_rotation(const std::string& dofs, const float* sin, const float* cos);

// Its inverse for a joint of three different axes: the angles (deg) whose
// joint_rotation is `r` (the Tait-Bryan decomposition, the middle angle
// within +-90). False for any other `dofs`.
bool joint_angles(const std::string& dofs, const glm::mat3& r, float out_deg[3]);

// The angle (deg) of the rotation between two orientations of one joint,
// each given as its dofs' angles (deg): how far the joint turns from one to
// the other, whatever the path its angles take.
float rotation_between(const std::string& dofs, const float* a, const float* b);

struct LocalToModelJob {
  const SkeletonDef* skeleton = nullptr;
  std::span<const float> angles_deg;  // in: dof_count() angles, SkeletonDef order
  glm::vec3 root_ms{0.0f};            // in: root joint position, model space (m)
  std::span<glm::mat4> models;        // out: one model-space transform per joint
  // Joints to compute, bit i for joint i (after ozz's from/to options); the
  // others' transforms are left as they were. A joint's parent must be in it.
  std::uint32_t joint_mask = ~0u;

  // False when the skeleton is missing, a parent does not precede its child,
  // or a span is shorter than the skeleton needs.
  bool Validate() const;
  // Writes `models`; returns false (and writes nothing) when !Validate().
  bool Run() const;
};

}  // namespace mc::anim

// The human skeleton Matchcast animates: 16 box/sphere segments, about 1.83 m
// tall, with joint limits for every degree of freedom.
//
// Conventions are those of proto/skeleton.hpp: body space is right-handed,
// Y up, the body faces +X, +Z is the body's right. Intrinsic Euler angles in
// each joint's `dofs` order. Signs that follow from this (degrees):
//   - rotation about +Z turns +X towards +Y: positive hip / shoulder flexion
//     swings the limb forward, knee flexion is negative, elbow flexion is
//     positive, a positive torso Z angle leans the torso backwards;
//   - rotation about +Y turns +X towards -Z: a positive yaw looks LEFT, so a
//     field angle (which grows towards the body's right) maps to yaw = -angle;
//   - rotation about +X turns +Y towards +Z: a positive X angle moves a
//     hanging limb towards -Z (right limb: adduction, left limb: abduction).
//
// Placement of a player (what a client does with a PlayerPose):
//   M_pelvis = Field(x, y, z) * Yaw(-heading) * R_pelvis(angles)
// where Field maps field (x, y, height) to the client's frame. The pelvis
// offset_ls is zero; PlayerPose::z is the pelvis height above the grass. With
// straight legs the ankles are 0.92 m below the pelvis and the soles 1.00 m.
#pragma once

#include "proto/skeleton.hpp"

namespace mc::anim {

// Joint indices of human_skeleton(), parents before children.
enum HumanJoint : int {
  kPelvis = 0, kTorso, kNeck, kHead,
  kRUpperArm, kRLowerArm, kRHand,
  kLUpperArm, kLLowerArm, kLHand,
  kRThigh, kRShin, kRFoot,
  kLThigh, kLShin, kLFoot,
  kHumanJointCount
};

// Index of each joint's first dof in a pose's angle vector. Dof orders:
// pelvis/torso/neck/head "yzx", shoulders and hips "zxy", elbows and knees
// "z", wrists and ankles "zx".
namespace dof {
inline constexpr int kPelvis = 0, kTorso = 3, kNeck = 6, kHead = 9;
inline constexpr int kRShoulder = 12, kRElbow = 15, kRWrist = 16;
inline constexpr int kLShoulder = 18, kLElbow = 21, kLWrist = 22;
inline constexpr int kRHip = 24, kRKnee = 27, kRAnkle = 28;
inline constexpr int kLHip = 30, kLKnee = 33, kLAnkle = 34;
inline constexpr int kCount = 36;
}  // namespace dof

// Dimensions the motion code needs (metres), equal to the offsets in the
// definition.
namespace dims {
inline constexpr float kHipDrop = 0.06f;      // pelvis joint -> hip joints, down
inline constexpr float kHipHalfWidth = 0.10f; // pelvis joint -> hip joints, sideways
inline constexpr float kThigh = 0.44f;        // hip -> knee
inline constexpr float kShin = 0.42f;         // knee -> ankle
inline constexpr float kAnkleHeight = 0.08f;  // ankle above the sole
inline constexpr float kFootFront = 0.19f;    // ankle -> toe tip, forward
inline constexpr float kFootBack = 0.07f;     // ankle -> heel, backward
inline constexpr float kStandPelvis = kHipDrop + kThigh + kShin + kAnkleHeight;  // 1.00
}  // namespace dims

// The definition, built once; valid for the program's lifetime.
const SkeletonDef& human_skeleton();

}  // namespace mc::anim

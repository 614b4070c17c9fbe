// One player posed on the hello's skeleton, in world space (X = field x,
// Y up, Z = field y), and the geometry the close-up metrics take from it:
// the feet's lowest sole points, the clearance of two segments' centre
// lines, how deep a hand reaches into a body box. The quality tool's own
// forward kinematics, apart from the animator's (issue 23: it measures
// what a spectator receives).
#pragma once

#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "proto/pose_frame.hpp"
#include "proto/skeleton.hpp"

namespace mc::anim::tools::posed {

enum Group { kLegs = 0, kArms, kTrunk, kHead };

struct Box {
  bool valid = false;
  glm::vec3 c{0}, h{0};  // centre and half extents, joint local space
  int axis = 1;          // the longest axis (the centreline)
  float half_width = 0;  // the larger of the other two half extents
};

// Indices into the hello's skeleton, found by name.
struct Rig {
  int foot[2] = {-1, -1}, thigh[2] = {-1, -1}, shin[2] = {-1, -1}, hand[2] = {-1, -1};
  int pelvis = -1, torso = -1;
  std::vector<int> group;      // per joint
  std::vector<int> first_dof;  // per joint
  std::vector<Box> box;        // per joint

  explicit Rig(const SkeletonDef& s);
};

struct FootGeom {
  float lowest = 1e9f;
  glm::vec3 contact_ls{0};
  bool grounded = false;
};

// One player on one drawn frame, in world space: X = field x, Y up, Z = field y.
struct Geom {
  bool active = false;
  float x = 0, y = 0;
  std::vector<glm::mat4> world;
  std::vector<glm::mat3> rot;  // local rotations; the pelvis's with the heading
  FootGeom feet[2];
};

// Poses `p` on `s` (its angles, root position and heading) into `g`, and
// finds each foot's lowest sole point and whether it is on the grass.
void pose(const SkeletonDef& s, const Rig& rig, const PlayerPose& p, Geom& g);

// Rotation angle (deg) between two orientations.
float rotation_deg(const glm::mat3& a, const glm::mat3& b);

// Signed distance from a point (box local space) to a box: negative inside.
float box_sd(const Box& b, const glm::vec3& p);

// Clearance of joints a's and b's box centrelines less half the larger box
// width (< 0: too close); 1 when either has no box.
float clearance(const Rig& rig, const Geom& g, int a, int b);

// How deep the hand's box reaches into a body box (m, 0 when outside).
float hand_depth(const Rig& rig, const Geom& g, int hand, int body);

}  // namespace mc::anim::tools::posed

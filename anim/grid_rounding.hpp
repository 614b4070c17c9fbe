// Rounding a pose to the stream's grid so that the rounding does not move
// its ankles.
//
// Why: the stream carries joint angles on a 0.99 deg grid and positions on
// a 1 cm grid (proto/SPEC.md section 3). Each value rounded to its nearest
// grid point on its own, a leg is a 0.9 m lever under the root's position
// and heading, the pelvis's three dofs, the hip's three and the knee: a
// planted ankle moves by a centimetre or two, differently on every frame.
// The clients pin a grounded foot to the line between two frames' ankles
// (SPEC 4.7 step 2), so they draw that jitter faithfully, as a foot that
// slides: in the two full games it was most of the grounded foot's speed
// at 20 Hz (0.29-0.37 m/s in the running bands, 0.06-0.18 m/s unrounded).
//
// So the animator rounds its own output. The root, the heading and the
// pelvis go to their nearest grid points. Then, for each leg whose sole
// may be on the grass, each of the hip's three dofs and the knee takes the
// grid point below or above its value: of the 16 choices, the one that
// leaves the ankle nearest where the unrounded pose has it. Each dof's step moves the ankle by (axis x lever)
// times the step to first order; the second order is below 0.02 mm at a
// 1 deg step. A dof may so be 0.99 deg off its unrounded value instead of
// 0.495 deg: the pose is the animator's to choose, and the stream carries it
// exactly (the encoder's rounding of a grid value is the value itself).
#pragma once

#include <glm/mat4x4.hpp>

#include "proto/pose_frame.hpp"
#include "proto/quantizer.hpp"
#include "proto/skeleton.hpp"

namespace mc::anim {

// `models`: the joints of `pose` in body space (LocalToModelJob on
// pose.angles for `skeleton`, human_skeleton(), any root height): the
// pelvis's, thighs', shins' and feet's are read. When a sole may be on the
// grass, writes pose.x, y, z and heading and the pelvis's angles as values
// on `grid`, and the hip's and knee's angles of each leg whose sole may be;
// the rest is left for the encoder to round. `kicking_leg` (0 right, 1
// left) is a leg whose foot meets the ball in this frame: its ankle is kept
// too (the kicks' p95 from the foot's box to the ball 1.5 -> 1.0 cm).
void round_legs_to_grid(const proto::Quantizer& grid, const SkeletonDef& skeleton, const glm::mat4* models,
                        PlayerPose& pose, int kicking_leg = -1);

}  // namespace mc::anim

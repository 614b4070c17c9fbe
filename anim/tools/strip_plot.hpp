// Pictures a person can look at: a strip of one player's poses, seen from
// the side, one pose per cell (right limbs red, left limbs blue, the ball
// green).
#pragma once

#include <vector>

#include "anim/tools/png.hpp"
#include "proto/pose_frame.hpp"
#include "proto/skeleton.hpp"

namespace mc::anim::tools {

inline constexpr int kCellPx = 150;   // width of one pose's cell
inline constexpr int kRowPx = 230;    // height of one row
inline constexpr float kPxPerM = 100; // drawing scale

// Draws row `row` of `img`: the player in `slot` at each of `frames`, seen
// from its right side along `view_heading` (field deg), each pose centred on
// its own pelvis.
void draw_pose_row(Image& img, int row, const SkeletonDef& skeleton, const std::vector<const PoseFrame*>& frames,
                   int slot, float view_heading);

}  // namespace mc::anim::tools

// Feet in the air keep off the grass (issue 23). A foot that no footstep
// holds and that travels with its sole within a few centimetres of the
// grass reads as a foot sliding over it, whatever the animation meant: a
// foot just off the grass or about to land that the clients' blend between
// two frames drags through the contact height, a swing that crosses the
// other leg low in a turn, a foot handed back from an action. Before the
// legs are solved, such a foot's ankle target is raised until the sole
// it asks for is swing_clear() up: kSwingClearM, more for a foot that
// travels far while the body runs with it. Human skeleton only; no I/O.
#pragma once

namespace mc::anim {

// A foot in the air that moves further than this over the grass in a frame
// (m; 1 m/s at 20 Hz) keeps its sole kSwingClearM up at least: clear of the
// contact height (3 cm) by a margin for the clients' blend, which takes a
// sole leaving the grass or landing on it a third of its way in a third of
// the frame (proto/SPEC.md 4.7). 7 and 8 cm for every such foot took the
// 60 Hz sliding further down but brought floating bodies (anim/README.md).
inline constexpr float kSkimStepM = 0.05f;
inline constexpr float kSwingClearM = 0.05f;
// After the joint speed limit such a foot's ankle may turn this far (deg)
// past its pitch towards level to keep the sole swing_clear() up
// (player_animation.cpp). With 8 deg, as far as a sole pitched into the
// grass turns, game 2's 9+ m/s band at 20 Hz was 0.50 m/s; with 20 deg
// 0.39 (50 deg gave the same).
inline constexpr float kSkimLevelDeg = 20.0f;
// A foot that travels further keeps higher: kSwingClearPerM of its travel
// over the frame, from kSwingClearM up to kSwingClearMaxM. The clients'
// blend draws a third of a leaving swing's travel at a little over half its
// height (proto/SPEC.md 4.7), so a sprinter's 0.5-0.9 m swing skims the
// grass unless its first frame's sole is well up. The travel counted is
// kSwingTravelPerRoot times the root's at most: a player who stops keeps
// his last swing low, or he floats. With these, every grounded-foot band
// at the clients' 60 Hz is within issue 23's 0.5 m/s on both full games
// (anim/README.md has the variants measured). Up to 22 cm, game 1's 8-9 m/s
// band read 0.51 at phase 0.45 of the display; 26 cm (session 36) takes it
// to 0.49 with every band within 0.5 at 40 phases, once a landing foot is
// held back as the clients draw it (player_animation.cpp: without that,
// the higher swings popped 2 ankles at 60 Hz); 30 cm brought a shin
// through the other at 20 Hz.
inline constexpr float kSwingClearPerM = 0.3f;
inline constexpr float kSwingClearMaxM = 0.26f;
inline constexpr float kSwingTravelPerRoot = 2.5f;

// The sole's clearance asked of a foot in the air that travels `travel_m`
// over the grass in a frame while the root moves `root_m` (0 when the foot
// does not travel further than kSkimStepM).
float swing_clear(float travel_m, float root_m);

// Whether a foot in the air whose ankle target is `ankle_height` m up and
// `travel_m` from where its ankle was on the last frame (over the grass)
// may need raising to a clearance of `clear_m`: no corner of the foot's box
// is further from the ankle than its centre's offset plus its half
// diagonal. Most feet in the air are higher.
bool may_skim(float ankle_height, float travel_m, float clear_m);

// How far to raise an ankle target `ankle_height` m up whose sole is asked
// for at `pitch_deg` (LegPoseJob's FootTarget; level sideways) so that the
// sole's lowest corner is `clear_m` up: 0 when it is. The leg's solution
// gives that sole unless the ankle's limits hold it off its pitch or level
// (a leg crossing the other); posing the solution to catch those too cost
// 3-4 % of the animation's time for 0.01-0.02 m/s of the 60 Hz sliding.
float swing_lift(float ankle_height, float pitch_deg, float clear_m);

}  // namespace mc::anim

// The quality tool's measurement on both full games of tests/data/rcg/full
// (issue 23): what a spectator receives, decoded and posed on the hello's
// skeleton, at 20 Hz and at the clients' 60 Hz. Each figure has a bound:
// issue 23's target where it is met, else the figure as last measured, so
// that no figure can regress (anim/README.md has the table).
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "anim/animator.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/tools/close_up_metrics.hpp"
#include "anim/tools/contact_sheet.hpp"
#include "anim/tools/stream_view.hpp"
#include "server/ingest/state_source.hpp"

namespace mc::anim::tools {
namespace {

// Upper bounds (lower for the kick's depth), one set per drawing rate.
struct Bounds {
  // Grounded-foot mean: standing, the worst band up to 9 m/s, above 9 m/s,
  // and the worst band up to 8 m/s.
  double stand_mps, moving_band_mps, sprint_band_mps, to_8_band_mps;
  double kick_p95_m, kick_max_m;
  long kicks_inside;
  double leg_deg, arm_deg, trunk_deg, head_deg;
  long ankle_pops;
  long thighs, shins, feet, hands;
  long floating;
  double ankle_limit_share;
  double cadence_p99;
  double lowest_m;  // lower bound
  double step_in_m;
};

// Hands: issue 23's target (0) holds at 20 Hz and at 60 Hz since the arms
// lift 6 cm clear of the thighs (2026-11-26; 3 cm left 10 and 4 drawn
// frames of the two games at 60 Hz).
// Floating and ankle pops: a body that slows below a run with both feet up
// comes down (anim/footsteps.cpp) since 2026-11-26: floating 1448/1334 ->
// 463/466 player-frames, pops 623/486 -> 561/453. The bound on thighs
// closer than half a box width rose from 45 to 52 with it (35/37 -> 39/49):
// more quick short steps bring the feet closer together; anim/README.md.
// Kicks: the kicking leg may turn 57 deg on its contact frame (50 before,
// anim/player_animation.hpp) since 2026-11-26: the farthest foot from the
// ball at contact 0.144/0.036 m -> 0.084/0.021 m, so the bound went 0.15 -> 0.09.
// Legs apart: after contact the kicking foot keeps to its own side of the
// planted support foot (anim/action_motion.cpp) since 2026-11-26: thighs /
// shins / feet too close 39/53/34 -> 26/11/16 and 49/83/30 -> 39/19/17 at
// 20 Hz; the bounds went 52/90/45 -> 45/25/22 (60 Hz 800/370/250 -> 740/160/200).
// Kicks meet issue 23's target (max 3 cm) since a kick is planned for the
// heading the body has at contact (anim/animator.cpp, 2026-11-27): the
// farthest foot 0.084/0.021 m -> 0.028/0.022 m. The worst was a receiver
// who turned 150 deg, kicked and turned away: planned for a body 84 deg off,
// the foot on the wrong side of the ball. With it the sprint band of game 2
// (9+ m/s, 189 frame pairs) went 4.74 -> 4.81 m/s, so its bound 4.8 -> 4.9.
// A tackler who runs off gets up (anim/animator.cpp, 2026-11-27) instead of
// gliding in the slide's pose for tackle_cycles: the worst moving band went
// 3.50/4.81 -> 1.22/1.21 m/s at 20 Hz and 4.63/4.87 -> 4.30/4.30 at 60 Hz,
// so the bounds 4.9 -> 1.3 and 4.9 -> 4.4.
// A foot that lands late bears the body for half a stance (anim/footsteps,
// 2026-11-27): floating 456/463 -> 264/269 player-frames at 20 Hz (60 Hz
// 1101/1085 -> 561/541), every moving band lower (worst 1.22/1.21 -> 1.06/0.85
// m/s), for more ankle pops, 558/442 -> 607/464 (60 Hz 2041/1713 ->
// 2242/1743), and thighs too close at 60 Hz 729/709 -> 829/769: the feet
// held a frame or two longer swing faster after (anim/README.md). Bounds:
// floating 500 -> 280 and 1200 -> 580, bands 1.3 -> 1.1 and 4.4 -> 4.3,
// pops 580 -> 620 and 2100 -> 2300, thighs at 60 Hz 740 -> 850.
// With both feet up on a slow frame, the foot further through its swing
// reaches down (anim/footsteps, 2026-11-27): floating 264/269 -> 176/145
// (60 Hz 561/541 -> 375/286), bounds 280 -> 190 and 580 -> 400.
// A kick whose support foot locomotion has taken back ends its
// follow-through (anim/animator.cpp, 2026-11-27): floating 176/145 ->
// 132/118 (60 Hz 375/286 -> 251/231), ankle pops 611/463 -> 586/442 (60 Hz
// 2252/1748 -> 2184/1675); bounds 190 -> 140 and 400 -> 260, pops 620 ->
// 600 and 2300 -> 2250. Feet too close at 60 Hz on game 2 went 199 -> 201,
// its bound 200 -> 205.
// Floating meets issue 23's target (at most 50 player-frames a game at
// 20 Hz) since the pelvis comes down for a foot reaching down (anim/
// player_animation.cpp, 2026-11-27): 132/118 -> 33/35 (60 Hz 251/231 ->
// 69/77, against 150 for three drawn frames per 20 Hz frame).
// Planted legs still too close turn their knees out over the same feet
// (anim/player_animation.cpp, 2026-11-27): thighs / shins / feet too close
// 26/9/14 -> 18/9/13 and 28/13/17 -> 17/11/13 at 20 Hz (60 Hz 823/125/176 ->
// 790/116/175, 773/157/200 -> 745/149/187); bounds 45/25/22 -> 20/12/15 and
// 850/160/205 -> 800/155/190.
// An ankle moves at most 0.5 m a frame relative to the pelvis and 0.92 m
// over the grass (anim/ankle_travel.hpp, 2026-11-27; a swing at most 0.55 m
// past the hip in anim/footsteps.cpp), and a kick's support foot held short
// as it plants is planted where it came down: ankle pops 589/445 -> 27/26
// at 20 Hz (60 Hz 2203/1684 -> 126/124), bounds 600 -> 30 and 2250 -> 130;
// every band up to 9 m/s now meets the target at 20 Hz on both games
// (8-9 m/s 0.61/0.41 -> 0.48/0.39). The trade: thighs / shins / feet too
// close went 18/9/13 -> 19/15/15 and 17/11/13 -> 19/14/12 (bounds 20/12/15
// -> 20/15/15; 60 Hz thighs 790 -> 803, bound 800 -> 810), and the 9+ m/s
// band of game 1 (135 frame pairs; the worst a goalkeeper getting up from a dive
// while the server carries him at 9 m/s) 1.09 -> 1.26 m/s, bound 1.1 ->
// 1.3. The lowest point at 60 Hz rose, -0.097/-0.104 -> -0.063/-0.089 m:
// bound -0.11 -> -0.095, and its worst band 4.25 -> 4.06 m/s: bound 4.3 -> 4.1
// (anim/README.md). The bands up to 9 m/s are bounded apart from the
// sprint band since then: issue 23's 0.5 m/s at 20 Hz (the 3-4 m/s band of
// game 1 was 0.53 before the support foot's new spot), 1.7 at 60 Hz (8-9 m/s
// 1.64/1.21).
// The lowest point at 60 Hz meets issue 23's target (-2 cm) since the clients
// rest every pose they draw on the grass (proto/SPEC.md 4.7, anim::
// rest_on_grass; 2026-11-27): -0.063/-0.089 -> -0.010/-0.010 m.
// Legs keep half a box width plus 3.5 cm apart, not 1.5 (anim/
// limb_clearance.cpp, 2026-11-27): thighs / shins / feet too close 19/15/15
// -> 5/8/8 and 19/14/12 -> 1/5/10 at 20 Hz (60 Hz 803/124/180 -> 384/53/131,
// 742/142/162 -> 359/39/131), bounds 20/15/15 -> 5/8/10 and 810/155/190 ->
// 390/55/135; ankle pops at 60 Hz 126/124 -> 131/138, bound 130 -> 140.
// Ankle pops at 20 Hz meet issue 23's target (0) since a kicking foot keeps
// within a frame's reach of its contact on the frames before it, and legs
// turned apart keep within a frame's travel (anim/ankle_travel.hpp,
// 2026-11-27): 27/28 -> 0/0 (60 Hz 131/138 -> 77/69), bounds 30 -> 0 and
// 140 -> 80. The trade: one kick on game 1 (a ball behind a backpedalling
// player) misses by 8.3 cm, its knee held by the joint speed limit, so the
// kick bound 0.03 -> 0.09; thighs / shins too close on game 1 5/8 -> 8/9
// (60 Hz shins 53 -> 58), bounds 5/8/10 -> 8/9/10 and 390/55/135 ->
// 390/58/135.
// A leg in the air is turned out again after the legs were separated or
// the joint speed limit held a leg back (anim/player_animation.cpp,
// separate_legs_again, 2026-11-27): thighs / shins / feet too close 8/9/10
// -> 5/5/6 and 2/5/10 -> 0/1/4 at 20 Hz (60 Hz 390/58/133 -> 380/45/122,
// 359/39/130 -> 343/23/117), bounds 8/9/10 -> 5/5/6 and 390/58/135 ->
// 380/45/122; ankle pops at 60 Hz 77/69 -> 80/77.
// Kicks meet issue 23's target again since a contact behind the hips is
// reached back for with less wind-up (anim/kick_planner.cpp, 2026-11-27):
// the farthest foot 0.083/0.024 -> 0.028/0.024 m, bound 0.09 -> 0.03; feet
// too close 6/4 -> 5/4 (60 Hz 122/117 -> 119/117), ankle pops at 60 Hz
// 80/77 -> 77/74.
// A whole-body action's leg pose blended over the IK legs is turned out of
// the other leg's way too (separate_legs_again, 2026-11-27): thighs /
// shins / feet too close 5/5/5 -> 4/4/3 and 0/1/4 -> 0/1/3 (60 Hz
// 380/45/119 -> 376/40/115, 343/23/117 -> 343/23/116).
// The clients keep planted feet on their line between frames and raise
// feet that leave or land (proto/SPEC.md 4.7 step 2, anim/leg_blend.cpp;
// 2026-11-27): at 60 Hz the worst band up to 8 m/s 0.85/0.92 -> 0.70/0.78
// m/s (bound 0.8, new), up to 9 m/s 1.65/1.20 -> 1.46/1.05 (bound 1.7 ->
// 1.5); thighs / shins / feet too close 376/40/115 -> 359/40/116 and
// 343/23/116 -> 323/27/119, ankle pops 77/74 -> 81/73 (at the threshold:
// steps of 0.60-0.63 m relative to the pelvis per 50 ms that cross it
// either way); bounds 376/40/116 -> 360/40/120 and pops 77 -> 81.
// The clients turn a leg in the air out of the other leg's way as they
// blend (proto/SPEC.md 4.7 step 2, second part; anim/leg_blend.cpp,
// 2026-11-27): thighs / shins / feet too close at 60 Hz 359/40/116 ->
// 18/10/71 and 323/27/119 -> 28/5/67, no other figure moved; bounds
// 360/40/120 -> 28/10/71.
// With both feet up, the leg further across the body turns out (not the
// right one always), and a leg turned out again keeps each third of the
// clients' blend within the hip's limit too (anim/limb_clearance.cpp,
// anim/player_animation.cpp, 2026-11-27): thighs / shins / feet too close
// at 20 Hz 4/4/3 -> 2/1/3 and 0/1/3 -> 0/0/3, ankle pops at 60 Hz 81/73 ->
// 61/63; the trade: feet too close at 60 Hz 71/67 -> 76/72, the 9+ m/s band
// of game 2 0.70 -> 0.78 m/s and 8-9 m/s of game 1 0.47 -> 0.50 (its bound
// 0.5). Bounds 4/4/3 -> 2/1/3, 60 Hz pops 81 -> 63, feet 71 -> 76, shins
// 10 -> 9.
// When the leg further across may not turn (the speed limit holds it), the
// other one turns out instead (anim/player_animation.cpp, 2026-11-27):
// thighs / shins too close 2/1 -> 1/0 on game 1 (60 Hz 19/9 -> 18/8), no
// other figure moved; bounds 2/1 -> 1/0, 60 Hz shins 9 -> 8.
// The clients' turn out of the other leg's way is bounded by the ankle's
// travel smoothly (its sideways move and its travel within 0.47 m a frame)
// rather than refused from 0.4 m of travel (2026-11-27): at 60 Hz thighs /
// shins / feet too close 18/8/76 -> 14/7/70 and 25/3/72 -> 16/1/63, ankle
// pops unchanged; bounds 28/8/76 -> 16/7/70.
// The animator holds back a leg whose ankle the clients' linear blend
// carries too fast over part of a frame, though its chord keeps within the
// bounds (anim/ankle_travel.cpp limit_drawn_travel, 2026-11-27): ankle
// pops at 60 Hz 61/63 -> 21/17, all of them a kicking foot's last frame
// before contact; thighs too close at 60 Hz on game 2 16 -> 17, feet 63 ->
// 60, the 60 Hz 5-6 m/s band of game 2 0.800 -> 0.8002. Bounds: pops 63 ->
// 21, thighs 16 -> 17, 60 Hz bands to 8 m/s 0.80 -> 0.81.
// A foot in the air that travels keeps its sole 5 cm up (anim/
// swing_clearance.hpp, 2026-11-28): the 60 Hz bands up to 8 m/s at most
// 0.71/0.80 -> 0.69/0.78 (0.5-1 m/s 0.59/0.60 -> 0.48/0.48), at 20 Hz
// 0.46/0.47 -> 0.39/0.42; thighs / shins too close at 60 Hz 14/7 -> 13/6
// and 17/1 -> 15/1; floating 33/36 -> 41/41 at 20 Hz. Bounds: 60 Hz bands
// to 8 m/s 0.81 -> 0.80, thighs / shins 17/7 -> 15/6.
// The IK legs are clamped to their joint limits before they are kept apart,
// a foot lands with its sole's centre line 11 cm from the other's whatever
// their yaws (anim/footsteps.cpp), and a kicking leg the speed limit holds
// short of the ball reaches it with the hip (anim/kick_reach.hpp,
// 2026-11-28): thighs / shins / feet too close at 20 Hz 1/0/3 -> 0/0/0 and
// 0/0/3 -> 0/0/0 (issue 23's target), the 9+ m/s band of game 1 1.21 ->
// 0.94 m/s; at 60 Hz 13/6/70 -> 14/6/69 and 15/1/59 -> 15/2/56, ankle pops
// 21/17 -> 21/18. Bounds: 20 Hz 1/0/3 -> 0/0/0, sprint band 1.3 -> 1.0,
// 60 Hz feet 70 -> 69.
// A catch is the upper body's over the legs' footsteps (anim/
// action_motion.cpp, 2026-11-28): the 9+ m/s band at 20 Hz 0.94/0.79 ->
// 0.79/0.63 (a goalkeeper who caught and ran on); bound 1.0 -> 0.85.
// A foot in the air that travels turns towards a level sole until it is
// 5 cm up, after the joint speed limit (anim/player_animation.cpp,
// 2026-11-28): the 9+ m/s band at 20 Hz 0.79/0.63 -> 0.63/0.38 (game 2
// within issue 23's 0.5), the bands below it 0.01-0.08 lower at 20 Hz and
// up to 0.06 at 60 Hz; at 60 Hz thighs too close 13/13 -> 11/12, feet
// 66/54 -> 68/52. Bounds: 20 Hz sprint band 0.85 -> 0.65; 60 Hz worst band
// up to 9 m/s 1.5 -> 1.35, up to 8 m/s 0.80 -> 0.75, 9+ 4.1 -> 4.0,
// thighs 13 -> 12, feet 66 -> 68.
// The animator rounds its own frames to the stream's grid, the hip and
// knee of each leg whose sole may be on the grass (and a kicking leg at
// contact) the way that keeps its ankle where the unrounded pose has it
// (anim/grid_rounding.hpp, 2026-11-29): the 20 Hz bands from 0.5 to 9 m/s
// 0.29-0.37 -> 0.16-0.25, the 9+ m/s band 0.63/0.38 -> 0.50/0.31; at 60 Hz
// 3-4 m/s 0.55/0.53 -> 0.45/0.43 ... 8-9 m/s 1.32/0.98 -> 1.25/0.89;
// kicks' p95 1.5/1.4 -> 1.0/1.1 cm. The legs' angles move by up to a grid
// step more: at 60 Hz thighs / shins / feet too close 11/6/68 and 12/2/52
// -> 12/6/64 and 14/2/53. Bounds: 20 Hz sprint band 0.65 -> 0.55; 60 Hz
// worst band up to 9 m/s 1.35 -> 1.3, up to 8 m/s 0.75 -> 0.65, thighs /
// shins / feet 12/6/68 -> 14/6/65.
// Above 7.5 m/s a foot stays on the grass until the hip is out of its
// reach, not a frame before (anim/footsteps.cpp, 2026-11-29): a sprinter's
// stance is two frames, not one. A planted foot the ankle's travel bound
// pulls back lets go (it stepped twice on one spot), and a hand is kept
// out of its thigh in the clients' blend too (a sprinter's raised knee
// met the arm swinging back). The 9+ m/s band 0.50/0.31 -> 0.19/0.17 at
// 20 Hz and 3.93/3.80 -> 0.58/0.64 at 60 Hz, 8-9 m/s 1.25/0.89 ->
// 0.74/0.60 at 60 Hz; thighs too close at 60 Hz 12/14 -> 10/18. Bounds: 20
// Hz sprint band 0.55 -> 0.5 (issue 23's target); 60 Hz worst band up to 9
// m/s 1.3 -> 0.8, 9+ 4.0 -> 0.7, thighs 14 -> 18.
constexpr Bounds kAt20Hz{0.20, 0.5, 0.5, 0.5, 0.02, 0.03, 0, 60, 45, 45, 45, 0, 0, 0, 0, 0, 50, 0.02, 4.5,
                         -0.02, 0.31};
// A kicking foot on its last frame before contact is held back by the
// clients' blend as any other foot is (limit_drawn_travel; the contact
// reaches the ball with the hip, kick_reach.hpp, 2026-11-28): ankle pops
// at 60 Hz 21/18 -> 1/1, kicks unchanged, shins too close at 60 Hz on
// game 1 6 -> 7. Bounds: pops 21 -> 1, shins 6 -> 7.
// The clients' drawn travel relative to the pelvis is held within 0.55 m a
// frame, not 0.58 (room for their 1 deg swing of a leg), a leg held back is
// turned out of the other's way again, and a turn-out too fast in full is
// taken in part (anim/player_animation.cpp, anim/limb_clearance.cpp,
// 2026-11-28): ankle pops at 60 Hz 1/1 -> 0/0 (issue 23's target), thighs /
// shins / feet too close at 60 Hz 14/7/69 -> 13/6/66 and 15/2/56 ->
// 13/2/54, 20 Hz still 0/0/0. Bounds: pops 1 -> 0, 15/7/69 -> 13/6/66.
// The clients part feet that meet in the blend along the line between
// them, in four rounds, not two (anim/leg_blend.cpp, 2026-11-29): thighs /
// shins / feet too close at 60 Hz 10/6/65 and 18/2/52 -> 11/5/30 and
// 16/3/31, no other figure moved. Bounds: 18/6/65 -> 16/5/31.
// A leaving or landing foot is eased across the grass too (2026-11-29):
// the 4-5 m/s bands 0.51/0.51 -> 0.47/0.47, 5-6 m/s 0.55/0.63 ->
// 0.52/0.58; too close 11/5/30 and 16/3/31 -> 11/6/33 and 13/3/30.
// Bounds: worst band up to 8 m/s 0.65 -> 0.6, 16/5/31 -> 13/6/33.
// The animator draws each frame from the last one as the clients do and,
// where their legs pass through each other, turns a leg in the air apart
// at the frame (anim/drawn_leg_clearance.hpp, 2026-11-29): too close at
// 60 Hz 11/6/33 and 13/3/30 -> 4/1/10 and 3/0/15, no band moved by more
// than its rounding. Bounds: 13/6/33 -> 4/1/15.
// A foot in the air keeps its sole higher the further it travels while the
// body runs with it (anim/swing_clearance.hpp, 2026-11-29): at 60 Hz the
// 5-6 m/s bands 0.52/0.58 -> 0.43/0.48, 8-9 m/s 0.73/0.58 -> 0.46/0.38, 9+
// 0.56/0.63 -> 0.46/0.46, every band within issue 23's 0.5 on both games;
// too close 4/1/10 and 3/0/15 -> 3/2/8 and 3/0/9 (game 1's two shins under 1
// and 3 mm inside). Bounds: every 60 Hz band 0.5, 4/1/15 -> 3/2/9.
// A leg in the air may also bend or straighten its knee where the clients'
// blend brings the legs through each other (anim/drawn_leg_clearance.cpp,
// 2026-11-29): too close at 60 Hz 3/2/8 and 3/0/9 -> 3/3/6 and 2/0/4, no
// other figure moved by more than its rounding. Bounds: 3/2/9 -> 3/3/6.
// The clients turn a foot that is leaving the grass or landing on it out of
// the other leg's way by t or 1 - t however low their blend draws it
// (anim/leg_blend.cpp, proto/SPEC.md 4.7, 2026-11-29): too close at 60 Hz
// 3/3/6 and 2/0/4 -> 2/1/2 and 2/0/2; grounded-foot pairs faster than 0.5
// m/s at 60 Hz +20 and +14 (of 48,231 and 47,415). Bounds: 3/3/6 -> 2/1/2.
// A leg in the air may also swing forward or back at the hip (flexion),
// in 2-degree steps, not 4 (anim/drawn_leg_clearance.cpp, 2026-11-29):
// too close at 60 Hz 2/1/2 and 2/0/2 -> 0/0/0 and 1/0/0 (game 2 seq
// 11568, thighs 1.5 cm inside, where every turn of the leg in the air pops
// its ankle), no other figure moved by more than its rounding. Bounds:
// 2/1/2 -> 1/0/0.
// The animator checks its blend over the whole frame (a search between six
// points), not at five points of it, and turns a leg 4 degrees at a time
// (anim/drawn_leg_clearance.cpp, 2026-11-29): summed over eight phases of
// the display (0, 0.1, 0.25, 0.35, 0.5, 0.6, 0.75, 0.85) too close 95 and 78
// -> 12 and 33 player-frames (game 2's thighs 16 -> 20, the worst at
// seven phases seq 496, which no turn within the bounds clears), ankle
// pops 3/0 -> 0/0; but at these points, which the old check sampled,
// 0/0/0 and 1/0/0 -> 0/1/0 and 2/0/1 (the old figure here was the
// favoured phase's). Bounds: 1/0/0 -> 2/1/1.
// A turn that clears counts only if the frame as the stream rounds it
// clears too, a refused step is tried at half its size, and whole-body
// actions are checked as well (2026-11-30): over the eight phases 12 and
// 33 -> 9 and 20, here 0/1/0 and 2/0/1 -> 0/0/0 and 1/0/1. Bounds:
// 2/1/1 -> 1/0/1.
// A foot left crossed behind the other by a fast turn uncrosses a pass
// length off instead of beside it (anim/footsteps.cpp, session 34): over
// the eight phases 3 and 18 -> 3 and 5, here 0/0/0 and 1/0/1 -> 0/0/0 and
// 0/0/1. Bounds: 1/0/1 -> 0/0/1.
// A foot's way checked past where the other one stood as the frame began,
// a landing foot's step bounded, the drawn travel held within 0.54 m and
// checked again after the last turn apart (session 34): 0/0/1 -> 0/0/0,
// issue 23's target at this phase. Bounds: 0/0/1 -> 0/0/0.
constexpr Bounds kAt60Hz{0.20, 0.5, 0.5, 0.5, 0.02, 0.03, 0, 60, 45, 45, 45, 0, 0, 0, 0, 0, 150, 0.02, 4.5,
                         -0.02, 0.31};

// At 60 Hz half a drawn frame later (t = 1/6, 1/2, 5/6 of each frame): a
// display's clock is not the stream's, so a viewer sees every phase, and
// the figures above, at the frames and their thirds, were the most
// favourable one while the animator checked its own frames at the same
// points (anim/drawn_leg_clearance.hpp). Measured 2026-11-29 (matchcast-anim-quality
// --draw-phase 0.5): the 8-9 m/s band 0.54/0.45, 9+ 0.49/0.52; thighs /
// shins / feet too close 0/1/10 and 2/0/6; a hand inside a thigh 1/1 (2.1
// and 3.6 cm); ankle pops 1/0. Issue 23's targets do not hold here yet; the
// bounds keep these figures from getting worse.
// With the blend checked over the whole frame (above): too close 0/1/10 and
// 2/0/6 -> 0/1/1 and 3/0/1, ankle pops 1/0 -> 0/0, the bands and hands as
// they were. Bounds: pops 1 -> 0, 2/1/10 -> 3/1/1.
// With the changes of 2026-11-30 (above): 0/1/1 and 3/0/1 -> 0/0/1 and
// 2/0/1 (game 1's shins were a tackle's, game 2's third thighs seq 496's).
// Bounds: 3/1/1 -> 2/0/1.
// A knee folding up to kMaxKneeStepDeg (2026-11-30, session 33): the 8-9
// m/s band 0.54/0.45 -> 0.51/0.42, 9+ 0.49/0.52 -> 0.47/0.48, too close
// 0/0/1 and 2/0/1 -> 0/0/0 and 1/0/1; with the kicking foot kept off the
// grass after its contact, 8-9 m/s 0.49/0.41 and 9+ 0.47/0.47: issue 23's
// 0.5 met. Bounds: bands 0.55/0.55 -> 0.50/0.50, 2/0/1 -> 1/0/1. With a
// hand's blend checked from 5 deg of turn and when it was near in the
// frame before: hands 1/1 (2.1, 3.6 cm) -> 0/0 (1.1, 1.1 cm). Bound 1 -> 0.
// With a crossed foot uncrossed a pass length off (session 34): 0/0/0 and
// 1/0/1 -> 0/0/0 and 0/0/0, issue 23's target at this phase. Bounds: 1/0/1
// -> 0/0/0: kAt60Hz's bounds, which the test holds it to.

// At the other six phases of anim/README.md's eight (0.1, 0.25, 0.35, 0.6,
// 0.75, 0.85), measured in session 34: every target held but the legs,
// 0/0/1 at most at a phase (game 1 at 0.85, game 2 at 0.35 and 0.85), 1
// and 2 player-frames summed over the eight phases. With the drawn check's
// search over every close stretch and about a turn of the feet's way
// (session 35, anim/drawn_leg_clearance.cpp): 0 and 0, every target at
// every phase, so kAt60Hz's bounds hold at all eight.
// Phase 0.45 (session 36): game 1's 8-9 m/s band was 0.51, over the 0.5
// (0.50 at 0.425; a scan of 40 phases found no other band over it). With a
// sprinter's swing kept up to 26 cm clear (swing_clearance.hpp) and a
// landing foot held back as the clients draw it (player_animation.cpp),
// 0.49 there and every band within 0.5 at all 40; so 0.45 is measured too.
// Phases 0.225, 0.375, 0.675 and 0.725 (session 37): on that scan, game 1
// still drew the legs too close in one player-frame at each (thighs seq
// 8801 left 8, -1.0 cm; feet seq 2194 right 2, 2429 right 8, 3629 left
// 6). With the clients' step parting the feet from each other's centre
// line (proto/SPEC.md 4.7 step 2) and the drawn-leg check drawing finely
// where that way turns 15 deg (drawn_leg_clearance.cpp), all 80
// measurements hold every target; these four are measured too, and 0.125,
// where the check with 30 deg turns of that way let game 2 seq 332 through
// (feet 1.2 cm inside each other).

void expect_within(const CloseUpReport& r, const Bounds& b, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_LE(band_mean(r, 0), b.stand_mps);
  double worst = 0;
  for (int band = 1; band + 1 < kSpeedBands; ++band) worst = std::max(worst, band_mean(r, band));
  EXPECT_LE(worst, b.moving_band_mps);
  EXPECT_LE(band_mean(r, kSpeedBands - 1), b.sprint_band_mps);
  double to_8 = 0;
  for (int band = 1; band + 2 < kSpeedBands; ++band) to_8 = std::max(to_8, band_mean(r, band));
  EXPECT_LE(to_8, b.to_8_band_mps);
  EXPECT_LE(r.kick_box_m.percentile(95), b.kick_p95_m);
  EXPECT_LE(r.kick_box_m.max(), b.kick_max_m);
  EXPECT_LE(r.kicks_inside, b.kicks_inside);
  EXPECT_LE(r.leg_step_deg.max(), b.leg_deg);
  EXPECT_LE(r.arm_step_deg.max(), b.arm_deg);
  EXPECT_LE(r.trunk_step_deg.max(), b.trunk_deg);
  EXPECT_LE(r.head_step_deg.max(), b.head_deg);
  EXPECT_LE(r.ankle_pops, b.ankle_pops);
  EXPECT_LE(r.thighs_close, b.thighs);
  EXPECT_LE(r.shins_close, b.shins);
  EXPECT_LE(r.feet_close, b.feet);
  EXPECT_LE(r.hands_inside, b.hands);
  EXPECT_LE(r.floating, b.floating);
  EXPECT_LE(r.ankle_limit_share, b.ankle_limit_share);
  EXPECT_LE(r.cadence.percentile(99), b.cadence_p99);
  // Issue 4's targets, which hold.
  EXPECT_LE(r.root_error_m.max(), 0.01);
  EXPECT_EQ(r.limit_violations, 0);
  EXPECT_GE(r.lowest_m, b.lowest_m);
  EXPECT_LE(r.step_in_m.max(), b.step_in_m);
}

void check_log(const char* name) {
  const std::string path = std::string(MATCHCAST_TEST_RCG_DIR) + "/full/" + name;
  std::string err;
  auto src = ingest::open_log(path, err);
  ASSERT_TRUE(src) << err;
  std::vector<WorldState> states;
  WorldState s;
  while (src->next(s)) states.push_back(s);
  ASSERT_GT(states.size(), 6000u);
  std::vector<PoseFrame> frames;
  std::vector<AnimEvent> events;
  Animator a(human_skeleton(), src->params());
  for (const WorldState& st : states) a.push(st, frames, &events);
  a.finish(frames, &events);
  ASSERT_EQ(frames.size(), 2 * states.size());
  StreamView view;
  ASSERT_TRUE(view_stream(human_skeleton(), src->params(), frames, events, view, err)) << err;
  // The close-up contact sheet a person can judge, beside the other tests' pictures.
  const std::string dir = std::string(MATCHCAST_SOURCE_DIR) + "/test-output/anim";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  ContactSheetRows rows;
  const std::string sheet = dir + "/contact-sheet-" + std::string(name).substr(0, 14) + ".png";
  EXPECT_TRUE(write_contact_sheet(view, sheet, rows, err)) << err;
  EXPECT_FALSE(rows.sprint.empty());
  EXPECT_FALSE(rows.kick.empty());
  EXPECT_FALSE(rows.turn.empty());
  const CloseUpReport r20 = measure_close_up(view, states, frames, 1);
  const CloseUpReport r60 = measure_close_up(view, states, frames, 3);
  const std::string table = std::string(name) + "\n" + format_close_up({&r20, &r60});
  expect_within(r20, kAt20Hz, "20 Hz\n" + table);
  expect_within(r60, kAt60Hz, "60 Hz\n" + table);
  const CloseUpReport half = measure_close_up(view, states, frames, 3, DrawnLegs::LegBlend, 0.5);
  // Drawn elsewhere: the same number of draws, but not the same poses (a
  // mean over thousands of other points could only match to the last bit
  // if the phase were left out).
  EXPECT_EQ(half.frames, r60.frames);
  EXPECT_NE(band_mean(half, 5), band_mean(r60, 5));
  expect_within(half, kAt60Hz, "60 Hz, half a drawn frame later\n" + format_close_up({&r20, &half}));
  // The display's other phases (anim/README.md measures these eight, and
  // 0.45, where the sprint bands came closest to the target, and the five
  // where legs came too close last): every target holds at each.
  for (double phase : {0.1, 0.125, 0.225, 0.25, 0.35, 0.375, 0.45, 0.6, 0.675, 0.725, 0.75, 0.85}) {
    const CloseUpReport r = measure_close_up(view, states, frames, 3, DrawnLegs::LegBlend, phase);
    expect_within(r, kAt60Hz, "60 Hz at phase " + std::to_string(phase) + "\n" + format_close_up({&r20, &r}));
  }
  EXPECT_GT(r20.kicks, 500);  // the game's kicks were found, animated and told
  EXPECT_GT(r20.cadence.values.size(), 10000u);
}

TEST(QualityFullGames, FiguresHoldOnTheFirstGame) { check_log("20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz"); }
TEST(QualityFullGames, FiguresHoldOnTheSecondGame) { check_log("20261122031059-HELIOS_A_4-vs-HELIOS_B_3.rcg.gz"); }

}  // namespace
}  // namespace mc::anim::tools

// A close-up contact sheet a person can judge (issue 23): one sprinting
// player, one kick and one turn on the spot, every frame of one second
// (20 frames), seen from the player's side, drawn from what a spectator
// receives (stream_view.hpp: decoded frames, the hello's skeleton). Feet on
// the grass are marked under the sole, so a foot that slides shows as marks
// that move.
#pragma once

#include <string>

#include "anim/tools/stream_view.hpp"

namespace mc::anim::tools {

struct ContactSheetRows {
  std::string sprint, kick, turn;  // "seq N, left 7" of each row's first frame, "" when none was found
};

// Finds the three moments in `view` and writes the sheet to `path` (PNG; the
// folder must exist). False with `error` when nothing could be drawn.
bool write_contact_sheet(const StreamView& view, const std::string& path, ContactSheetRows& rows, std::string& error);

}  // namespace mc::anim::tools

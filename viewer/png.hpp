// The viewer's screenshots use the project's one PNG module (libpng).
#pragma once

#include "anim/tools/png.hpp"

namespace mc::viewer {

using mc::anim::tools::Image;
using mc::anim::tools::read_png;
using mc::anim::tools::write_png;

}  // namespace mc::viewer

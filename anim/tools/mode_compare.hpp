// Two quality reports of the same log side by side (the quality tool's
// --compare: keyframe mode against mocap mode), one metric per line with its
// target and whether each mode meets it.
#pragma once

#include <string>

#include "anim/tools/metrics.hpp"

namespace mc::anim::tools {

std::string format_comparison(const QualityReport& keyframe, const QualityReport& mocap);

}  // namespace mc::anim::tools

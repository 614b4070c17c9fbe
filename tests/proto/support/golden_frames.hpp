// The inputs of the golden test vectors: scripted frames with the awkward
// cases mixed in (state change, teleport, ball kicked far, player leaving).
#pragma once

#include <vector>

#include "proto/frame_codec.hpp"
#include "proto/hello.hpp"

namespace mc::proto::testing {

inline constexpr int kGoldenFrameCount = 20;
inline constexpr int kGoldenKeyframeInterval = 8;

Hello golden_hello();
std::vector<PoseFrame> golden_frames(const SkeletonDef& skeleton);

}  // namespace mc::proto::testing

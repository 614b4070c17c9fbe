// Loads the animator's mocap mode (mocap_motion_source.hpp) from the CMU clip
// folder: the five kicks of subject 10 (cmu_10_01, 02, 03, 05, 06), resampled
// to 30 Hz. The caller hands the result to AnimConfig::motion_source.
#pragma once

#include <memory>
#include <string>

#include "anim/mocap/mocap_motion_source.hpp"

namespace mc::anim::mocap::io {

// Null with `error` set ("path:row:col: what") when a clip cannot be read.
std::shared_ptr<const MocapMotionSource> load_mocap_motion_source(const std::string& mocap_dir, std::string& error);

// The kicks and the slow walk: the motion graph of the whole clip set
// (asset_cache.hpp, cached in `cache_dir`, "" = none), walks starting on
// subject 10's walk at 1 m/s.
std::shared_ptr<const MocapMotionSource> load_mocap_motion_source_with_walk(const std::string& mocap_dir,
                                                                            const std::string& cache_dir,
                                                                            std::string& error);

}  // namespace mc::anim::mocap::io

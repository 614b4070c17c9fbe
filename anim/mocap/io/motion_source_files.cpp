#include "anim/mocap/io/motion_source_files.hpp"

#include <vector>

#include "anim/mocap/io/clip_files.hpp"

namespace mc::anim::mocap::io {

std::shared_ptr<const MocapMotionSource> load_mocap_motion_source(const std::string& mocap_dir, std::string& error) {
  static constexpr const char* kKicks[] = {"cmu_10_01.bvh", "cmu_10_02.bvh", "cmu_10_03.bvh", "cmu_10_05.bvh",
                                           "cmu_10_06.bvh"};
  std::vector<MocapClip> clips;
  for (const char* name : kKicks) {
    MocapClip raw;
    if (!load_bvh(mocap_dir + "/" + name, raw, error)) return nullptr;
    clips.push_back(resample(raw, 30));
  }
  auto source = std::make_shared<const MocapMotionSource>(std::move(clips));
  if (source->kick_count() == 0) {
    error = mocap_dir + ": no usable kick clip";
    return nullptr;
  }
  return source;
}

}  // namespace mc::anim::mocap::io

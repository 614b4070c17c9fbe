#include "anim/mocap/io/motion_source_files.hpp"

#include <vector>

#include "anim/mocap/io/asset_cache.hpp"
#include "anim/mocap/io/clip_files.hpp"

namespace mc::anim::mocap::io {

namespace {
bool load_kicks(const std::string& mocap_dir, std::vector<MocapClip>& clips, std::string& error) {
  static constexpr const char* kKicks[] = {"cmu_10_01.bvh", "cmu_10_02.bvh", "cmu_10_03.bvh", "cmu_10_05.bvh",
                                           "cmu_10_06.bvh"};
  for (const char* name : kKicks) {
    MocapClip raw;
    if (!load_bvh(mocap_dir + "/" + name, raw, error)) return false;
    clips.push_back(resample(raw, 30));
  }
  return true;
}
}  // namespace

std::shared_ptr<const MocapMotionSource> load_mocap_motion_source(const std::string& mocap_dir, std::string& error) {
  std::vector<MocapClip> clips;
  if (!load_kicks(mocap_dir, clips, error)) return nullptr;
  auto source = std::make_shared<const MocapMotionSource>(std::move(clips));
  if (source->kick_count() == 0) {
    error = mocap_dir + ": no usable kick clip";
    return nullptr;
  }
  return source;
}

}  // namespace mc::anim::mocap::io

namespace mc::anim::mocap::io {

std::shared_ptr<const MocapMotionSource> load_mocap_motion_source_with_walk(const std::string& mocap_dir,
                                                                            const std::string& cache_dir,
                                                                            std::string& error) {
  std::vector<MocapClip> kicks, clips;
  if (!load_kicks(mocap_dir, kicks, error)) return nullptr;
  AssetOptions o;
  o.clips.dir = mocap_dir;
  o.cache_dir = cache_dir;
  MocapAssets assets;
  if (!load_or_build_assets(o, assets, error)) return nullptr;
  std::uint64_t hash = 0;
  if (!load_cmu_clip_set(o.clips, clips, hash, error)) return nullptr;
  const int start = pick_start_node(assets.graph, o.start_clip, 1.0f);
  auto source = std::make_shared<const MocapMotionSource>(std::move(kicks), std::move(assets.graph), std::move(clips), start);
  if (source->kick_count() == 0 || !source->has_walk()) {
    error = mocap_dir + ": no usable kick clip or walk graph";
    return nullptr;
  }
  return source;
}

}  // namespace mc::anim::mocap::io

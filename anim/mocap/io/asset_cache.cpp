#include "anim/mocap/io/asset_cache.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "anim/mocap/mocap_blob.hpp"

namespace mc::anim::mocap::io {

int pick_start_node(const MotionGraph& g, const std::string& clip_name, float speed) {
  int best = -1;
  float best_err = 0;
  for (int i = 0; i < g.size(); ++i) {
    const auto& n = g.nodes[static_cast<std::size_t>(i)];
    if (g.clip_names[n.clip] != clip_name || n.frame < 15 || g.degree(i) == 0) continue;
    const float err = std::fabs(n.speed - speed);
    if (best < 0 || err < best_err) { best = i; best_err = err; }
  }
  return best;
}

namespace {

std::string params_key(const AssetOptions& o) {
  const auto& m = o.map;
  char buf[512];
  std::snprintf(buf, sizeof buf, "g%d/%.5f/%d m%d/%d/%.4f/%.4f/%.4f/%d/%d/%llu/%.4f/%.4f/%s/%d", o.graph.window,
                o.graph.threshold_rms, o.graph.min_frame_gap, m.grid.width, m.grid.height, m.grid.cell, m.grid.origin_x,
                m.grid.origin_y, m.max_depth, m.iterations, static_cast<unsigned long long>(m.seed), m.alpha, m.max_speed,
                o.start_clip.c_str(), m.start_node);
  std::string key = buf;
  for (auto b : m.obstacles) key += static_cast<char>('0' + b);
  return key;
}

void put_u32(std::string& s, std::uint32_t v) { s.append(reinterpret_cast<const char*>(&v), 4); }
bool get_u32(std::string_view s, std::size_t& p, std::uint32_t& v) {
  if (s.size() - p < 4) return false;
  std::memcpy(&v, s.data() + p, 4);
  p += 4;
  return true;
}

}  // namespace

bool load_or_build_assets(const AssetOptions& o, MocapAssets& a, std::string& error) {
  a = MocapAssets();
  std::vector<MocapClip> clips;
  std::uint64_t hash = 0;
  if (!load_cmu_clip_set(o.clips, clips, hash, error)) return false;
  hash = fnv1a64(params_key(o), hash);
  char name[64];
  std::snprintf(name, sizeof name, "mocap-%016llx.bin", static_cast<unsigned long long>(hash));
  if (!o.cache_dir.empty()) {
    a.cache_path = o.cache_dir + "/" + name;
    std::string bytes, ignored;
    if (read_file(a.cache_path, bytes, ignored)) {
      std::size_t p = 0;
      std::uint32_t gl = 0, ml = 0, start = 0;
      std::string why;
      if (get_u32(bytes, p, start) && get_u32(bytes, p, gl) && gl <= bytes.size() - p &&
          deserialize_graph(std::string_view(bytes).substr(p, gl), a.graph, why) && (p += gl, get_u32(bytes, p, ml)) &&
          ml == bytes.size() - p && deserialize_map(std::string_view(bytes).substr(p, ml), a.map, why) &&
          static_cast<int>(start) < a.graph.size()) {
        a.map_params = o.map;
        a.map_params.start_node = static_cast<int>(start);
        a.from_cache = true;
        return true;
      }
      std::fprintf(stderr, "mocap cache %s unusable (%s): rebuilding\n", a.cache_path.c_str(), why.c_str());
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  a.graph = build_motion_graph(clips, o.graph);
  const auto t1 = std::chrono::steady_clock::now();
  a.graph_seconds = std::chrono::duration<double>(t1 - t0).count();
  a.graph.stats.build_seconds = a.graph_seconds;
  a.map_params = o.map;
  if (a.map_params.start_node < 0) a.map_params.start_node = pick_start_node(a.graph, o.start_clip, 1.0f);
  if (a.map_params.start_node < 0) { error = "the start clip " + o.start_clip + " has no node in the pruned graph"; return false; }
  a.map = compute_capability_map(a.graph, a.map_params);
  a.map_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  if (!a.cache_path.empty()) {
    std::string bytes;
    const std::string g = serialize_graph(a.graph), m = serialize_map(a.map);
    put_u32(bytes, static_cast<std::uint32_t>(a.map_params.start_node));
    put_u32(bytes, static_cast<std::uint32_t>(g.size()));
    bytes += g;
    put_u32(bytes, static_cast<std::uint32_t>(m.size()));
    bytes += m;
    std::error_code ec;
    std::filesystem::create_directories(o.cache_dir, ec);
    std::string werr;
    if (!write_file(a.cache_path, bytes, werr)) std::fprintf(stderr, "mocap cache not written: %s\n", werr.c_str());
  }
  return true;
}

std::shared_ptr<const ReachModel> load_reach_model(const std::string& mocap_dir, const std::string& cache_dir,
                                                   std::string& error) {
  AssetOptions o;
  o.clips.dir = mocap_dir;
  o.map.start_node = -1;
  o.cache_dir = cache_dir;
  MocapAssets a;
  if (!load_or_build_assets(o, a, error)) return nullptr;
  return std::make_shared<const ReachModel>(make_reach_model(std::move(a.map), a.graph.hz));
}

}  // namespace mc::anim::mocap::io

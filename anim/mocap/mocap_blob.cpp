#include "anim/mocap/mocap_blob.hpp"

#include <cmath>
#include <cstring>

namespace mc::anim::mocap {

std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t h) {
  for (unsigned char c : bytes) { h ^= c; h *= 0x100000001b3ull; }
  return h;
}

namespace {

constexpr char kMagic[8] = {'M', 'C', 'G', 'R', 'A', 'P', 'H', '1'};
constexpr std::uint32_t kMaxCount = 50'000'000;

class Writer {
 public:
  template <class T> void put(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));  // the targets we build for are little-endian
    out.append(b, sizeof(T));
  }
  void str(const std::string& s) { put<std::uint32_t>(static_cast<std::uint32_t>(s.size())); out += s; }
  std::string out;
};

class Reader {
 public:
  explicit Reader(std::string_view b) : b_(b) {}
  template <class T> bool get(T& v) {
    if (b_.size() - p_ < sizeof(T)) return false;
    std::memcpy(&v, b_.data() + p_, sizeof(T));
    p_ += sizeof(T);
    return true;
  }
  bool str(std::string& s) {
    std::uint32_t n = 0;
    if (!get(n) || n > b_.size() - p_) return false;
    s.assign(b_.data() + p_, n);
    p_ += n;
    return true;
  }
  bool count(std::uint32_t& n, std::size_t item_bytes) {
    return get(n) && n <= kMaxCount && static_cast<std::size_t>(n) * item_bytes <= b_.size() - p_;
  }
  bool done() const { return p_ == b_.size(); }

 private:
  std::string_view b_;
  std::size_t p_ = 0;
};

}  // namespace

std::string serialize_graph(const MotionGraph& g) {
  Writer w;
  w.out.append(kMagic, sizeof(kMagic));
  w.put<float>(g.hz);
  w.put<std::int32_t>(g.window);
  const auto& s = g.stats;
  for (int v : {s.frames, s.natural_edges, s.transition_edges, s.components, s.nodes_after, s.edges_after, s.transitions_after})
    w.put<std::int32_t>(v);
  w.put<double>(s.build_seconds);
  w.put<std::uint32_t>(static_cast<std::uint32_t>(g.clip_names.size()));
  for (const auto& n : g.clip_names) w.str(n);
  w.put<std::uint32_t>(static_cast<std::uint32_t>(g.nodes.size()));
  for (const auto& n : g.nodes) {
    w.put<std::uint16_t>(n.clip);
    w.put<std::int32_t>(n.frame);
    w.put<float>(n.fwd); w.put<float>(n.right); w.put<float>(n.dyaw); w.put<float>(n.speed);
  }
  w.put<std::uint32_t>(static_cast<std::uint32_t>(g.targets.size()));
  for (std::size_t i = 0; i + 1 < g.first_edge.size(); ++i) w.put<std::uint32_t>(g.first_edge[i + 1]);
  for (std::size_t e = 0; e < g.targets.size(); ++e) {
    w.put<std::uint32_t>(g.targets[e]);
    w.put<std::uint8_t>(g.transition[e]);
  }
  return w.out;
}

bool deserialize_graph(std::string_view bytes, MotionGraph& g, std::string& error) {
  g = MotionGraph();
  auto bad = [&](const char* what) { error = std::string("graph blob: ") + what; g = MotionGraph(); return false; };
  if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0) return bad("bad magic");
  Reader r(bytes.substr(sizeof(kMagic)));
  std::int32_t window = 0;
  if (!r.get(g.hz) || !r.get(window) || !(g.hz > 0 && g.hz < 1000) || window < 1 || window > 1000) return bad("bad header");
  g.window = window;
  auto& s = g.stats;
  for (int* v : {&s.frames, &s.natural_edges, &s.transition_edges, &s.components, &s.nodes_after, &s.edges_after, &s.transitions_after})
    if (!r.get(*v)) return bad("truncated stats");
  if (!r.get(s.build_seconds)) return bad("truncated stats");
  std::uint32_t n = 0;
  if (!r.count(n, 4)) return bad("bad clip count");
  g.clip_names.resize(n);
  for (auto& c : g.clip_names)
    if (!r.str(c)) return bad("truncated clip name");
  if (!r.count(n, 22)) return bad("bad node count");
  g.nodes.resize(n);
  for (auto& node : g.nodes) {
    if (!r.get(node.clip) || !r.get(node.frame) || !r.get(node.fwd) || !r.get(node.right) || !r.get(node.dyaw) ||
        !r.get(node.speed))
      return bad("truncated node");
    if (node.clip >= g.clip_names.size()) return bad("node names an unknown clip");
  }
  std::uint32_t edges = 0;
  if (!r.get(edges) || edges > kMaxCount) return bad("bad edge count");
  g.first_edge.assign(1, 0);
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    std::uint32_t f = 0;
    if (!r.get(f)) return bad("truncated edge offsets");
    if (f < g.first_edge.back() || f > edges) return bad("edge offsets out of order");
    g.first_edge.push_back(f);
  }
  if (g.first_edge.back() != edges) return bad("edge offsets do not end at the edge count");
  g.targets.resize(edges);
  g.transition.resize(edges);
  for (std::uint32_t e = 0; e < edges; ++e) {
    if (!r.get(g.targets[e]) || !r.get(g.transition[e])) return bad("truncated edges");
    if (g.targets[e] >= g.nodes.size()) return bad("edge to a node that does not exist");
  }
  if (!r.done()) return bad("trailing bytes");
  return true;
}

}  // namespace mc::anim::mocap

#include "anim/mocap/capability_map.hpp"

namespace mc::anim::mocap {

namespace {
constexpr char kMapMagic[8] = {'M', 'C', 'C', 'M', 'A', 'P', '0', '1'};
}

std::string serialize_map(const CapabilityMap& m) {
  Writer w;
  w.out.append(kMapMagic, sizeof(kMapMagic));
  w.put<std::int32_t>(m.grid.width);
  w.put<std::int32_t>(m.grid.height);
  w.put<float>(m.grid.cell);
  w.put<float>(m.grid.origin_x);
  w.put<float>(m.grid.origin_y);
  w.put<std::int32_t>(m.iterations);
  for (float c : m.cost) w.put<float>(c);
  return w.out;
}

bool deserialize_map(std::string_view bytes, CapabilityMap& m, std::string& error) {
  m = CapabilityMap();
  auto bad = [&](const char* what) { error = std::string("map blob: ") + what; m = CapabilityMap(); return false; };
  if (bytes.size() < sizeof(kMapMagic) || std::memcmp(bytes.data(), kMapMagic, sizeof(kMapMagic)) != 0) return bad("bad magic");
  Reader r(bytes.substr(sizeof(kMapMagic)));
  if (!r.get(m.grid.width) || !r.get(m.grid.height) || !r.get(m.grid.cell) || !r.get(m.grid.origin_x) ||
      !r.get(m.grid.origin_y) || !r.get(m.iterations))
    return bad("truncated header");
  if (m.grid.width < 1 || m.grid.height < 1 || m.grid.width > 4096 || m.grid.height > 4096 || !(m.grid.cell > 0) ||
      !std::isfinite(m.grid.origin_x) || !std::isfinite(m.grid.origin_y) || !std::isfinite(m.grid.cell))
    return bad("bad grid");
  m.cost.resize(static_cast<std::size_t>(m.grid.cells()));
  for (auto& c : m.cost)
    if (!r.get(c) || std::isnan(c) || c < 0) return bad("bad or truncated costs");
  if (!r.done()) return bad("trailing bytes");
  m.best_iteration.assign(m.cost.size(), 0);
  m.best_step.assign(m.cost.size(), 0);
  return true;
}

}  // namespace mc::anim::mocap

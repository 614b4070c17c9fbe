#include "anim/mocap/capability_map.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

namespace mc::anim::mocap {

int MapGrid::index(float x, float y) const {
  const float fx = (x - origin_x) / cell, fy = (y - origin_y) / cell;
  if (!(fx >= 0 && fy >= 0 && fx < static_cast<float>(width) && fy < static_cast<float>(height))) return -1;
  return static_cast<int>(fy) * width + static_cast<int>(fx);
}

WalkRng::WalkRng(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ull * (stream + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  s_ = (z ^ (z >> 31)) | 1;
}

std::uint64_t WalkRng::next() {
  s_ ^= s_ << 13;
  s_ ^= s_ >> 7;
  s_ ^= s_ << 17;
  return s_ * 0x2545f4914f6cdd1dull;
}

int CapabilityMap::reached() const {
  return static_cast<int>(std::count_if(cost.begin(), cost.end(), [](float c) { return c != kUnreached; }));
}

int CapabilityMap::converged_iteration(double fraction) const {
  std::vector<std::uint32_t> its;
  for (std::size_t i = 0; i < cost.size(); ++i)
    if (cost[i] != kUnreached) its.push_back(best_iteration[i] + 1);
  if (its.empty()) return 0;
  std::sort(its.begin(), its.end());
  const auto k = static_cast<std::size_t>(std::ceil(fraction * static_cast<double>(its.size()))) - 1;
  return static_cast<int>(its[std::min(k, its.size() - 1)]);
}

namespace {

// One walk; calls visit(step, node, x, y) after every step; stops when visit
// returns false, at a node with no enabled exit, or at max_depth.
template <class Visit>
void walk(const MotionGraph& g, const CapabilityParams& p, std::uint32_t iteration, Visit&& visit) {
  WalkRng rng(p.seed, iteration);
  std::uint32_t node = static_cast<std::uint32_t>(p.start_node);
  float x = 0, y = 0, c = 1, s = 0;  // position, heading (cos, sin)
  std::uint32_t enabled[64];
  for (int step = 1; step <= p.max_depth; ++step) {
    const std::uint32_t b = g.first_edge[node], e = g.first_edge[node + 1];
    std::uint32_t n = 0;
    for (std::uint32_t k = b; k < e && n < 64; ++k)
      if (p.max_speed <= 0 || g.nodes[g.targets[k]].speed <= p.max_speed) enabled[n++] = g.targets[k];
    if (n == 0) return;
    node = n == 1 ? enabled[0] : enabled[rng.below(n)];
    const GraphNode& v = g.nodes[node];
    x += v.fwd * c - v.right * s;
    y += v.fwd * s + v.right * c;
    const float cy = std::cos(v.dyaw), sy = std::sin(v.dyaw);
    const float nc = c * cy - s * sy;
    s = s * cy + c * sy;
    c = nc;
    if (!visit(step, node, x, y)) return;
  }
}

}  // namespace

CapabilityMap compute_capability_map(const MotionGraph& g, const CapabilityParams& p) {
  CapabilityMap m;
  m.grid = p.grid;
  const auto cells = static_cast<std::size_t>(p.grid.cells());
  m.cost.assign(cells, kUnreached);
  m.best_iteration.assign(cells, 0);
  m.best_step.assign(cells, 0);
  if (g.size() == 0 || p.start_node < 0 || p.start_node >= g.size()) return m;
  const bool obstacles = p.obstacles.size() == cells;
  int improved = 0;
  for (int it = 0; it < p.iterations; ++it) {
    walk(g, p, static_cast<std::uint32_t>(it), [&](int step, std::uint32_t, float x, float y) {
      ++m.steps;
      const int cell = m.grid.index(x, y);
      if (cell < 0) return true;  // off the map: the walk may come back
      const auto ci = static_cast<std::size_t>(cell);
      if (obstacles && p.obstacles[ci]) { ++m.pruned_by_obstacles; return false; }
      float cost = static_cast<float>(step);
      if (p.alpha > 0) {
        const float dx = x - m.grid.center_x(cell), dy = y - m.grid.center_y(cell);
        cost += p.alpha * (dx * dx + dy * dy);
      }
      if (cost < m.cost[ci]) {
        ++improved;
        m.cost[ci] = cost;
        m.best_iteration[ci] = static_cast<std::uint32_t>(it);
        m.best_step[ci] = static_cast<std::uint16_t>(std::min(step, 65535));
      }
      return true;
    });
    m.iterations = it + 1;
    if (p.checkpoint_every > 0 && (m.iterations % p.checkpoint_every == 0 || m.iterations == p.iterations)) {
      m.checkpoint_iteration.push_back(m.iterations);
      m.checkpoint_improved.push_back(improved);
      improved = 0;
      for (int t : p.tracked_cells)
        m.tracked_history.push_back(t >= 0 && static_cast<std::size_t>(t) < cells ? m.cost[static_cast<std::size_t>(t)] : kUnreached);
    }
  }
  return m;
}

std::vector<int> cell_path(const MotionGraph& g, const CapabilityParams& p, const CapabilityMap& m, int cell) {
  std::vector<int> path;
  if (cell < 0 || static_cast<std::size_t>(cell) >= m.cost.size() || m.cost[static_cast<std::size_t>(cell)] == kUnreached) return path;
  const int last = m.best_step[static_cast<std::size_t>(cell)];
  path.push_back(p.start_node);
  walk(g, p, m.best_iteration[static_cast<std::size_t>(cell)], [&](int step, std::uint32_t node, float, float) {
    path.push_back(static_cast<int>(node));
    return step < last;
  });
  return path;
}

std::vector<std::uint32_t> iterations_within(const MotionGraph& g, const CapabilityParams& p, const CapabilityMap& fin,
                                             float tolerance) {
  const std::size_t cells = fin.cost.size();
  std::vector<std::uint32_t> out(cells, 0);
  if (g.size() == 0 || p.start_node < 0 || p.start_node >= g.size()) return out;
  std::vector<float> cost(cells, kUnreached);
  const bool obstacles = p.obstacles.size() == cells;
  for (int it = 0; it < fin.iterations; ++it) {
    walk(g, p, static_cast<std::uint32_t>(it), [&](int step, std::uint32_t, float x, float y) {
      const int cell = fin.grid.index(x, y);
      if (cell < 0) return true;
      const auto ci = static_cast<std::size_t>(cell);
      if (obstacles && p.obstacles[ci]) return false;
      float c = static_cast<float>(step);
      if (p.alpha > 0) {
        const float dx = x - fin.grid.center_x(cell), dy = y - fin.grid.center_y(cell);
        c += p.alpha * (dx * dx + dy * dy);
      }
      if (c < cost[ci]) {
        cost[ci] = c;
        if (out[ci] == 0 && fin.cost[ci] != kUnreached && c <= fin.cost[ci] * (1 + tolerance))
          out[ci] = static_cast<std::uint32_t>(it + 1);
      }
      return true;
    });
  }
  return out;
}

std::uint32_t iteration_quantile(std::vector<std::uint32_t> its, double fraction) {
  its.erase(std::remove(its.begin(), its.end(), 0u), its.end());
  if (its.empty()) return 0;
  std::sort(its.begin(), its.end());
  const auto k = static_cast<std::size_t>(std::ceil(fraction * static_cast<double>(its.size())));
  return its[std::min(its.size() - 1, k > 0 ? k - 1 : 0)];
}

std::vector<float> grassfire(const MapGrid& grid, const std::vector<std::uint8_t>& obstacles) {
  const auto cells = static_cast<std::size_t>(grid.cells());
  std::vector<float> d(cells, kUnreached);
  const int start = grid.index(0, 0);
  if (start < 0) return d;
  const bool obs = obstacles.size() == cells;
  using Item = std::pair<float, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> q;
  d[static_cast<std::size_t>(start)] = 0;
  q.push({0.0f, start});
  const float diag = grid.cell * std::sqrt(2.0f);
  while (!q.empty()) {
    const auto [dist, i] = q.top();
    q.pop();
    if (dist > d[static_cast<std::size_t>(i)]) continue;
    const int cx = i % grid.width, cy = i / grid.width;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (!dx && !dy) continue;
        const int nx = cx + dx, ny = cy + dy;
        if (nx < 0 || ny < 0 || nx >= grid.width || ny >= grid.height) continue;
        const int n = ny * grid.width + nx;
        if (obs && obstacles[static_cast<std::size_t>(n)]) continue;
        const float nd = dist + (dx && dy ? diag : grid.cell);
        if (nd < d[static_cast<std::size_t>(n)]) { d[static_cast<std::size_t>(n)] = nd; q.push({nd, n}); }
      }
  }
  return d;
}

}  // namespace mc::anim::mocap

#include "anim/mocap/motion_graph.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "anim/mocap/frame_distance.hpp"

namespace mc::anim::mocap {

int MotionGraph::find(int clip, int frame) const {
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].clip == clip && nodes[i].frame == frame) return static_cast<int>(i);
  return -1;
}

std::vector<GraphNode> clip_ground_motion(const MocapClip& clip, std::uint16_t clip_index) {
  const int lh = clip.skeleton.find("LeftUpLeg"), rh = clip.skeleton.find("RightUpLeg");
  std::vector<GraphNode> out(static_cast<std::size_t>(clip.frames));
  std::vector<glm::vec2> pos(out.size()), face(out.size());
  std::vector<glm::vec3> p;
  for (int f = 0; f < clip.frames; ++f) {
    forward_kinematics(clip, f, p);
    const auto k = static_cast<std::size_t>(f);
    pos[k] = {clip.root_position[k].x, clip.root_position[k].z};
    face[k] = (lh >= 0 && rh >= 0) ? facing_xz(p, lh, rh) : glm::vec2(0, 1);
  }
  const int h = std::max(1, static_cast<int>(std::lround(0.25 / clip.frame_time)));
  for (int f = 0; f < clip.frames; ++f) {
    auto& n = out[static_cast<std::size_t>(f)];
    n.clip = clip_index;
    n.frame = f;
    const int a = std::max(0, f - h), b = std::min(clip.frames - 1, f + h);
    if (b > a)
      n.speed = static_cast<float>(glm::length(pos[static_cast<std::size_t>(b)] - pos[static_cast<std::size_t>(a)]) /
                                   ((b - a) * clip.frame_time));
    if (f == 0) continue;
    const glm::vec2 fp = face[static_cast<std::size_t>(f - 1)];
    const glm::vec2 rp(-fp.y, fp.x);  // the right of a facing (x, z): facing +Z has its right at -X
    const glm::vec2 d = pos[static_cast<std::size_t>(f)] - pos[static_cast<std::size_t>(f - 1)];
    n.fwd = glm::dot(d, fp);
    n.right = glm::dot(d, rp);
    const glm::vec2 fc = face[static_cast<std::size_t>(f)];
    n.dyaw = std::atan2(glm::dot(fc, rp), glm::dot(fc, fp));
  }
  return out;
}

int strongly_connected_components(const std::vector<std::uint32_t>& first_edge,
                                  const std::vector<std::uint32_t>& targets, std::vector<int>& comp) {
  const std::size_t n = first_edge.empty() ? 0 : first_edge.size() - 1;
  comp.assign(n, -1);
  std::vector<int> index(n, -1), low(n, 0);
  std::vector<bool> on_stack(n, false);
  std::vector<std::uint32_t> stack;                       // Tarjan's node stack
  std::vector<std::pair<std::uint32_t, std::uint32_t>> call;  // (node, next edge): the explicit DFS stack
  int next_index = 0, count = 0;
  for (std::uint32_t root = 0; root < n; ++root) {
    if (index[root] >= 0) continue;
    call.emplace_back(root, first_edge[root]);
    index[root] = low[root] = next_index++;
    stack.push_back(root);
    on_stack[root] = true;
    while (!call.empty()) {
      auto& [v, e] = call.back();
      if (e < first_edge[v + 1]) {
        const std::uint32_t w = targets[e++];
        if (index[w] < 0) {
          index[w] = low[w] = next_index++;
          stack.push_back(w);
          on_stack[w] = true;
          call.emplace_back(w, first_edge[w]);  // invalidates v, e: loop re-reads back()
        } else if (on_stack[w]) {
          low[v] = std::min(low[v], index[w]);
        }
        continue;
      }
      const std::uint32_t done = v;
      call.pop_back();
      if (!call.empty()) low[call.back().first] = std::min(low[call.back().first], low[done]);
      if (low[done] == index[done]) {
        std::uint32_t w;
        do {
          w = stack.back();
          stack.pop_back();
          on_stack[w] = false;
          comp[w] = count;
        } while (w != done);
        ++count;
      }
    }
  }
  return count;
}

void keep_largest_scc(MotionGraph& g) {
  std::vector<int> comp;
  const int count = strongly_connected_components(g.first_edge, g.targets, comp);
  g.stats.components = count;
  std::vector<int> sizes(static_cast<std::size_t>(std::max(count, 1)), 0);
  for (int c : comp) ++sizes[static_cast<std::size_t>(c)];
  const int keep = static_cast<int>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  std::vector<int> renum(g.nodes.size(), -1);
  std::vector<GraphNode> nodes;
  for (std::size_t i = 0; i < g.nodes.size(); ++i)
    if (comp[i] == keep) { renum[i] = static_cast<int>(nodes.size()); nodes.push_back(g.nodes[i]); }
  std::vector<std::uint32_t> first{0}, targets;
  std::vector<std::uint8_t> trans;
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    if (renum[i] < 0) continue;
    for (auto e = g.first_edge[i]; e < g.first_edge[i + 1]; ++e) {
      const int t = renum[g.targets[e]];
      if (t < 0) continue;
      targets.push_back(static_cast<std::uint32_t>(t));
      trans.push_back(g.transition[e]);
    }
    first.push_back(static_cast<std::uint32_t>(targets.size()));
  }
  g.nodes = std::move(nodes);
  g.first_edge = std::move(first);
  g.targets = std::move(targets);
  g.transition = std::move(trans);
  g.stats.nodes_after = g.size();
  g.stats.edges_after = static_cast<int>(g.targets.size());
  g.stats.transitions_after = static_cast<int>(std::count(g.transition.begin(), g.transition.end(), 1));
}

MotionGraph build_motion_graph(const std::vector<MocapClip>& clips, const GraphBuildParams& prm) {
  MotionGraph g;
  g.window = prm.window;
  if (clips.empty()) { g.first_edge = {0}; return g; }
  g.hz = static_cast<float>(1.0 / clips.front().frame_time);
  const std::vector<int> joints = cloud_joints(clips.front().skeleton);
  const int J = static_cast<int>(joints.size());
  const int WS = std::max(1, prm.window);
  const int len = WS * J;
  // Nodes (every frame of every clip) and the windows that fit in their clip.
  std::vector<int> clip_first;  // first global node of each clip
  struct Win { int node; int clip; int frame; };
  std::vector<Win> wins;
  for (std::size_t c = 0; c < clips.size(); ++c) {
    g.clip_names.push_back(clips[c].name);
    clip_first.push_back(g.size());
    const auto gm = clip_ground_motion(clips[c], static_cast<std::uint16_t>(c));
    g.nodes.insert(g.nodes.end(), gm.begin(), gm.end());
    for (int f = 0; f + WS < clips[c].frames; ++f) wins.push_back({clip_first.back() + f, static_cast<int>(c), f});
  }
  g.stats.frames = g.size();
  // Window clouds, each centred on its own x/z mean so that float sums stay
  // accurate; uniform joint weights.
  const std::size_t nw = wins.size();
  std::vector<float> wx(nw * static_cast<std::size_t>(len)), wy(wx.size()), wz(wx.size());
  std::vector<float> weight(static_cast<std::size_t>(len), 1.0f);
  std::vector<WindowSums> sums(nw);
  {
    std::vector<FrameClouds> fc;
    for (const auto& c : clips) {
      // Same joints by name: skeletons from different formats order them differently.
      std::vector<int> mine;
      for (int j : joints) mine.push_back(std::max(0, c.skeleton.find(clips.front().skeleton.names[static_cast<std::size_t>(j)])));
      fc.push_back(make_frame_clouds(c, mine));
    }
    for (std::size_t k = 0; k < nw; ++k) {
      const auto& cl = fc[static_cast<std::size_t>(wins[k].clip)];
      const std::size_t src = static_cast<std::size_t>(wins[k].frame) * static_cast<std::size_t>(J);
      const std::size_t dst = k * static_cast<std::size_t>(len);
      double mx = 0, mz = 0;
      for (int i = 0; i < len; ++i) { mx += cl.x[src + static_cast<std::size_t>(i)]; mz += cl.z[src + static_cast<std::size_t>(i)]; }
      mx /= len; mz /= len;
      for (int i = 0; i < len; ++i) {
        wx[dst + static_cast<std::size_t>(i)] = static_cast<float>(cl.x[src + static_cast<std::size_t>(i)] - mx);
        wy[dst + static_cast<std::size_t>(i)] = cl.y[src + static_cast<std::size_t>(i)];
        wz[dst + static_cast<std::size_t>(i)] = static_cast<float>(cl.z[src + static_cast<std::size_t>(i)] - mz);
      }
      sums[k] = window_sums(wx.data(), wy.data(), wz.data(), weight.data(), dst, len);
    }
  }
  // Full matrix of RMS distances (symmetric: the upper triangle is computed).
  std::vector<float> dist(nw * nw, 0.0f);
  for (std::size_t a = 0; a < nw; ++a) {
    for (std::size_t b = a + 1; b < nw; ++b) {
      const double d = window_distance(wx.data(), wy.data(), wz.data(), weight.data(), a * static_cast<std::size_t>(len),
                                       b * static_cast<std::size_t>(len), len, sums[a], sums[b]);
      const float r = static_cast<float>(std::sqrt(d / sums[a].w));
      dist[a * nw + b] = r;
      dist[b * nw + a] = r;
    }
  }
  // Transitions at local minima under the threshold.
  auto same_clip_next = [&](std::size_t k, int step) -> long {
    const long m = static_cast<long>(k) + step;
    if (m < 0 || m >= static_cast<long>(nw) || wins[static_cast<std::size_t>(m)].clip != wins[k].clip) return -1;
    return m;
  };
  std::vector<std::vector<std::uint32_t>> out(g.nodes.size());
  std::vector<std::vector<std::uint8_t>> out_t(g.nodes.size());
  for (std::size_t c = 0; c < clips.size(); ++c)
    for (int f = 0; f + 1 < clips[c].frames; ++f) {
      const auto n = static_cast<std::size_t>(clip_first[c] + f);
      out[n].push_back(static_cast<std::uint32_t>(n + 1));
      out_t[n].push_back(0);
      ++g.stats.natural_edges;
    }
  for (std::size_t a = 0; a < nw; ++a) {
    for (std::size_t b = a + 1; b < nw; ++b) {
      const float d = dist[a * nw + b];
      if (d >= prm.threshold_rms) continue;
      if (wins[a].clip == wins[b].clip && std::abs(wins[a].frame - wins[b].frame) < prm.min_frame_gap) continue;
      bool minimum = true;
      for (int da = -1; da <= 1 && minimum; ++da)
        for (int db = -1; db <= 1 && minimum; ++db) {
          if (da == 0 && db == 0) continue;
          const long na = same_clip_next(a, da), nb = same_clip_next(b, db);
          if (na < 0 || nb < 0 || na == nb) continue;
          if (dist[static_cast<std::size_t>(na) * nw + static_cast<std::size_t>(nb)] < d) minimum = false;
        }
      if (!minimum) continue;
      // i -> j+1 and j -> i+1: after frame i the motion continues as j's successor.
      const auto i = static_cast<std::size_t>(wins[a].node), j = static_cast<std::size_t>(wins[b].node);
      out[i].push_back(static_cast<std::uint32_t>(j + 1)); out_t[i].push_back(1);
      out[j].push_back(static_cast<std::uint32_t>(i + 1)); out_t[j].push_back(1);
      g.stats.transition_edges += 2;
    }
  }
  g.first_edge.assign(1, 0);
  for (std::size_t n = 0; n < out.size(); ++n) {
    g.targets.insert(g.targets.end(), out[n].begin(), out[n].end());
    g.transition.insert(g.transition.end(), out_t[n].begin(), out_t[n].end());
    g.first_edge.push_back(static_cast<std::uint32_t>(g.targets.size()));
  }
  keep_largest_scc(g);
  return g;
}

}  // namespace mc::anim::mocap

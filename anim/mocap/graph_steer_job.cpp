#include "anim/mocap/graph_steer_job.hpp"

namespace mc::anim::mocap {

namespace {
// The clip's own next frame of `n` (its non-transition edge), or -1.
int natural_next(const MotionGraph& g, std::uint32_t n) {
  for (auto e = g.first_edge[n]; e < g.first_edge[n + 1]; ++e)
    if (!g.transition[e]) return static_cast<int>(g.targets[e]);
  return -1;
}
}  // namespace

bool GraphSteerJob::Validate() const {
  if (!graph || !next || lookahead < 1 || node < 0 || node >= graph->size()) return false;
  return graph->degree(node) > 0;
}

bool GraphSteerJob::Run() const {
  if (!Validate()) return false;
  const MotionGraph& g = *graph;
  const auto n = static_cast<std::uint32_t>(node);
  float best = 0;
  int chosen = -1;
  bool chosen_transition = false;
  for (auto e = g.first_edge[n]; e < g.first_edge[n + 1]; ++e) {
    // Average ground motion over the successor and the frames after it.
    double fwd = 0, turn = 0;
    int frames = 0;
    for (int v = static_cast<int>(g.targets[e]); v >= 0 && frames < lookahead; v = natural_next(g, static_cast<std::uint32_t>(v))) {
      fwd += g.nodes[static_cast<std::size_t>(v)].fwd;
      turn += g.nodes[static_cast<std::size_t>(v)].dyaw;
      ++frames;
    }
    const double speed = fwd / frames * g.hz, rate = turn / frames * g.hz;
    const float cost = static_cast<float>((speed - want_speed) * (speed - want_speed) +
                                          turn_weight * (rate - want_turn) * (rate - want_turn));
    const bool is_transition = g.transition[e] != 0;
    const bool better = chosen < 0 || cost < best ||
                        (cost == best && chosen_transition && !is_transition) ||
                        (cost == best && is_transition == chosen_transition && static_cast<int>(g.targets[e]) < chosen);
    if (better) { best = cost; chosen = static_cast<int>(g.targets[e]); chosen_transition = is_transition; }
  }
  *next = chosen;
  if (transition) *transition = chosen_transition;
  return true;
}

}  // namespace mc::anim::mocap

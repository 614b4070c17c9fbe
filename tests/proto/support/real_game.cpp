#include "tests/proto/support/real_game.hpp"

#include "server/ingest/state_source.hpp"
#include "tests/proto/support/synthetic.hpp"

#ifdef MATCHCAST_HAVE_ANIMATOR
#include "anim/animator.hpp"
#include "anim/human_skeleton.hpp"
#endif

namespace mc::proto::testing {

std::string default_full_game_log() {
  return std::string(MATCHCAST_SHARED_DIR) + "/data/rcg/full/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz";
}

bool load_real_game(const std::string& log_path, bool prefer_animator, std::size_t max_states, RealGame& out,
                    std::string& error) {
  auto source = ingest::open_log(log_path, error);
  if (!source) return false;
  std::vector<WorldState> states;
  WorldState s;
  while ((max_states == 0 || states.size() < max_states) && source->next(s)) states.push_back(s);
  if (states.size() < 2) {
    error = "log has fewer than 2 states: " + log_path;
    return false;
  }
  out.left_name = states.back().left.name;
  out.right_name = states.back().right.name;
  out.frames.clear();
#ifdef MATCHCAST_HAVE_ANIMATOR
  if (prefer_animator) {
    out.skeleton = anim::human_skeleton();
    out.animated_by = "anim::Animator";
    anim::Animator animator(out.skeleton, source->params());
    for (const auto& st : states) animator.push(st, out.frames);
    animator.finish(out.frames);
    return true;
  }
#else
  (void)prefer_animator;
#endif
  out.skeleton = humanoid_skeleton();
  out.animated_by = "GaitSynth";
  GaitSynth synth(out.skeleton);
  for (std::size_t i = 0; i < states.size(); ++i) synth.add(states[i], states[std::min(i + 1, states.size() - 1)], out.frames);
  return true;
}

}  // namespace mc::proto::testing

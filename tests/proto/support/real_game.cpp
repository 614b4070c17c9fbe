#include "tests/proto/support/real_game.hpp"

#include <algorithm>
#include <iterator>

#include "server/ingest/state_source.hpp"
#include "tests/proto/support/synthetic.hpp"

#ifdef MATCHCAST_HAVE_ANIMATOR
#include "anim/animator.hpp"
#include "anim/event_messages.hpp"
#include "proto/control_messages.hpp"
#include "anim/human_skeleton.hpp"
#endif

namespace mc::proto::testing {

std::string default_full_game_log() {
  return std::string(MATCHCAST_TEST_RCG_DIR) + "/full/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz";
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
    std::vector<anim::FrameInfo> infos;
    animator.set_frame_info_sink(&infos);
    std::vector<anim::AnimEvent> events;
    std::vector<std::pair<int, StaminaUpdate>> stamina;  // (state time, update): once every 10 states
    for (std::size_t i = 0; i < states.size(); ++i) {
      if (i % 10 == 0) stamina.emplace_back(states[i].time, stamina_update(states[i]));
      animator.push(states[i], out.frames, &events);
    }
    animator.finish(out.frames, &events);
    out.contacts.clear();
    if (infos.size() == out.frames.size()) {
      out.contacts.reserve(infos.size() * kMaxPlayers);
      for (const anim::FrameInfo& fi : infos)
        for (const anim::PlayerFrameInfo& p : fi.players)
          out.contacts.push_back(static_cast<std::uint8_t>((p.planted[0] ? 1 : 0) | (p.planted[1] ? 2 : 0)));
    }
    // As server/app/log_feed.cpp sends them: an event just before the first
    // frame at or after its seq, then a stamina update just before the first
    // frame of its state, numbered as that frame.
    std::vector<std::pair<std::size_t, std::string>> by_event, by_time;
    std::size_t f = 0;
    for (const auto& e : events) {
      if (e.type == anim::AnimEventType::Card && e.card == anim::Card::None) continue;
      while (f < out.frames.size() && out.frames[f].seq < e.seq) ++f;
      by_event.emplace_back(f, to_json(anim::to_control_message(e)));
    }
    f = 0;
    for (auto& [time, u] : stamina) {
      while (f < out.frames.size() && out.frames[f].time < time) ++f;
      u.seq = f < out.frames.size() ? out.frames[f].seq : 0;
      by_time.emplace_back(f, to_json(ControlMessage{u}));
    }
    out.controls.clear();
    std::merge(by_event.begin(), by_event.end(), by_time.begin(), by_time.end(), std::back_inserter(out.controls),
               [](const auto& a, const auto& b) { return a.first < b.first; });
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

// matchcast-anim-quality: animates whole logs and measures what a spectator
// receives (issue 23, close_up_metrics.hpp): the frames encoded and decoded,
// posed on the hello's skeleton, at 20 Hz and at the clients' drawing rate;
// each figure with its target. Then it writes a picture of one player's kick
// and run.
//
//   matchcast-anim-quality [--mode keyframe|mocap] [--compare] [--mocap-dir DIR] [--mocap-cache DIR]
//                          [--png FILE] [--contact-sheet FILE] [--draw-rate HZ] [--draw-phase F]
//                          [--lookahead N] [--detail none|run|kick|full] [--leg-blend none] LOG...
//
// --mode mocap takes the kicks and slow walking from the CMU clips
// (anim/motion_source.hpp; the motion graph is cached in --mocap-cache);
// --compare animates each log in both modes and prints the metrics side by
// side (the picture then shows the mocap mode). --draw-rate: the clients'
// drawing rate measured beside the 20 Hz frames (a multiple of 20, default 60);
// --draw-phase: where its draws fall, a fraction of one drawn frame past
// each 20 Hz frame (0 <= F < 1, default 0: on the frames and the thirds; a
// display's clock is not the stream's, so a viewer sees every phase);
// drawn as the clients draw it (the angle blend, then the feet and the legs
// kept apart, anim/leg_blend.hpp); --leg-blend none leaves that step out, to
// measure what it gives. MATCHCAST_CLOSEUP_BREAKDOWN=1 sorts the
// drawn frames' sliding by the 20 Hz feet around them and by the foot's
// own speed (stderr).
// --contact-sheet: the close-up contact sheet of the first log (a sprint, a
// kick, a turn, every frame of a second, contact_sheet.hpp), default
// test-output/anim/contact-sheet.png.
//
// Exit status 0 when every target holds on every log, 1 otherwise, 2 on bad
// arguments or unreadable logs.
#include <cstdio>
#include <filesystem>
#include <cstdlib>
#include <string>
#include <vector>

#include "anim/animator.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/mocap/io/motion_source_files.hpp"
#include "anim/tools/close_up_metrics.hpp"
#include "anim/tools/contact_sheet.hpp"
#include "anim/tools/metrics.hpp"
#include "anim/tools/mode_compare.hpp"
#include "anim/tools/strip_plot.hpp"
#include "anim/tools/stream_view.hpp"
#include "server/ingest/state_source.hpp"

namespace {

using namespace mc;
using namespace mc::anim;
using namespace mc::anim::tools;

struct Animated {
  std::vector<WorldState> states;
  std::vector<PoseFrame> frames;
  std::vector<FrameInfo> infos;
  std::vector<AnimEvent> events;
  GameParams params;
};

bool animate_log(const std::string& path, const AnimConfig& cfg, Animated& a) {
  std::string err;
  auto src = ingest::open_log(path, err);
  if (!src) {
    std::fprintf(stderr, "%s: %s\n", path.c_str(), err.c_str());
    return false;
  }
  WorldState s;
  while (src->next(s)) a.states.push_back(s);
  a.params = src->params();
  Animator anim(human_skeleton(), a.params, cfg);
  anim.set_frame_info_sink(&a.infos);
  a.frames.reserve(2 * a.states.size());
  for (const WorldState& st : a.states) anim.push(st, a.frames, &a.events);
  anim.finish(a.frames, &a.events);
  return true;
}

// Row 1: the first kick with a run-up (contact frame in the middle); row 2:
// the same player's longest run in the first half.
bool write_picture(const Animated& a, const std::string& path) {
  const SkeletonDef& skel = human_skeleton();
  constexpr int kCells = 16;
  const AnimEvent* kick = nullptr;
  for (const AnimEvent& e : a.events) {
    if (e.type != AnimEventType::Kick || e.seq < 40) continue;
    const std::size_t p = static_cast<std::size_t>(player_index(e.side, e.unum));
    const std::size_t fi = e.seq - a.frames[0].seq;
    if (fi + kCells >= a.frames.size()) continue;
    const Action before = a.infos[fi - 6].players[p].action;
    if (before == Action::Run || before == Action::Walk) { kick = &e; break; }
  }
  if (kick == nullptr) {
    for (const AnimEvent& e : a.events)
      if (e.type == AnimEventType::Kick && e.seq >= 40) { kick = &e; break; }
  }
  if (kick == nullptr) return false;
  const int slot = player_index(kick->side, kick->unum);
  Image img(kCells * kCellPx, 4 * kRowPx);
  std::vector<const PoseFrame*> row;
  const std::size_t k0 = kick->seq - a.frames[0].seq - kCells / 2;
  for (int c = 0; c < kCells; ++c) row.push_back(&a.frames[k0 + static_cast<std::size_t>(c)]);
  draw_pose_row(img, 0, skel, row, slot, row[kCells / 2]->players[static_cast<std::size_t>(slot)].heading);
  // Longest run of Run frames of that player.
  std::size_t best = 0, best_len = 0, cur = 0, len = 0;
  for (std::size_t i = 0; i < a.infos.size(); ++i) {
    if (a.infos[i].players[static_cast<std::size_t>(slot)].action == Action::Run) {
      if (len == 0) cur = i;
      if (++len > best_len) { best_len = len; best = cur; }
    } else {
      len = 0;
    }
  }
  row.clear();
  for (int c = 0; c < kCells && best + static_cast<std::size_t>(c) < a.frames.size(); ++c)
    row.push_back(&a.frames[best + static_cast<std::size_t>(c)]);
  if (!row.empty()) draw_pose_row(img, 1, skel, row, slot, row[0]->players[static_cast<std::size_t>(slot)].heading);
  // Rows 3 and 4: the first tackle and the first goalie catch or dive, from
  // a few frames before they start.
  const Action wanted[2][2] = {{Action::Tackle, Action::Tackle}, {Action::Catch, Action::Dive}};
  for (int r = 0; r < 2; ++r) {
    bool done = false;
    for (std::size_t i = 4; i + kCells < a.infos.size() && !done; ++i) {
      for (int p = 0; p < kMaxPlayers && !done; ++p) {
        const PlayerFrameInfo& pi = a.infos[i].players[static_cast<std::size_t>(p)];
        if ((pi.action != wanted[r][0] && pi.action != wanted[r][1]) || !pi.in_action) continue;
        row.clear();
        for (int c = 0; c < kCells; ++c) row.push_back(&a.frames[i - 4 + static_cast<std::size_t>(c)]);
        draw_pose_row(img, 2 + r, skel, row, p, row[4]->players[static_cast<std::size_t>(p)].heading);
        std::printf("picture row %d: slot %d, %s from seq %u\n", 3 + r, p, action_name(pi.action), row[0]->seq);
        done = true;
      }
    }
  }
  std::string err;
  if (!tools::write_png(path, img, err)) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return false;
  }
  std::printf("picture: %s (row 1: %s %d kicking with the %s foot at seq %u, contact in cell %d; row 2: a run "
              "from seq %u)\n",
              path.c_str(), kick->side == Side::Left ? "left" : "right", kick->unum,
              kick->foot == Foot::Right ? "right" : "left", kick->seq, kCells / 2 + 1,
              a.frames[best].seq);
  return true;
}

void print_usage(const char* self) {
  std::fprintf(stderr,
               "usage: %s [--mode keyframe|mocap] [--compare] [--mocap-dir DIR] [--mocap-cache DIR] [--png FILE] "
               "[--contact-sheet FILE] [--draw-rate HZ] [--draw-phase F] [--lookahead N] "
               "[--detail none|run|kick|full] [--leg-blend none] LOG...\n",
               self);
}

// A number that is the whole of `text` (strtod's, nothing after it).
bool parse_number(const char* text, double& out) {
  char* end = nullptr;
  out = std::strtod(text, &end);
  return end != text && *end == '\0';
}

}  // namespace

int main(int argc, char** argv) {
  AnimConfig cfg;
  std::string png = "anim-quality.png";
  std::vector<std::string> logs;
  std::string mode = "keyframe", mocap_dir = MATCHCAST_DEFAULT_MOCAP_DIR, mocap_cache = MATCHCAST_DEFAULT_MOCAP_CACHE;
  bool compare = false;
  DrawnLegs drawn_legs = DrawnLegs::LegBlend;
  int draw_rate = 60;
  double draw_phase = 0.0;
  std::string sheet = "test-output/anim/contact-sheet.png";
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--png" && i + 1 < argc) png = argv[++i];
    else if (arg == "--contact-sheet" && i + 1 < argc) sheet = argv[++i];
    else if (arg == "--draw-rate" && i + 1 < argc) draw_rate = std::atoi(argv[++i]);
    else if (arg == "--draw-phase" && i + 1 < argc) {
      if (!parse_number(argv[++i], draw_phase) || !(draw_phase >= 0.0 && draw_phase < 1.0)) {
        std::fprintf(stderr, "%s: --draw-phase must be a number at least 0 and below 1, not '%s'\n", argv[0], argv[i]);
        return 2;
      }
    }
    else if (arg == "--lookahead" && i + 1 < argc) cfg.lookahead_cycles = std::atoi(argv[++i]);
    else if (arg == "--mode" && i + 1 < argc && (std::string(argv[i + 1]) == "keyframe" || std::string(argv[i + 1]) == "mocap"))
      mode = argv[++i];
    else if (arg == "--compare") compare = true;
    else if (arg == "--leg-blend" && i + 1 < argc && std::string(argv[i + 1]) == "none") {
      drawn_legs = DrawnLegs::AngleBlendOnly;
      ++i;
    }
    else if (arg == "--mocap-dir" && i + 1 < argc) mocap_dir = argv[++i];
    else if (arg == "--mocap-cache" && i + 1 < argc) mocap_cache = argv[++i];
    else if (arg == "--detail" && i + 1 < argc) {
      const auto d = detail_from_name(argv[++i]);
      if (!d) {
        std::fprintf(stderr, "%s: --detail must be none, run, kick or full\n", argv[0]);
        return 2;
      }
      cfg.detail = *d;
    } else if (!arg.empty() && arg[0] == '-') {
      print_usage(argv[0]);
      return 2;
    } else {
      logs.push_back(arg);
    }
  }
  if (draw_rate < 20 || draw_rate % 20 != 0) {
    std::fprintf(stderr, "%s: --draw-rate must be a multiple of 20\n", argv[0]);
    return 2;
  }
  if (logs.empty()) {
    print_usage(argv[0]);
    return 2;
  }
  // Mocap mode: the caller loads the clips, the animator stays pure.
  AnimConfig mocap_cfg = cfg;
  if (mode == "mocap" || compare) {
    std::string err;
    auto source = mocap::io::load_mocap_motion_source_with_walk(mocap_dir, mocap_cache, err);
    if (!source) {
      std::fprintf(stderr, "%s\n", err.c_str());
      return 2;
    }
    std::printf("mocap mode: %zu CMU kicks and the graph walk from %s (cache dir %s)\n", source->kick_count(),
                mocap_dir.c_str(), mocap_cache.c_str());
    mocap_cfg.motion_source = std::move(source);
  }
  const AnimConfig& shown_cfg = mode == "mocap" || compare ? mocap_cfg : cfg;
  bool all_ok = true, pictured = false;
  const char* trace = std::getenv("MATCHCAST_ANIM_TRACE");  // "SLOT FROM TO": per-frame dump for debugging
  for (const std::string& log : logs) {
    Animated a;
    if (!animate_log(log, shown_cfg, a)) return 2;
    // What a spectator receives, measured at 20 Hz and at the drawing rate.
    auto close_up = [&](const Animated& x, const char* label) {
      StreamView view;
      std::string err;
      if (!view_stream(human_skeleton(), x.params, x.frames, x.events, view, err)) {
        std::fprintf(stderr, "%s: the stream does not decode: %s\n", log.c_str(), err.c_str());
        return false;
      }
      if (!sheet.empty()) {
        ContactSheetRows rows;
        std::error_code ec;
        const std::filesystem::path dir = std::filesystem::path(sheet).parent_path();
        if (!dir.empty()) std::filesystem::create_directories(dir, ec);
        if (write_contact_sheet(view, sheet, rows, err))
          std::printf("contact sheet: %s (sprint from %s; kick from %s, contact in cell 10; turn from %s)\n",
                      sheet.c_str(), rows.sprint.c_str(), rows.kick.c_str(), rows.turn.c_str());
        else
          std::fprintf(stderr, "contact sheet: %s\n", err.c_str());
        sheet.clear();  // the first log's
      }
      const CloseUpReport r20 = measure_close_up(view, x.states, x.frames, 1);
      const CloseUpReport rd = measure_close_up(view, x.states, x.frames, draw_rate / 20, drawn_legs, draw_phase);
      if (draw_phase > 0.0) std::printf("drawn at phase %.3f of a drawn frame past each 20 Hz frame\n", draw_phase);
      std::printf("== %s%s (%zu frames, %zu kicks, %.0f B/frame on the wire)\n%s", log.c_str(), label, view.frames.size(),
                  view.kicks.size(), static_cast<double>(view.encoded_bytes) / static_cast<double>(std::max<std::size_t>(1, view.frames.size())),
                  format_close_up({&r20, &rd}).c_str());
      return close_up_targets_hold(r20) && close_up_targets_hold(rd);
    };
    if (compare) {
      Animated k;
      if (!animate_log(log, cfg, k)) return 2;
      const tools::QualityReport r =
          tools::measure(human_skeleton(), a.states, a.frames, a.infos, a.events, a.params.ball_size());
      const tools::QualityReport rk =
          tools::measure(human_skeleton(), k.states, k.frames, k.infos, k.events, k.params.ball_size());
      std::printf("== %s (keyframe | mocap), the animator's own bookkeeping (issue 4)\n%s", log.c_str(),
                  tools::format_comparison(rk, r).c_str());
      all_ok = close_up(k, " keyframe mode") && all_ok;
      all_ok = close_up(a, " mocap mode") && all_ok;
    } else {
      all_ok = close_up(a, mode == "mocap" ? " mocap mode" : "") && all_ok;
    }
    int counts[kActionCount] = {};
    for (const FrameInfo& fi : a.infos)
      for (const PlayerFrameInfo& p : fi.players) ++counts[static_cast<int>(p.action)];
    std::printf("actions (player-frames):");
    for (int k = 0; k < kActionCount; ++k) std::printf(" %s %d", action_name(static_cast<Action>(k)), counts[k]);
    std::printf("\n");
    int slot = -1;
    unsigned from = 0, to = 0;
    if (trace != nullptr && std::sscanf(trace, "%d %u %u", &slot, &from, &to) == 3 && slot >= 0 && slot < kMaxPlayers) {
      for (std::size_t i = 0; i < a.frames.size(); ++i) {
        const PoseFrame& f = a.frames[i];
        if (f.seq < from || f.seq > to) continue;
        const PlayerPose& p = f.players[static_cast<std::size_t>(slot)];
        const PlayerFrameInfo& pi = a.infos[i].players[static_cast<std::size_t>(slot)];
        std::printf("seq %u %-9s act%d rst%d pl%d%d x %.3f y %.3f z %.3f h %.1f st %x | hipR %.1f %.1f %.1f kR %.1f "
                    "hipL %.1f %.1f %.1f kL %.1f ankR %.1f %.1f ankL %.1f %.1f\n",
                    f.seq, action_name(pi.action), pi.in_action, pi.reset, pi.planted[0], pi.planted[1], p.x, p.y,
                    p.z, p.heading, p.state, p.angles[24], p.angles[25], p.angles[26], p.angles[27], p.angles[30],
                    p.angles[31], p.angles[32], p.angles[33], p.angles[28], p.angles[29], p.angles[34], p.angles[35]);
      }
    }
    if (std::getenv("MATCHCAST_ACTIONS_DUMP") != nullptr)  // debug aid: every player-frame's action, to join with the slides' lists
      for (std::size_t i = 0; i < a.frames.size(); ++i)
        for (std::size_t s = 0; s < a.infos[i].players.size(); ++s)
          std::fprintf(stderr, "act %u %zu %s\n", a.frames[i].seq, s, action_name(a.infos[i].players[s].action));
    if (!pictured) pictured = write_picture(a, png);
  }
  std::printf("%s\n", all_ok ? "ALL TARGETS HOLD" : "SOME TARGETS FAIL");
  return all_ok ? 0 : 1;
}

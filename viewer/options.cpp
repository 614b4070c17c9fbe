#include "viewer/options.hpp"

#include <filesystem>
#include <cctype>
#include <sstream>

#include <boost/program_options.hpp>

namespace mc::viewer {

namespace po = boost::program_options;

bool parse_player(const std::string& text, Side& side, int& unum) {
  if (text.size() < 2 || text.size() > 3) return false;
  const char s = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  if (s != 'l' && s != 'r') return false;
  int n = 0;
  for (std::size_t i = 1; i < text.size(); ++i) {
    if (text[i] < '0' || text[i] > '9') return false;
    n = n * 10 + (text[i] - '0');
  }
  if (n < 1 || n > kPlayersPerSide) return false;
  side = s == 'l' ? Side::Left : Side::Right;
  unum = n;
  return true;
}

std::optional<ViewerOptions> parse_options(int argc, char** argv, std::string& message, int& exit_code) {
  ViewerOptions o;
  std::string camera = "director";
  po::options_description desc(
      "matchcast-viewer SOURCE [options]\n"
      "SOURCE: a relay (ws://HOST:PORT/ws, ws://HOST:PORT/ws?recording=NAME, http://HOST:PORT/)\n"
      "        or a recording file (.mcrec) or a game log (.rcg, .rcg.gz: animated in-process)\n"
      "Keys: 0 director, 1 broadcast, 2 orbit, 4 player view, 5 follow, 7 top-down, 8 close-up,\n"
      "      C next camera;\n"
      "      Tab/] next player, [ previous, Esc nearest the ball; N numbers on/off;\n"
      "      Space/P pause, Left/Right seek 10 s (Shift: 60 s), Up/Down speed; Q quit.\n"
      "      Orbit: drag to turn, scroll to zoom.\n"
      "Options");
  desc.add_options()
      ("help,h", "this text")
      ("camera", po::value(&camera), "director (the server's cut, the default) | broadcast | orbit | player | follow | top | closeup")
      ("follow", po::value(&o.follow), "the chosen player for player/follow/closeup: l1..l11, r1..r11")
      ("width", po::value(&o.width), "window or screenshot width (px)")
      ("height", po::value(&o.height), "window or screenshot height (px)")
      ("speed", po::value(&o.speed), "recording playback speed")
      ("loop", po::bool_switch(&o.loop), "recording: start again at the end")
      ("fullscreen", po::bool_switch(&o.fullscreen), "full screen on the primary monitor")
      ("samples", po::value(&o.samples), "window: anti-aliasing samples per pixel (default 4, or 0 on a software renderer such as llvmpipe)")
      ("no-vsync", "render as fast as possible instead of at the display's rate")
      ("no-labels", "no numbers above the players")
      ("screenshot", po::value(&o.screenshot), "render one frame offscreen to this PNG and exit")
      ("at", po::value(&o.at), "with --screenshot: the simulation cycle to render (first frame at or after it)")
      ("timeout", po::value(&o.timeout_s), "with --screenshot: longest wait for that frame (s)")
      ("report", po::value(&o.report), "with --screenshot: also write what was drawn as JSON")
      ("quit-after", po::value(&o.quit_after_s), "close after this many seconds and print the drawing figures")
      ("simulate-slow-ms", po::value(&o.simulate_slow_ms), "testing: pretend each frame takes this long to draw");
  po::options_description hidden;
  hidden.add_options()("source", po::value(&o.source));
  po::options_description all;
  all.add(desc).add(hidden);
  po::positional_options_description pos;
  pos.add("source", 1);
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(argc, argv).options(all).positional(pos).run(), vm);
    po::notify(vm);
  } catch (const std::exception& e) {
    message = std::string("matchcast-viewer: ") + e.what() + " (--help lists the options)";
    exit_code = 1;
    return std::nullopt;
  }
  if (vm.count("help")) {
    std::ostringstream s;
    s << desc;
    message = s.str();
    exit_code = 0;
    return std::nullopt;
  }
  exit_code = 1;
  if (o.source.empty()) {
    message = "matchcast-viewer: no SOURCE (a ws:// relay address or a recording file); --help for more";
    return std::nullopt;
  }
  if (!camera_mode_from_name(camera, o.camera)) {
    message = "matchcast-viewer: unknown camera \"" + camera + "\" (director, broadcast, orbit, player, follow, top, closeup)";
    return std::nullopt;
  }
  Side side;
  int unum;
  if (!o.follow.empty() && !parse_player(o.follow, side, unum)) {
    message = "matchcast-viewer: --follow wants l1..l11 or r1..r11, not \"" + o.follow + "\"";
    return std::nullopt;
  }
  if (o.width < 16 || o.height < 16 || o.width > 8192 || o.height > 8192) {
    message = "matchcast-viewer: --width/--height must be 16..8192";
    return std::nullopt;
  }
  if (!o.screenshot.empty() && o.at < 0) {
    message = "matchcast-viewer: --screenshot needs --at SIMTIME (a simulation cycle, 0 or more)";
    return std::nullopt;
  }
  o.vsync = vm.count("no-vsync") == 0;
  o.labels = vm.count("no-labels") == 0;
  // A file: it exists, or it is named like a recording or a log; anything else is an address.
  std::error_code ec;
  o.is_file = o.source.find("://") == std::string::npos &&
              (std::filesystem::is_regular_file(o.source, ec) || o.source.ends_with(".mcrec") ||
               o.source.ends_with(".rcg") || o.source.ends_with(".rcg.gz"));
  return o;
}

}  // namespace mc::viewer

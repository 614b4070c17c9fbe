#include "server/app/server_options.hpp"

#include "anim/mocap/io/asset_cache.hpp"
#include "anim/mocap/io/motion_source_files.hpp"

#include <algorithm>
#include <boost/program_options.hpp>
#include <fstream>
#include <sstream>

#ifndef MATCHCAST_SOURCE_DIR
#define MATCHCAST_SOURCE_DIR "."
#endif

namespace po = boost::program_options;

namespace mc::app {
namespace {

// Settings given as VALUE (every channel) or CHANNEL=VALUE (one), applied in
// order. `apply(feed, value)` returns false for a value it does not know.
// False with `message` on a bad value or a channel this server does not have.
template <class Apply>
bool per_channel(const std::vector<std::string>& settings, std::vector<ChannelFeed>& feeds, const std::string& option,
                 const std::string& values, Apply apply, std::string& message) {
  for (const std::string& d : settings) {
    const auto eq = d.find('=');
    const std::string channel = eq == std::string::npos ? "" : d.substr(0, eq);
    const std::string value = eq == std::string::npos ? d : d.substr(eq + 1);
    bool any = false;
    for (auto& cf : feeds) {
      if (!channel.empty() && cf.channel != channel) continue;
      if (!apply(cf.feed, value)) {
        message = "matchcast-server: " + option + " must be " + values + " (or CHANNEL=VALUE), not '" + d + "'";
        return false;
      }
      any = true;
    }
    if (!any) {
      message = "matchcast-server: " + option + " names no channel of this server: '" + channel + "'";
      return false;
    }
  }
  return true;
}

}  // namespace

std::optional<ServerOptions> parse_server_options(int argc, const char* const argv[],
                                                  std::string& message, int& exit_code) {
  ServerOptions o;
  const std::string source_dir = MATCHCAST_SOURCE_DIR;
  std::string config_file;
  std::vector<std::string> logs;
  std::string origins;
  FeedConfig feed;
  unsigned max_queue_kb = 0, stall_ms = 0;
  std::string role = "standalone", edge_games, record_at = "origin";
  std::string record_max_bytes = "2G", record_max_age = "30d";
  unsigned header_timeout_ms = 0;
  unsigned nats_reconnect_ms = 0, origin_silence_ms = 0, edge_on_demand_ms = 0;
  bool nats_in_order = false;
  std::vector<std::string> details, anim_modes;
  std::string reach_channels, mocap_dir = source_dir + "/data/mocap", mocap_cache = "mocap-cache";
  po::options_description desc(
      "matchcast-server: broadcast a RoboCup 2D game as a live 3D stream\n\nOptions");
  // clang-format off
  unsigned send_buffer_kb = 0;
  desc.add_options()
    ("help,h", "print this help and exit")
    ("config", po::value(&config_file), "read options from this file (key = value lines)")
    ("rcg", po::value(&logs)->composing(),
        "game to broadcast: a log (.rcg/.rcg.gz, any version) or a live rcssserver "
        "(udp://HOST:PORT), as SOURCE or CHANNEL=SOURCE; "
        "repeat for several games at once (default: the bundled game on channel 'live')")
    ("loop", po::value(&feed.loop)->default_value(true), "start the log again at its end (true/false)")
    ("speed", po::value(&feed.speed)->default_value(1.0), "playback speed, 1 = real time")
    ("keyframe-interval", po::value(&feed.keyframe_interval)->default_value(20),
        "frames between keyframes (20 = 1 s)")
    ("detail", po::value(&details)->composing(),
        "animation detail none|run|kick|full (the perception study's levels), for every channel "
        "as LEVEL or for one as CHANNEL=LEVEL; repeatable (default: full)")
    ("anim-mode", po::value(&anim_modes)->composing(),
        "keyframe (default) or mocap: kicks and slow walking from the CMU captures of --mocap-dir; "
        "for every channel as MODE or for one as CHANNEL=MODE; repeatable")
    ("lookahead", po::value(&feed.anim.lookahead_cycles)->default_value(feed.anim.lookahead_cycles),
        "following 10 Hz states each frame waits for, 1..4 (each adds 100 ms of delay and lengthens "
        "the kick preparation)")
    ("reach-overlay", po::value(&reach_channels),
        "channels that also send the reach map (who gets where first, from motion capture), "
        "2.5 times a second: comma-separated names or 'all' (default: none)")
    ("mocap-dir", po::value(&mocap_dir)->default_value(mocap_dir), "the CMU clips the reach map and the mocap animation mode are built from")
    ("mocap-cache", po::value(&mocap_cache)->default_value(mocap_cache),
        "folder where the built motion graph and map are cached (empty = rebuild at each start)")
    ("address", po::value(&o.relay.address)->default_value("127.0.0.1"), "address to listen on")
    ("port", po::value(&o.relay.port)->default_value(8080), "TCP port, 0 = any free port")
    ("web", po::value(&o.relay.web_root)->default_value(source_dir + "/web"),
        "folder of the web page; nothing outside it is served")
    ("threads", po::value(&o.relay.threads)->default_value(0), "I/O threads, 0 = one per core")
    ("max-clients", po::value(&o.relay.max_clients)->default_value(o.relay.max_clients),
        "spectators at once; more are refused with 503")
    ("max-queue-kb", po::value(&max_queue_kb)->default_value(static_cast<unsigned>(o.relay.max_queue_bytes / 1024)),
        "per-spectator queue bound; past it the spectator skips to the next keyframe")
    ("stall-timeout-ms", po::value(&stall_ms)->default_value(static_cast<unsigned>(o.relay.stall_timeout.count())),
        "a spectator whose write is stuck this long is disconnected")
    ("max-message-bytes", po::value(&o.relay.max_inbound_message)->default_value(o.relay.max_inbound_message),
        "largest message a spectator may send")
    ("max-connections-per-ip", po::value(&o.relay.max_connections_per_ip)->default_value(o.relay.max_connections_per_ip),
        "connections one client address may hold, 0 = no limit")
    ("header-timeout-ms", po::value(&header_timeout_ms)->default_value(static_cast<unsigned>(o.relay.header_timeout.count())),
        "a request's headers (or a TLS handshake) must arrive within this time, or the connection is closed")
    ("allowed-origins", po::value(&origins), "comma-separated Origin values allowed to open the stream (default: any)")
    ("record-dir", po::value(&o.record_dir)->default_value(o.record_dir),
        "record every live channel here, one file per game, and offer the recordings for replay (empty: off)")
    ("record-max-bytes", po::value(&record_max_bytes)->default_value(record_max_bytes),
        "recordings may take this much together (K, M, G: powers of 1024); past it the oldest are deleted (0: no limit)")
    ("record-max-age", po::value(&record_max_age)->default_value(record_max_age),
        "recordings last written longer ago are deleted: 90s, 30m, 12h, 7d (0: no limit)")
    ("control-token", po::value(&o.relay.control_token),
        "bearer token for POST /control/... (default: control disabled)")
    ("tls-cert", po::value(&o.relay.tls_cert_file),
        "PEM certificate (chain) file: with --tls-key, the port speaks HTTPS and WSS only")
    ("tls-key", po::value(&o.relay.tls_key_file), "PEM private key file of --tls-cert")
    ("send-buffer-kb", po::value(&send_buffer_kb)->default_value(static_cast<unsigned>(o.relay.socket_send_buffer / 1024)),
        "kernel send buffer per connection (bounds a stalled spectator's kernel memory), 0 = OS autotuning")
    ("role", po::value(&role)->default_value(role),
        "standalone (one machine, no NATS), origin (publish the feeds on NATS), "
        "edge (serve games from NATS, no feeds) or both")
    ("nats-url", po::value(&o.nats.url)->default_value(o.nats.url),
        "NATS server(s), comma-separated (origin/edge/both)")
    ("nats-in-order", po::bool_switch(&nats_in_order),
        "connect to the --nats-url servers in the order listed, falling back to the next (default: random order)")
    ("nats-subject-prefix", po::value(&o.nats.subject_prefix)->default_value(o.nats.subject_prefix),
        "subjects <prefix>.<game>.live/.key, stream <PREFIX>_KEY")
    ("edge-games", po::value(&edge_games),
        "comma-separated games an edge carries (default: every game published)")
    ("record-at", po::value(&record_at)->default_value(record_at),
        "with NATS, where recording happens: origin, or edge (this edge records its games; "
        "set it on the origin too)")
    ("nats-replicas", po::value(&o.nats.stream_replicas)->default_value(o.nats.stream_replicas),
        "copies of the keyframe stream (3 on a 3-node cluster)")
    ("nats-reconnect-wait-ms", po::value(&nats_reconnect_ms)->default_value(static_cast<unsigned>(o.nats.reconnect_wait.count())),
        "pause between NATS reconnect attempts")
    ("origin-silence-ms", po::value(&origin_silence_ms)->default_value(static_cast<unsigned>(o.nats.origin_silence.count())),
        "an edge says 'feed lost' after this long without a message from the origin")
    ("edge-on-demand-ms", po::value(&edge_on_demand_ms)->default_value(static_cast<unsigned>(o.nats.on_demand_wait.count())),
        "an edge asked for a game it does not carry (/ws?channel=NAME) subscribes to it and waits this long "
        "for it before closing the spectator with a reason; 0 = never subscribe on demand");
  // clang-format on
  try {
    po::variables_map vm;
    po::store(po::parse_command_line(argc, argv, desc), vm);
    if (vm.count("help")) {
      std::ostringstream s;
      s << desc;
      message = s.str();
      exit_code = 0;
      return std::nullopt;
    }
    if (vm.count("config")) {
      const std::string path = vm["config"].as<std::string>();
      std::ifstream in(path);
      if (!in) throw po::error("cannot read config file '" + path + "'");
      po::store(po::parse_config_file(in, desc), vm);
    }
    po::notify(vm);
  } catch (const po::error& e) {
    message = std::string("matchcast-server: ") + e.what() + "\n(see --help)";
    exit_code = 2;
    return std::nullopt;
  }
  o.relay.socket_send_buffer = static_cast<std::size_t>(send_buffer_kb) * 1024;
  o.relay.header_timeout = std::chrono::milliseconds(std::max(100u, header_timeout_ms));
  if (!parse_byte_size(record_max_bytes, o.retention.max_bytes)) {
    message = "matchcast-server: --record-max-bytes takes a size such as 500M or 2G, not '" + record_max_bytes + "'";
    exit_code = 2;
    return std::nullopt;
  }
  if (!parse_duration(record_max_age, o.retention.max_age)) {
    message = "matchcast-server: --record-max-age takes a duration such as 12h or 7d, not '" + record_max_age + "'";
    exit_code = 2;
    return std::nullopt;
  }
  if (feed.speed <= 0 || feed.speed > 100) {
    message = "matchcast-server: --speed must be in (0, 100]";
    exit_code = 2;
    return std::nullopt;
  }
  if (feed.anim.lookahead_cycles < 1 || feed.anim.lookahead_cycles > 4) {
    message = "matchcast-server: --lookahead must be in [1, 4]";
    exit_code = 2;
    return std::nullopt;
  }
  if (feed.keyframe_interval < 1 || feed.keyframe_interval > 1200) {
    message = "matchcast-server: --keyframe-interval must be in [1, 1200]";
    exit_code = 2;
    return std::nullopt;
  }
  if (role == "standalone") o.nats.role = nats::Role::Standalone;
  else if (role == "origin") o.nats.role = nats::Role::Origin;
  else if (role == "edge") o.nats.role = nats::Role::Edge;
  else if (role == "both") o.nats.role = nats::Role::Both;
  else {
    message = "matchcast-server: --role must be standalone, origin, edge or both, not '" + role + "'";
    exit_code = 2;
    return std::nullopt;
  }
  if (record_at != "origin" && record_at != "edge") {
    message = "matchcast-server: --record-at must be origin or edge, not '" + record_at + "'";
    exit_code = 2;
    return std::nullopt;
  }
  o.nats.record_at = record_at == "edge" ? nats::RecordAt::Edge : nats::RecordAt::Origin;
  if (o.nats.stream_replicas < 1 || o.nats.stream_replicas > 5) {
    message = "matchcast-server: --nats-replicas must be in [1, 5]";
    exit_code = 2;
    return std::nullopt;
  }
  o.nats.reconnect_wait = std::chrono::milliseconds(std::max(50u, nats_reconnect_ms));
  o.nats.origin_silence = std::chrono::milliseconds(std::max(200u, origin_silence_ms));
  o.nats.on_demand_wait = std::chrono::milliseconds(edge_on_demand_ms);
  o.nats.randomize_servers = !nats_in_order;
  for (std::size_t pos = 0; pos < edge_games.size();) {
    auto comma = edge_games.find(',', pos);
    if (comma == std::string::npos) comma = edge_games.size();
    std::string one = edge_games.substr(pos, comma - pos);
    one.erase(0, one.find_first_not_of(' '));
    one.erase(one.find_last_not_of(' ') + 1);
    if (!one.empty()) o.nats.edge_games.push_back(one);
    pos = comma + 1;
  }
  // An edge has no feeds of its own: its games come from NATS.
  if (o.nats.role == nats::Role::Edge && !logs.empty()) {
    message = "matchcast-server: an edge has no --rcg feeds (use --role both to run feeds too)";
    exit_code = 2;
    return std::nullopt;
  }
  if (logs.empty() && o.nats.role != nats::Role::Edge) logs.push_back(source_dir + "/data/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz");
  for (std::size_t i = 0; i < logs.size(); ++i) {
    ChannelFeed cf{i == 0 ? "live" : "live" + std::to_string(i + 1), feed};
    const auto eq = logs[i].find('=');
    // CHANNEL=SOURCE, unless the '=' belongs to the path (a '/' before it).
    if (eq != std::string::npos && logs[i].find('/') > eq) {
      cf.channel = logs[i].substr(0, eq);
      cf.feed.log_path = logs[i].substr(eq + 1);
    } else {
      cf.feed.log_path = logs[i];
    }
    if (cf.channel.empty() || cf.channel.find_first_not_of(
          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.") != std::string::npos) {
      message = "matchcast-server: channel names use letters, digits, '_', '-' and '.' only: '" + cf.channel + "'";
      exit_code = 2;
      return std::nullopt;
    }
    for (const auto& other : o.feeds)
      if (other.channel == cf.channel) {
        message = "matchcast-server: channel '" + cf.channel + "' given twice";
        exit_code = 2;
        return std::nullopt;
      }
    o.feeds.push_back(cf);
  }
  // --detail LEVEL / --anim-mode MODE apply to every channel, CHANNEL=... to one (later wins).
  const bool details_ok = per_channel(details, o.feeds, "--detail", "none, run, kick or full",
      [](FeedConfig& f, const std::string& v) {
        const auto level = anim::detail_from_name(v);
        if (level) f.anim.detail = *level;
        return level.has_value();
      }, message);
  std::shared_ptr<const anim::MotionSource> mocap_motion;  // loaded once, shared by the channels that use it
  std::string mocap_error;
  const bool modes_ok = details_ok && per_channel(anim_modes, o.feeds, "--anim-mode", "keyframe or mocap",
      [&](FeedConfig& f, const std::string& v) {
        if (v == "keyframe") f.anim.motion_source = nullptr;
        else if (v != "mocap") return false;
        else {
          if (!mocap_motion && mocap_error.empty())
            mocap_motion = anim::mocap::io::load_mocap_motion_source_with_walk(mocap_dir, mocap_cache, mocap_error);
          f.anim.motion_source = mocap_motion;
        }
        return true;
      }, message);
  if (!details_ok || !modes_ok || !mocap_error.empty()) {
    if (!mocap_error.empty()) message = "matchcast-server: --anim-mode mocap: " + mocap_error;
    exit_code = 2;
    return std::nullopt;
  }
  if (!reach_channels.empty()) {
    std::string error;
    const auto model = anim::mocap::io::load_reach_model(mocap_dir, mocap_cache, error);
    if (!model) {
      message = "matchcast-server: --reach-overlay: " + error;
      exit_code = 2;
      return std::nullopt;
    }
    const std::string list = "," + reach_channels + ",";
    bool any = false;
    for (auto& cf : o.feeds)
      if (reach_channels == "all" || list.find("," + cf.channel + ",") != std::string::npos) {
        cf.feed.reach_model = model;
        any = true;
      }
    if (!any) {
      message = "matchcast-server: --reach-overlay names no channel of this server: '" + reach_channels + "'";
      exit_code = 2;
      return std::nullopt;
    }
  }
  for (std::size_t pos = 0; pos < origins.size();) {
    auto comma = origins.find(',', pos);
    if (comma == std::string::npos) comma = origins.size();
    std::string one = origins.substr(pos, comma - pos);
    one.erase(0, one.find_first_not_of(' '));
    one.erase(one.find_last_not_of(' ') + 1);
    if (!one.empty()) o.relay.allowed_origins.push_back(one);
    pos = comma + 1;
  }
  o.relay.max_queue_bytes = static_cast<std::size_t>(max_queue_kb) * 1024;
  o.relay.stall_timeout = std::chrono::milliseconds(stall_ms);
  return o;
}

}  // namespace mc::app

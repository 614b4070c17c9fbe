// open_source(): one spec string for "a log file" or "a live server", so
// command lines take either (e.g. --source udp://127.0.0.1:6000).
#include <charconv>

#include "server/ingest/monitor_client.hpp"
#include "server/ingest/state_source.hpp"

namespace mc::ingest {
namespace {

constexpr std::string_view kScheme = "udp://";

template <typename Int>
bool parse_int(std::string_view s, Int& v) {
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && p == s.data() + s.size();
}

}  // namespace

bool is_live_spec(const std::string& spec) { return spec.rfind(kScheme, 0) == 0; }

std::unique_ptr<StateSource> open_source(const std::string& spec, std::string& error) {
  if (!is_live_spec(spec)) return open_log(spec, error);
  std::string_view rest = std::string_view(spec).substr(kScheme.size());
  MonitorClientConfig cfg;
  if (const auto slash = rest.find('/'); slash != std::string_view::npos) {
    if (!parse_int(rest.substr(slash + 1), cfg.version) ||
        !(cfg.version == -1 || (cfg.version >= 1 && cfg.version <= 5))) {
      error = spec + ": monitor version must be 1..5 or -1";
      return nullptr;
    }
    rest = rest.substr(0, slash);
  }
  if (const auto colon = rest.rfind(':'); colon != std::string_view::npos) {
    if (!parse_int(rest.substr(colon + 1), cfg.port) || cfg.port == 0) {
      error = spec + ": bad port";
      return nullptr;
    }
    rest = rest.substr(0, colon);
  }
  if (!rest.empty()) cfg.host = std::string(rest);
  auto client = std::make_unique<MonitorClient>(cfg);
  if (!client->error().empty()) {
    error = spec + ": " + client->error();
    return nullptr;
  }
  return client;
}

}  // namespace mc::ingest

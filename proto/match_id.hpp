// The hello's match_id names a game for spectators. It must never tell them
// where the server keeps it: a log is named by its file name without folder
// and extensions ("/srv/logs/20261122-A_1-vs-B_5.rcg.gz" becomes
// "20261122-A_1-vs-B_5"), a live game by its teams ("A-vs-B"), never by the
// rcssserver's address. Recordings made before this rule hold a server path
// in their hello; public_match_id() cleans one up when it is replayed.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace mc::proto {

// The last component of a path ('/' or '\\' separated), without the
// extensions of a game log or recording (.gz, then .rcg/.rcl/.json/.log/
// .mcrec). Text with no separator and no such extension is returned as is.
inline std::string public_match_id(std::string_view match_id) {
  const auto slash = match_id.find_last_of("/\\");
  if (slash != std::string_view::npos) match_id.remove_prefix(slash + 1);
  auto strip = [&](std::string_view ext) {
    if (match_id.size() > ext.size() && match_id.substr(match_id.size() - ext.size()) == ext) {
      match_id.remove_suffix(ext.size());
      return true;
    }
    return false;
  };
  strip(".gz");
  for (std::string_view ext : {".rcg", ".rcl", ".json", ".log", ".mcrec"})
    if (strip(ext)) break;
  return std::string(match_id);
}

// The match_id of a feed: a log path gives its public name, a live source
// ("udp://HOST:PORT", whose address is nobody else's business) the team
// names, or "live" while they are not known.
inline std::string match_id_of_source(std::string_view source, std::string_view left, std::string_view right) {
  if (source.substr(0, 6) == "udp://") {
    if (left.empty() && right.empty()) return "live";
    return std::string(left.empty() ? "?" : left) + "-vs-" + std::string(right.empty() ? "?" : right);
  }
  return public_match_id(source);
}

// A hello as JSON text with its match_id made public (public_match_id).
// Text that is not a JSON object, or whose match_id holds no path, is
// returned unchanged.
inline std::string hello_without_paths(const std::string& hello_json) {
  auto j = nlohmann::json::parse(hello_json, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object() || !j.contains("match_id") || !j["match_id"].is_string()) return hello_json;
  const std::string& id = j["match_id"].get_ref<const std::string&>();
  if (id.find_first_of("/\\") == std::string::npos) return hello_json;
  j["match_id"] = public_match_id(id);
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace mc::proto

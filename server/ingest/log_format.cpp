#include "server/ingest/log_format.hpp"

namespace mc::ingest {

LogFormat sniff_log_format(std::string_view head) {
  auto first_non_space_after_line = [&](std::size_t from) -> char {
    const std::size_t nl = head.find('\n', from);
    if (nl == std::string_view::npos) return '\0';
    for (std::size_t i = nl + 1; i < head.size(); ++i) {
      const char c = head[i];
      if (c != ' ' && c != '\t' && c != '\r' && c != '\n') return c;
    }
    return '\0';
  };
  std::size_t i = 0;
  while (i < head.size() && (head[i] == ' ' || head[i] == '\t' || head[i] == '\r' || head[i] == '\n')) ++i;
  if (i < head.size() && head[i] == '[') return LogFormat::Json19;
  if (head.substr(0, 4) == "JSON") return LogFormat::Json18;
  if (head.size() >= 4 && head.substr(0, 3) == "ULG") {
    switch (head[3]) {
      case 2: return LogFormat::BinaryV2;
      case 3: return LogFormat::BinaryV3;
      case '4': return LogFormat::TextV4;
      case '5': return LogFormat::TextV5;
      case '6': return first_non_space_after_line(0) == '[' ? LogFormat::Json17 : LogFormat::TextV6;
      default: return LogFormat::Unknown;
    }
  }
  // v1: a dispinfo_t record starts with a big-endian Int16 mode, SHOW_MODE 1
  // or MSG_MODE 2 (the server's first record), so bytes 00 01 or 00 02.
  if (head.size() >= 2 && head[0] == 0 && (head[1] == 1 || head[1] == 2)) return LogFormat::BinaryV1;
  return LogFormat::Unknown;
}

const char* log_format_name(LogFormat f) {
  switch (f) {
    case LogFormat::BinaryV1: return "v1 binary";
    case LogFormat::BinaryV2: return "v2 binary";
    case LogFormat::BinaryV3: return "v3 binary";
    case LogFormat::TextV4: return "ULG4 text";
    case LogFormat::TextV5: return "ULG5 text";
    case LogFormat::TextV6: return "ULG6 text";
    case LogFormat::Json17: return "17.x JSON";
    case LogFormat::Json18: return "18.x JSON";
    case LogFormat::Json19: return "19.x JSON";
    case LogFormat::Unknown: break;
  }
  return "unknown";
}

}  // namespace mc::ingest

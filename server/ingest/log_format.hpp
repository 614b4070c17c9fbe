// Game-log format detection from the first (decoded) bytes, as in
// rcss-protocol.md section 9: never from the file name.
#pragma once

#include <string_view>

namespace mc::ingest {

enum class LogFormat {
  Unknown,
  BinaryV1,  // no header: 2052-byte dispinfo_t records
  BinaryV2,  // "ULG\x02"
  BinaryV3,  // "ULG\x03"
  TextV4,    // "ULG4\n"
  TextV5,    // "ULG5\n"
  TextV6,    // "ULG6\n" then '(' lines (18.x/19.x)
  Json17,    // "ULG6\n" then '[' (17.x JSON)
  Json18,    // "JSON\n" then '['
  Json19,    // '['
};

// `head` = the first bytes of the decoded log (a few hundred are enough to
// look past the ULG6 header line).
LogFormat sniff_log_format(std::string_view head);
const char* log_format_name(LogFormat f);

}  // namespace mc::ingest

// Test helper: paths into tests/data/rcg and whole-file reads (tests only;
// the readers themselves stream).
#pragma once

#include <string>

#include "server/ingest/byte_source.hpp"

namespace mc::ingest::testing {

inline std::string rcg(const std::string& rel) { return std::string(MATCHCAST_TEST_RCG_DIR) + "/" + rel; }

// The decoded (gunzipped) bytes of a file; "" if it cannot be read.
inline std::string decoded(const std::string& path) {
  std::string err;
  auto src = open_file_source(path, err);
  std::string out;
  if (!src) return out;
  char buf[1 << 16];
  while (std::size_t n = src->read(buf, sizeof buf)) out.append(buf, n);
  return out;
}

}  // namespace mc::ingest::testing

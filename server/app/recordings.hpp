// The recordings of one server: a Recorder per recorded channel, one file
// per game named <channel>-<UTC date-time>.mcrec in the recording folder,
// each offered for replay and time shift (replay::ReplayCatalog), and a
// retention policy that keeps the folder bounded: past --record-max-bytes
// or --record-max-age the oldest recordings are deleted, one log line each.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "server/app/recorder.hpp"
#include "server/replay/replay_catalog.hpp"

namespace mc::app {

struct RetentionPolicy {
  // Bytes all recordings of the folder may take together; past it the
  // oldest are deleted. The looping demo game makes ~3 MB per pass, ~430 MB
  // a day. 0 = no limit.
  std::uint64_t max_bytes = 0;
  // A recording last written longer ago than this is deleted. 0 = no limit.
  std::chrono::seconds max_age{0};
};

// "1048576", "500K", "300M", "2G" (powers of 1024; "0" = no limit). False
// when the text is not such a size.
bool parse_byte_size(const std::string& text, std::uint64_t& out);
// "90s", "30m", "12h", "7d", or seconds without a unit ("0" = no limit).
bool parse_duration(const std::string& text, std::chrono::seconds& out);

// Deletes recordings (files of `dir` with a valid recording name), the
// least recently written first, until the rest fit `policy`. Never a file
// named in `keep` (being written). Logs "recording_deleted" for each and
// returns their names.
std::vector<std::string> apply_retention(const std::string& dir, const RetentionPolicy& policy,
                                         const std::set<std::string>& keep,
                                         std::filesystem::file_time_type now = std::filesystem::file_time_type::clock::now());

class Recordings {
 public:
  // `catalog` (may be nullptr) learns each channel's current file, for
  // time shift, and forgets deleted ones.
  Recordings(std::string dir, RetentionPolicy policy, replay::ReplayCatalog* catalog);
  ~Recordings();

  // Starts recording `channel` (callable from any thread). False, logged,
  // when it cannot; the broadcast goes on either way.
  bool record(const std::shared_ptr<relay::Channel>& channel);
  // Applies the retention policy (also done each time a file is opened).
  void prune();
  // Stops every recorder: each file is closed with its index.
  void stop_all();

  // The files being written now, by channel (tests, status).
  std::map<std::string, std::string> current() const;

 private:
  std::string next_path(const std::string& channel);
  void opened(const std::string& channel, const std::string& path);

  const std::string dir_;
  const RetentionPolicy policy_;
  replay::ReplayCatalog* catalog_;
  mutable std::mutex mutex_;  // after a Recorder's own lock, never before
  std::mutex prune_mutex_;    // one prune at a time (feed threads, the main loop)
  std::map<std::string, std::string> current_;  // channel -> file name
  std::vector<std::shared_ptr<Recorder>> recorders_;
};

}  // namespace mc::app

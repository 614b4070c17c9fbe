// The recordings one server offers for replay: the files in its recording
// folder. Opens private replays for spectators (relay::ReplayFactory) and
// lists them for /recordings. A recording's summary (time range, goals) is
// computed once per file size and cached.
#pragma once

#include <map>
#include <mutex>
#include <string>

#include "server/relay/replay_source.hpp"
#include "server/replay/replay_player.hpp"

namespace mc::replay {

// Recording files end in this; names are [A-Za-z0-9_.-]+ so that no name
// can leave the folder.
inline constexpr const char* kRecordingSuffix = ".mcrec";

bool valid_recording_name(const std::string& name);

class ReplayCatalog : public relay::ReplayFactory {
 public:
  // `dir` may be empty: then there are no recordings.
  explicit ReplayCatalog(std::string dir) : dir_(std::move(dir)) {}

  std::shared_ptr<relay::ReplaySource> open(const std::string& name,
                                            boost::asio::any_io_executor executor,
                                            std::string& error) override;
  std::string list_json() override;

  const std::string& dir() const { return dir_; }

 private:
  struct Cached {
    std::uint64_t size = 0;
    RecordingSummary summary;
  };
  std::string dir_;
  std::mutex mutex_;
  std::map<std::string, Cached> summaries_;
};

}  // namespace mc::replay

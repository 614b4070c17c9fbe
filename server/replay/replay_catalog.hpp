// The recordings one server offers for replay: the files in its recording
// folder. Opens private replays for spectators (relay::ReplayFactory) and
// lists them for /recordings. A recording's summary (time range, goals) is
// computed once per file size and cached. Also opens time shifts of live
// channels: replays of their recordings while they are being written.
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

  // `channel` is being recorded into `name` (a file in dir()): its
  // spectators may time shift. Again at each new file (one per game).
  void set_live_recording(const std::string& channel, const std::string& name);
  // A private replay that follows the growing recording of `channel`.
  std::shared_ptr<relay::ReplaySource> open_timeshift(const std::string& channel,
                                                      boost::asio::any_io_executor executor,
                                                      std::string& error) override;

  // `name` was deleted: its cached summary goes too.
  void forget(const std::string& name);

  const std::string& dir() const { return dir_; }

 private:
  struct Cached {
    std::uint64_t size = 0;
    RecordingSummary summary;
    // The file's parsed hello, so that the next replay of it does not parse
    // it again (the reader checks that the file's hello text is the same).
    std::shared_ptr<const record::RecordingHello> hello;
  };
  // A live recording's summary, kept up to date by reading only what was
  // appended since the last time shift opened (the first one reads it all).
  struct Live {
    std::string name;
    std::unique_ptr<record::RecordingReader> reader;
    RecordingSummary summary;
  };
  std::string dir_;
  std::mutex mutex_;
  std::map<std::string, Cached> summaries_;
  std::map<std::string, Live> live_;  // by channel
};

}  // namespace mc::replay

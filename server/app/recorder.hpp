// Records a channel: subscribes like a spectator and appends every frame and
// control message, exactly as sent, to a recording file (proto/recording.hpp
// via server/record).
//
// One file per game: a new game on the channel (a new hello, or the game
// clock going back: a looping log's next pass, a live server's next match)
// closes the file with its index and opens the next one, so that no file
// grows without end and retention (recordings.hpp) can delete old games.
// Control messages are held until the frame that follows them, so that a
// new game's first messages (teams, score) land in its own file.
//
// A write that fails (a full disk, a file-size limit) stops this file, says
// so in the log, and leaves the part written readable; the broadcast goes on,
// and the next game tries a new file.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "server/record/recording_writer.hpp"
#include "server/relay/channel.hpp"

namespace mc::app {

struct RecorderOptions {
  // The path of each file: asked once at the start and again at each new
  // game. Must not name an existing file.
  std::function<std::string()> next_path;
  // Told the path of each file once it is open (the feed's thread; may be empty).
  std::function<void(const std::string& path)> on_opened;
  // No fdatasync per chunk: a chunk reaches the page cache with one write(),
  // which survives SIGKILL; syncing would stall the feed thread.
  record::WriterOptions writer{20, false};
};

class Recorder : public relay::Subscriber, public std::enable_shared_from_this<Recorder> {
 public:
  // Opens the first file and joins `channel`. nullptr + error when the
  // channel has no hello yet or the first file cannot be created.
  static std::shared_ptr<Recorder> start(const std::shared_ptr<relay::Channel>& channel,
                                         RecorderOptions options, std::string& error);
  // Records into `path`; later games into `path` with "-2", "-3"... before
  // its extension.
  static std::shared_ptr<Recorder> start(const std::shared_ptr<relay::Channel>& channel,
                                         const std::string& path, std::string& error);
  ~Recorder() override;

  void deliver(const relay::Message& m) override;
  // Leaves the channel and closes the file with its index.
  void stop();

  // The file being written ("" after a failure, until the next game).
  std::string path() const;
  // Files opened so far, this one included.
  std::uint64_t files() const;

 private:
  Recorder(std::shared_ptr<relay::Channel> channel, RecorderOptions options)
      : channel_(std::move(channel)), options_(std::move(options)) {}
  void write(const relay::Message& m);
  // Closes the current file (if any) and opens the next one with hello_.
  bool open_next(std::string& error);
  void close_current();
  void fail(const std::string& error);

  std::shared_ptr<relay::Channel> channel_;
  RecorderOptions options_;
  mutable std::mutex mutex_;
  record::RecordingWriter writer_;
  std::string path_;
  std::string hello_;                     // the hello of the game being recorded
  std::vector<relay::Message> held_;      // control messages waiting for the next frame
  bool new_game_ = false;                 // a new hello came: the next frame starts a file
  bool have_time_ = false;
  int last_time_ = 0;                     // game clock of the last frame
  bool failed_ = false;                   // this game's file failed: wait for the next game
  bool stopped_ = false;
  std::uint64_t files_ = 0;
};

}  // namespace mc::app

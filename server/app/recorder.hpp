// Records a channel: subscribes like a spectator and appends every frame and
// control message, exactly as sent, to a recording file (proto/recording.hpp
// via server/record). One file per channel per server run.
#pragma once

#include <memory>
#include <mutex>
#include <string>

#include "server/record/recording_writer.hpp"
#include "server/relay/channel.hpp"

namespace mc::app {

class Recorder : public relay::Subscriber, public std::enable_shared_from_this<Recorder> {
 public:
  // Opens `path` and joins `channel`. nullptr + error when the file cannot
  // be created or the channel has no hello yet.
  static std::shared_ptr<Recorder> start(const std::shared_ptr<relay::Channel>& channel,
                                         const std::string& path, std::string& error);
  ~Recorder() override;

  void deliver(const relay::Message& m) override;
  // Leaves the channel and closes the file with its index.
  void stop();

  const std::string& path() const { return path_; }

 private:
  Recorder(std::shared_ptr<relay::Channel> channel, std::string path)
      : channel_(std::move(channel)), path_(std::move(path)) {}
  void write(const relay::Message& m);

  std::shared_ptr<relay::Channel> channel_;
  std::string path_;
  std::mutex mutex_;
  record::RecordingWriter writer_;
  bool failed_ = false;
};

}  // namespace mc::app

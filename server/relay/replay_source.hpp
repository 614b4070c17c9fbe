// A spectator's private stream that the spectator steers (a replay of a
// recording: pause, seek, speed, goals). The relay only moves bytes: it
// subscribes the session to the source's channel and hands the spectator's
// text messages to the source. The owner of recordings implements it. A
// time shift is the same thing over a live channel's own recording.
#pragma once

#include <boost/asio/any_io_executor.hpp>
#include <memory>
#include <string>
#include <string_view>

#include "server/relay/channel.hpp"
#include "server/relay/spectator_message.hpp"

namespace mc::relay {

class ReplaySource {
 public:
  virtual ~ReplaySource() = default;
  // The private channel the session subscribes to.
  virtual std::shared_ptr<Channel> channel() = 0;
  // A message from the spectator, read once by the session (a replay's
  // controls: type "replay"); called on the session's strand.
  virtual void on_message(const SpectatorMessage& message) = 0;
  // The spectator left: stop producing.
  virtual void close() = 0;
};

class ReplayFactory {
 public:
  virtual ~ReplayFactory() = default;
  // A new private replay of the recording `name`, driven on `executor` (the
  // spectator's strand). nullptr + error when there is no such recording.
  virtual std::shared_ptr<ReplaySource> open(const std::string& name,
                                             boost::asio::any_io_executor executor,
                                             std::string& error) = 0;
  // A time shift of the live channel `channel`: a private replay of its
  // running recording, which keeps growing while it is read. nullptr +
  // error when the channel is not being recorded.
  virtual std::shared_ptr<ReplaySource> open_timeshift(const std::string& channel,
                                                       boost::asio::any_io_executor executor,
                                                       std::string& error) {
    (void)channel;
    (void)executor;
    error = "time shift is not available";
    return nullptr;
  }
  // The recordings as JSON (/recordings).
  virtual std::string list_json() = 0;
};

}  // namespace mc::relay

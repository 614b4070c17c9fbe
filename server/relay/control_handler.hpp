// What the relay asks its owner to do when an authorised operator calls a
// control endpoint (POST /control/ACTION?channel=NAME with a bearer token).
// The relay checks the token; the owner knows what feeds and recordings are.
#pragma once

#include <string>

namespace mc::relay {

class ControlHandler {
 public:
  virtual ~ControlHandler() = default;
  // `action` is the path after /control/ ("feed/stop", "recording/start",
  // ...). Returns false with `message` when the action or channel is
  // unknown or cannot be done; true with a short `message` otherwise.
  virtual bool control(const std::string& action, const std::string& channel,
                       std::string& message) = 0;
};

}  // namespace mc::relay

// An outbound WebSocket message, encoded once and shared, immutable, by every
// session that sends it (Beast chat-multi's shared_ptr<const std::string>).
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

namespace mc::relay {

struct Message {
  enum class Kind : std::uint8_t { Control, Keyframe, Delta };

  std::shared_ptr<const std::string> bytes;
  Kind kind = Kind::Control;
  // When the channel published it: the start of the relay's frame delay.
  std::chrono::steady_clock::time_point published{};

  bool binary() const { return kind != Kind::Control; }
  // Control messages (JSON) are never dropped; deltas may be, keyframes end a skip.
  bool droppable() const { return kind == Kind::Delta; }
  std::size_t size() const { return bytes ? bytes->size() : 0; }

  static Message control(std::string text) {
    return {std::make_shared<const std::string>(std::move(text)), Kind::Control,
            std::chrono::steady_clock::now()};
  }
  static Message frame(std::string data, bool keyframe) {
    return {std::make_shared<const std::string>(std::move(data)),
            keyframe ? Kind::Keyframe : Kind::Delta, std::chrono::steady_clock::now()};
  }
};

}  // namespace mc::relay

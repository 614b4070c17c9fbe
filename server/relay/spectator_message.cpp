#include "server/relay/spectator_message.hpp"

#include <cstdint>
#include <string_view>

#include "proto/json_sax.hpp"

namespace mc::relay {
namespace {

// RapidJSON's SAX handler over one message. It keeps the four members a
// spectator's message is read for and passes over everything else, so a
// message costs no tree: the relay reads every spectator's every message,
// and a tree was most of that (a map node and a string per member).
class MessageReader {
 public:
  using SizeType = rapidjson::SizeType;

  SpectatorMessage message;
  bool type_is_string = false;

  bool Null() { return other(); }
  bool Bool(bool) { return other(); }
  bool Int(int v) { return number(v); }
  bool Uint(unsigned v) { return number(v); }
  bool Int64(std::int64_t v) { return number(static_cast<double>(v)); }
  bool Uint64(std::uint64_t v) { return number(static_cast<double>(v)); }
  bool Double(double v) { return number(v); }
  bool String(const char* s, SizeType size, bool) {
    if (depth_ != 1) return top_level_ok();
    if (field_ == Field::Type) {
      message.type.assign(s, size);
      type_is_string = true;
    } else if (field_ == Field::Action) {
      message.action.assign(s, size);
    } else {
      set_other();
    }
    return true;
  }
  bool StartObject() { return open(); }
  bool StartArray() {
    if (depth_ == 0) return false;  // an array, not an object: stop here
    return open();
  }
  bool EndObject(SizeType) { return close(); }
  bool EndArray(SizeType) { return close(); }
  bool Key(const char* k, SizeType size, bool) {
    if (depth_ == 1) {
      const std::string_view key(k, size);
      field_ = key == "type" ? Field::Type
             : key == "action" ? Field::Action
             : key == "time" ? Field::Time
             : key == "speed" ? Field::Speed
                              : Field::Other;
    }
    return true;
  }

 private:
  enum class Field { Other, Type, Action, Time, Speed };

  // A scalar at the top is not an object: stop. Below the top level the
  // value belongs to a member's nested value, which nothing reads.
  bool top_level_ok() const { return depth_ > 0; }
  bool other() {
    if (depth_ == 1) set_other();
    return top_level_ok();
  }
  bool number(double v) {
    if (depth_ == 1) {
      if (field_ == Field::Time) message.time = v;
      else if (field_ == Field::Speed) message.speed = v;
      else set_other();
    }
    return top_level_ok();
  }
  // A member whose last value is not of its type reads as absent.
  void set_other() {
    if (field_ == Field::Type) type_is_string = false;
    else if (field_ == Field::Action) message.action.clear();
    else if (field_ == Field::Time) message.time.reset();
    else if (field_ == Field::Speed) message.speed.reset();
  }
  bool open() {
    if (depth_ == 1) set_other();  // a member's value is an object or array
    ++depth_;
    return true;
  }
  bool close() {
    --depth_;
    return true;
  }

  int depth_ = 0;  // 1 inside the message's own object
  Field field_ = Field::Other;
};

}  // namespace

std::optional<SpectatorMessage> read_spectator_message(std::string_view text) {
  MessageReader reader;
  // The whole text must be one JSON object (proto/json_sax.hpp).
  if (!proto::read_json_sax(text, reader) || !reader.type_is_string) return std::nullopt;
  return std::move(reader.message);
}

}  // namespace mc::relay

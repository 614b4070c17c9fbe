#include "server/relay/spectator_message.hpp"

#include <nlohmann/json.hpp>

#include "proto/json_text.hpp"

namespace mc::relay {
namespace {

// nlohmann's SAX interface over one message. It keeps the four members a
// spectator's message is read for and passes over everything else, so a
// message costs no tree: the relay reads every spectator's every message,
// and a tree was most of that (a map node and a string per member).
class MessageReader {
 public:
  using json = nlohmann::json;

  SpectatorMessage message;
  bool type_is_string = false;

  bool null() { return other(); }
  bool boolean(bool) { return other(); }
  bool number_integer(json::number_integer_t v) { return number(static_cast<double>(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return number(static_cast<double>(v)); }
  bool number_float(json::number_float_t v, const json::string_t&) { return number(v); }
  bool string(json::string_t& s) {
    if (depth_ != 1) return top_level_ok();
    if (field_ == Field::Type) {
      message.type = std::move(s);
      type_is_string = true;
    } else if (field_ == Field::Action) {
      message.action = std::move(s);
    } else {
      set_other();
    }
    return true;
  }
  bool binary(json::binary_t&) { return other(); }  // never from JSON text
  bool start_object(std::size_t) { return open(); }
  bool start_array(std::size_t) {
    if (depth_ == 0) return false;  // an array, not an object: stop here
    return open();
  }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(json::string_t& k) {
    if (depth_ == 1) {
      field_ = k == "type" ? Field::Type
             : k == "action" ? Field::Action
             : k == "time" ? Field::Time
             : k == "speed" ? Field::Speed
                            : Field::Other;
    }
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) { return false; }

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

// A message is one JSON object: its first and last characters other than
// JSON's whitespace are braces. Text that fails this is refused before the
// parser, which would refuse it too, but only after building an exception
// (a message string) for it: junk from a hostile or broken client costs no
// more than a look at its ends.
bool may_be_json_object(std::string_view text) {
  constexpr std::string_view kSpace = " \t\n\r";
  const std::size_t first = text.find_first_not_of(kSpace);
  const std::size_t last = text.find_last_not_of(kSpace);
  return first != std::string_view::npos && text[first] == '{' && text[last] == '}';
}

}  // namespace

std::optional<SpectatorMessage> read_spectator_message(std::string_view text) {
  MessageReader reader;
  // sax_parse is strict: the whole text must be one JSON value.
  if (!may_be_json_object(text) || !proto::may_be_json_text(text)) return std::nullopt;
  if (!nlohmann::json::sax_parse(text.begin(), text.end(), &reader) || !reader.type_is_string) return std::nullopt;
  return std::move(reader.message);
}

}  // namespace mc::relay

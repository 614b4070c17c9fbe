// Strict SAX reading of JSON text written elsewhere (a game log's records,
// a spectator's messages), through RapidJSON's reader: no tree, and no
// allocation once the thread's reader has sized its stack. Strict means one
// value per text (RFC 8259), numbers as exact doubles, strings that are
// UTF-8 and hold no surrogate (a lone "\udc00" escape too, which RapidJSON
// 1.1 lets through), and a NUL byte read as a byte, never as the end.
// Iterative: a hostile text nested a million deep cannot exhaust the call
// stack.
//
// The handler has Null(), Bool(bool), Number(double), String(string_view),
// StartObject(), Key(string_view), EndObject(), StartArray(), EndArray(),
// each returning false to stop; every number reaches it as a double, the
// way JSON means numbers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>

#include <rapidjson/memorystream.h>
#include <rapidjson/reader.h>

namespace mc::proto {
namespace json_sax_detail {

// UTF-8 of a surrogate code point (U+D800..U+DFFF) is ED A0..BF xx: the
// reader decodes a "\udc00" escape into it; text that is UTF-8 never has it.
inline bool has_surrogate(const char* s, std::size_t n) {
  for (const char* p = s; (p = static_cast<const char*>(std::memchr(p, '\xed', n - static_cast<std::size_t>(p - s))));) {
    if (++p == s + n) return false;
    if ((static_cast<unsigned char>(*p) & 0xe0) == 0xa0) return true;
  }
  return false;
}

// RapidJSON's handler interface over H's: numbers as doubles, text as
// string_view, and a string or key with a surrogate refused.
template <typename H>
struct Adapter {
  using SizeType = rapidjson::SizeType;
  H& h;
  bool Null() { return h.Null(); }
  bool Bool(bool b) { return h.Bool(b); }
  bool Int(int v) { return h.Number(v); }
  bool Uint(unsigned v) { return h.Number(v); }
  bool Int64(std::int64_t v) { return h.Number(static_cast<double>(v)); }
  bool Uint64(std::uint64_t v) { return h.Number(static_cast<double>(v)); }
  bool Double(double v) { return h.Number(v); }
  bool RawNumber(const char*, SizeType, bool) { return false; }  // only with kParseNumbersAsStringsFlag
  bool String(const char* s, SizeType n, bool) { return !has_surrogate(s, n) && h.String(std::string_view(s, n)); }
  bool StartObject() { return h.StartObject(); }
  bool Key(const char* s, SizeType n, bool) { return !has_surrogate(s, n) && h.Key(std::string_view(s, n)); }
  bool EndObject(SizeType) { return h.EndObject(); }
  bool StartArray() { return h.StartArray(); }
  bool EndArray(SizeType) { return h.EndArray(); }
};

}  // namespace json_sax_detail

// True when `text` is exactly one valid JSON value and the handler took
// every event of it.
template <typename Handler>
bool read_json_sax(std::string_view text, Handler& handler) {
  thread_local rapidjson::Reader reader;  // its stack holds the string being read
  constexpr unsigned kFlags =
      rapidjson::kParseIterativeFlag | rapidjson::kParseFullPrecisionFlag | rapidjson::kParseValidateEncodingFlag;
  json_sax_detail::Adapter<Handler> strict{handler};
  rapidjson::MemoryStream in(text.data(), text.size());
  // The stream gives NUL at its end, and the reader stops at a NUL: one
  // inside the text must not end it early with what follows unread.
  return !reader.Parse<kFlags>(in, strict).IsError() && in.Tell() == text.size();
}

}  // namespace mc::proto

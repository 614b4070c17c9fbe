// Strict SAX reading of JSON text written elsewhere (a game log's records,
// a spectator's messages), through RapidJSON's reader: no tree, and no
// allocation once the thread's reader has sized its stack. Strict means one
// value per text (RFC 8259), numbers as exact doubles, strings that are
// UTF-8 and hold no surrogate (a lone "\udc00" escape too, which RapidJSON
// 1.1 lets through), and a NUL byte read as a byte, never as the end.
// Iterative: a hostile text nested a million deep cannot exhaust the call
// stack.
//
// The handler is RapidJSON's: Null(), Bool(b), Int(i), Uint(u), Int64(i),
// Uint64(u), Double(d), RawNumber(..) (never called), String(s, n, copy),
// StartObject(), Key(s, n, copy), EndObject(n), StartArray(), EndArray(n),
// each returning false to stop.
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

// Forwards every event to H; refuses a string or key with a surrogate.
template <typename H>
struct NoSurrogates {
  using SizeType = rapidjson::SizeType;
  H& h;
  bool Null() { return h.Null(); }
  bool Bool(bool b) { return h.Bool(b); }
  bool Int(int v) { return h.Int(v); }
  bool Uint(unsigned v) { return h.Uint(v); }
  bool Int64(std::int64_t v) { return h.Int64(v); }
  bool Uint64(std::uint64_t v) { return h.Uint64(v); }
  bool Double(double v) { return h.Double(v); }
  bool RawNumber(const char*, SizeType, bool) { return false; }  // only with kParseNumbersAsStringsFlag
  bool String(const char* s, SizeType n, bool copy) { return !has_surrogate(s, n) && h.String(s, n, copy); }
  bool StartObject() { return h.StartObject(); }
  bool Key(const char* s, SizeType n, bool copy) { return !has_surrogate(s, n) && h.Key(s, n, copy); }
  bool EndObject(SizeType n) { return h.EndObject(n); }
  bool StartArray() { return h.StartArray(); }
  bool EndArray(SizeType n) { return h.EndArray(n); }
};

}  // namespace json_sax_detail

// True when `text` is exactly one valid JSON value and the handler took
// every event of it.
template <typename Handler>
bool read_json_sax(std::string_view text, Handler& handler) {
  thread_local rapidjson::Reader reader;  // its stack holds the string being read
  constexpr unsigned kFlags =
      rapidjson::kParseIterativeFlag | rapidjson::kParseFullPrecisionFlag | rapidjson::kParseValidateEncodingFlag;
  json_sax_detail::NoSurrogates<Handler> strict{handler};
  rapidjson::MemoryStream in(text.data(), text.size());
  // The stream gives NUL at its end, and the reader stops at a NUL: one
  // inside the text must not end it early with what follows unread.
  return !reader.Parse<kFlags>(in, strict).IsError() && in.Tell() == text.size();
}

}  // namespace mc::proto

// Cuts a JSON game log into its top-level objects without parsing the whole
// file: a 19.x log is one array `[ {..}, {..}, .. ]` of ~7000 objects, and
// 17.x/18.x logs put a header line ("ULG6", "JSON") before the array. Each
// `{...}` whose brace opens at nesting depth 0 (square brackets aside) is one
// element; everything between elements (commas, brackets, header lines) is
// skipped. Strings and escapes are tracked so braces inside them don't count.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "server/ingest/byte_source.hpp"
#include "server/ingest/read_window.hpp"

namespace mc::ingest {

class JsonSplitter {
 public:
  explicit JsonSplitter(ByteSource& src, std::size_t max_object = 8u << 20);

  enum class Result { Object, TooLong, Truncated, End };
  // Object: `obj` is the next element (valid until the next call), `offset`
  // its decoded byte offset. TooLong: an element over max_object bytes was
  // skipped. Truncated: the input ended inside an element (dropped).
  Result next(std::string_view& obj, std::uint64_t& offset);
  std::uint64_t bytes_read() const { return w_.consumed(); }

 private:
  ReadWindow w_;
  std::size_t max_object_;
};

}  // namespace mc::ingest

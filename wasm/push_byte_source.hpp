// A ByteSource the caller fills: the page reads a log in chunks (and
// gunzips it with the browser's DecompressionStream), then hands each chunk
// to the log reader through this. The reader pulls as from a file.
//
// A reader cannot wait for bytes that have not arrived: a read that finds
// the buffer empty before end() is an end of input to it. So the caller
// runs the reader only while at least a margin of bytes is buffered (or the
// input has ended), and starved() tells when a record needed more than that
// (the reader then saw a false end and cannot go on).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "server/ingest/byte_source.hpp"

namespace mc::wasm {

class PushByteSource : public ingest::ByteSource {
 public:
  // Appends decoded bytes. Memory: the unread bytes plus this chunk.
  void append(std::string_view bytes);
  // No more bytes will come; `error` is non-empty when the input broke off
  // (a truncated gzip stream, a read error): it is what error() says.
  void end(std::string error = {});

  std::size_t read(char* dst, std::size_t n) override;
  const std::string& error() const override { return error_; }
  std::uint64_t raw_offset() const override { return consumed_; }

  // Unread bytes, and the first of them (for sniffing the format).
  std::size_t buffered() const { return buf_.size() - begin_; }
  std::string_view peek(std::size_t n) const;
  bool ended() const { return ended_; }
  // A read found no byte before end(): the reader took it for the end.
  bool starved() const { return starved_; }
  // Bytes appended so far, and bytes the reader took.
  std::uint64_t received() const { return received_; }
  std::uint64_t consumed() const { return consumed_; }

 private:
  std::vector<char> buf_;
  std::size_t begin_ = 0;
  std::uint64_t received_ = 0, consumed_ = 0;
  bool ended_ = false, starved_ = false;
  std::string error_;
};

}  // namespace mc::wasm

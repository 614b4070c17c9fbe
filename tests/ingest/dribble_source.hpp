// A ByteSource that hands out at most `step` bytes per read: a record, a
// line or an escape split across reads, as a slow pipe or socket splits them.
#pragma once

#include <algorithm>
#include <cstring>
#include <string>

#include "server/ingest/byte_source.hpp"

namespace mc::ingest {

class DribbleSource final : public ByteSource {
 public:
  DribbleSource(std::string data, std::size_t step) : data_(std::move(data)), step_(step) {}
  std::size_t read(char* dst, std::size_t n) override {
    const std::size_t k = std::min({n, step_, data_.size() - pos_});
    std::memcpy(dst, data_.data() + pos_, k);
    pos_ += k;
    return k;
  }
  const std::string& error() const override { return err_; }
  std::uint64_t raw_offset() const override { return pos_; }

 private:
  std::string data_;
  std::size_t step_, pos_ = 0;
  std::string err_;
};

}  // namespace mc::ingest

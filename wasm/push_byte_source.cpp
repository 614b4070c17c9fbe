#include "wasm/push_byte_source.hpp"

#include <algorithm>
#include <cstring>

namespace mc::wasm {

void PushByteSource::append(std::string_view bytes) {
  if (ended_ || bytes.empty()) return;
  // Move the unread bytes to the front once the read part dominates, so the
  // buffer stays near the unread size instead of growing with the input.
  if (begin_ > 0 && begin_ >= buf_.size() / 2) {
    buf_.erase(buf_.begin(), buf_.begin() + static_cast<std::ptrdiff_t>(begin_));
    begin_ = 0;
  }
  buf_.insert(buf_.end(), bytes.begin(), bytes.end());
  received_ += bytes.size();
}

void PushByteSource::end(std::string error) {
  ended_ = true;
  error_ = std::move(error);
}

std::size_t PushByteSource::read(char* dst, std::size_t n) {
  const std::size_t k = std::min(n, buffered());
  if (k == 0) {
    if (!ended_ && n > 0) starved_ = true;
    return 0;
  }
  std::memcpy(dst, buf_.data() + begin_, k);
  begin_ += k;
  consumed_ += k;
  return k;
}

std::string_view PushByteSource::peek(std::size_t n) const {
  return std::string_view(buf_.data() + begin_, std::min(n, buffered()));
}

}  // namespace mc::wasm

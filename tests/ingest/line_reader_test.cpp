// LineReader: offsets, a missing final newline, over-long lines skipped
// with their offset, and lines split across source reads.
#include "server/ingest/line_reader.hpp"

#include <gtest/gtest.h>

#include <cstring>

namespace mc::ingest {
namespace {

// Hands out at most `step` bytes per read, to split lines across reads.
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

struct Got {
  std::vector<std::string> lines;
  std::vector<std::uint64_t> offsets;
  std::vector<std::uint64_t> too_long;
};

Got read_all(ByteSource& src, std::size_t max_line) {
  LineReader r(src, max_line);
  Got g;
  std::string_view line;
  std::uint64_t off = 0;
  for (int guard = 0; guard < 100000; ++guard) {
    const auto res = r.next(line, off);
    if (res == LineReader::Result::End) break;
    if (res == LineReader::Result::TooLong) {
      g.too_long.push_back(off);
      continue;
    }
    g.lines.emplace_back(line);
    g.offsets.push_back(off);
  }
  return g;
}

TEST(LineReader, LinesAndOffsets) {
  DribbleSource s("ab\n\ncde\nlast", 3);
  const Got g = read_all(s, 100);
  ASSERT_EQ(g.lines, (std::vector<std::string>{"ab", "", "cde", "last"}));
  EXPECT_EQ(g.offsets, (std::vector<std::uint64_t>{0, 3, 4, 8}));
}

TEST(LineReader, OverlongLinesAreSkippedWithTheirOffset) {
  const std::string big(5000, 'x');
  for (std::size_t step : {1u, 7u, 4096u, 1u << 20}) {
    DribbleSource s("ok\n" + big + "\nafter\n" + big, step);
    const Got g = read_all(s, 1000);
    EXPECT_EQ(g.lines, (std::vector<std::string>{"ok", "after"})) << step;
    EXPECT_EQ(g.too_long, (std::vector<std::uint64_t>{3, 3 + big.size() + 1 + 6})) << step;
  }
}

TEST(LineReader, LongLinesWithinTheLimitSpanManyReads) {
  const std::string big(3u << 20, 'y');  // larger than the internal chunk
  DribbleSource s(big + "\nz\n", 1u << 16);
  const Got g = read_all(s, 8u << 20);
  ASSERT_EQ(g.lines.size(), 2u);
  EXPECT_EQ(g.lines[0].size(), big.size());
  EXPECT_EQ(g.offsets[1], big.size() + 1);
}

}  // namespace
}  // namespace mc::ingest

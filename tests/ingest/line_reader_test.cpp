// LineReader: offsets, a missing final newline, over-long lines skipped
// with their offset, and lines split across source reads.
#include "server/ingest/line_reader.hpp"

#include <gtest/gtest.h>

#include "tests/ingest/dribble_source.hpp"

namespace mc::ingest {
namespace {

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

// SexpCursor: the number fast path must agree bit for bit with
// std::from_chars; hex states, "-0", exponents, bounds.
#include "server/ingest/sexp_cursor.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <random>

namespace mc::ingest {
namespace {

double parse(std::string_view s, bool& ok) {
  SexpCursor c(s);
  double v = 0;
  ok = c.number(v);
  return v;
}

TEST(SexpCursor, FastPathMatchesFromCharsBitForBit) {
  std::mt19937_64 rng(42);
  char buf[64];
  for (int i = 0; i < 200000; ++i) {
    const int int_digits = static_cast<int>(rng() % 8);
    const int frac_digits = static_cast<int>(rng() % 9);
    std::string s = rng() % 2 ? "-" : "";
    s += std::to_string(rng() % 10);
    for (int k = 0; k < int_digits; ++k) s += static_cast<char>('0' + rng() % 10);
    if (frac_digits) {
      s += '.';
      for (int k = 0; k < frac_digits; ++k) s += static_cast<char>('0' + rng() % 10);
    }
    bool ok = false;
    const double got = parse(s, ok);
    double want = 0;
    std::from_chars(s.data(), s.data() + s.size(), want);
    ASSERT_TRUE(ok) << s;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(want)) << s;
  }
  (void)buf;
}

TEST(SexpCursor, SpecialNumbers) {
  bool ok = false;
  EXPECT_TRUE(std::signbit(parse("-0", ok)));
  EXPECT_TRUE(ok);
  EXPECT_DOUBLE_EQ(parse("1e-05", ok), 1e-05);
  EXPECT_TRUE(ok);
  EXPECT_DOUBLE_EQ(parse("0.00111743)", ok), 0.00111743);
  EXPECT_TRUE(ok);
  EXPECT_DOUBLE_EQ(parse("12345678901234567890", ok), 12345678901234567890.0);
  EXPECT_TRUE(ok);
  parse("nan", ok);
  EXPECT_FALSE(ok);
  parse("inf", ok);
  EXPECT_FALSE(ok);
  parse("1x", ok);
  EXPECT_FALSE(ok);
  parse("", ok);
  EXPECT_FALSE(ok);
  parse("-", ok);
  EXPECT_FALSE(ok);
}

TEST(SexpCursor, HexStatesIncludingBareZero) {
  std::uint32_t v = 1;
  SexpCursor a("0 0x9 0x80100 0x");
  EXPECT_TRUE(a.hex(v));
  EXPECT_EQ(v, 0u);
  EXPECT_TRUE(a.hex(v));
  EXPECT_EQ(v, 9u);
  EXPECT_TRUE(a.hex(v));
  EXPECT_EQ(v, 0x80100u);
  EXPECT_FALSE(a.hex(v));
  SexpCursor big("0x1ffffffff");
  EXPECT_FALSE(big.hex(v));
}

TEST(SexpCursor, IntegersAndRanges) {
  SexpCursor c("12 -3 4.0 4.5 99999999999999999999 7");
  std::int64_t v = 0;
  EXPECT_TRUE(c.integer(v));
  EXPECT_EQ(v, 12);
  EXPECT_TRUE(c.integer(v));
  EXPECT_EQ(v, -3);
  EXPECT_TRUE(c.integer(v));
  EXPECT_EQ(v, 4);
  EXPECT_FALSE(c.integer(v));  // 4.5
  double skip = 0;
  EXPECT_TRUE(c.number(skip));
  EXPECT_FALSE(c.integer(v));  // too big for an exact integer
  EXPECT_TRUE(c.number(skip));
  int small = 0;
  EXPECT_FALSE(c.integer_in(small, 0, 5));  // 7 out of range, not consumed
  EXPECT_TRUE(c.integer_in(small, 0, 10));
  EXPECT_EQ(small, 7);
  EXPECT_TRUE(c.at_end());
}

TEST(SexpCursor, GroupsAndKeywords) {
  SexpCursor c("(show (a \"x)(\" (b)) rest");
  EXPECT_TRUE(c.lit('('));
  EXPECT_FALSE(c.keyword("sho"));
  EXPECT_TRUE(c.keyword("show"));
  EXPECT_TRUE(c.skip_group());
  std::string_view s;
  EXPECT_TRUE(c.symbol(s));
  EXPECT_EQ(s, "rest");
  SexpCursor open("(a (b");
  EXPECT_FALSE(open.skip_group());
}

}  // namespace
}  // namespace mc::ingest

// from_chars_double (fast_float): the same value, end and error as the
// native std::from_chars (libstdc++), bit for bit, so that swapping it in
// changed no frame; and the cases the WebAssembly build relies on.
#include "proto/float_chars.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <string>

namespace mc {
namespace {

void expect_same_as_std(const std::string& s) {
  double want = 12345, got = 12345;
  const auto w = std::from_chars(s.data(), s.data() + s.size(), want);
  const auto g = from_chars_double(s.data(), s.data() + s.size(), got);
  ASSERT_EQ(static_cast<int>(g.ec), static_cast<int>(w.ec)) << '"' << s << '"';
  ASSERT_EQ(g.ptr - s.data(), w.ptr - s.data()) << '"' << s << '"';
  if (std::isnan(want)) {
    ASSERT_TRUE(std::isnan(got)) << s;
  } else {
    ASSERT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(want)) << '"' << s << '"';
  }
}

TEST(FloatChars, RandomDecimalsAndExponentsMatchStdBitForBit) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 300000; ++i) {
    std::string s = rng() % 3 == 0 ? "-" : "";
    const int int_digits = static_cast<int>(rng() % 22);
    const int frac_digits = static_cast<int>(rng() % 22);
    for (int k = 0; k < int_digits; ++k) s += static_cast<char>('0' + rng() % 10);
    if (frac_digits || int_digits == 0) {
      s += '.';
      for (int k = 0; k < frac_digits + (int_digits == 0); ++k) s += static_cast<char>('0' + rng() % 10);
    }
    if (rng() % 4 == 0) s += (rng() % 2 ? "e" : "E") + std::to_string(static_cast<int>(rng() % 700) - 350);
    if (rng() % 5 == 0) s += ")";
    expect_same_as_std(s);
  }
}

TEST(FloatChars, EdgeCasesMatchStd) {
  for (const char* s : {"0", "-0", ".5", "-.5", "5.", "1e5", "1e", "1e+", "1e-05", "0x1p3", "+1", " 1",
                        "", "-", ".", "e5", "inf", "-inf", "INF", "infinity", "nan", "-nan",
                        "1.7976931348623157e308", "4.9e-324", "2.2250738585072014e-308",
                        "0.1000000000000000055511151231257827", "130600", "12345678901234567890",
                        "3.0)", "1,5", "9007199254740993"})
    expect_same_as_std(s);
}

TEST(FloatChars, OverflowIsOutOfRangeAndLeavesTheValue) {
  const std::string s = "1e400";
  double v = 3;
  const auto r = from_chars_double(s.data(), s.data() + s.size(), v);
  EXPECT_EQ(r.ec, std::errc::result_out_of_range);
  EXPECT_EQ(v, 3);
  const std::string n = "-1e999";
  EXPECT_EQ(from_chars_double(n.data(), n.data() + n.size(), v).ec, std::errc::result_out_of_range);
  EXPECT_EQ(v, 3);
}

}  // namespace
}  // namespace mc

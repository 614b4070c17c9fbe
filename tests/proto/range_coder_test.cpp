#include "proto/range_coder.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "proto/residual_coder.hpp"

namespace mc::proto {
namespace {

TEST(RangeCoder, BitsAndDirectBitsRoundTrip) {
  std::mt19937 rng(3);
  std::vector<int> bits;
  std::vector<std::uint32_t> directs;
  RangeEncoder enc;
  Prob p[4] = {kProbInit, kProbInit, kProbInit, kProbInit};
  for (int i = 0; i < 5000; ++i) {
    const int b = static_cast<int>(rng() % 10) < (i % 4) * 3 ? 1 : 0;  // differently skewed contexts
    bits.push_back(b);
    enc.encode_bit(p[i % 4], b != 0);
    if (i % 7 == 0) {
      directs.push_back(rng());
      enc.encode_direct(directs.back(), 32);
    }
  }
  const std::string bytes = enc.finish();
  RangeDecoder dec(bytes);
  Prob q[4] = {kProbInit, kProbInit, kProbInit, kProbInit};
  std::size_t di = 0;
  for (int i = 0; i < 5000; ++i) {
    ASSERT_EQ(dec.decode_bit(q[i % 4]) ? 1 : 0, bits[static_cast<std::size_t>(i)]) << i;
    if (i % 7 == 0) {
      ASSERT_EQ(dec.decode_direct(32), directs[di++]);
    }
  }
  EXPECT_FALSE(dec.overrun());
  EXPECT_EQ(dec.consumed(), bytes.size());  // a valid stream is read exactly to its end
}

TEST(RangeCoder, NearCertainBitsCostLittle) {
  RangeEncoder enc;
  Prob p = kProbInit;
  for (int i = 0; i < 8000; ++i) enc.encode_bit(p, false);
  EXPECT_LT(enc.finish().size(), 40u);  // 8000 bits in well under 1 bit each
}

TEST(RangeCoder, TruncatedInputSetsOverrun) {
  RangeEncoder enc;
  Prob p = kProbInit;
  for (int i = 0; i < 400; ++i) enc.encode_bit(p, i % 3 == 0);
  const std::string bytes = enc.finish();
  RangeDecoder dec(std::string_view(bytes).substr(0, bytes.size() - 1));
  Prob q = kProbInit;
  for (int i = 0; i < 400; ++i) dec.decode_bit(q);
  EXPECT_TRUE(dec.overrun());
}

TEST(ResidualCoder, SignedValuesRoundTripAcrossMagnitudes) {
  std::vector<std::int64_t> values = {0, 1, -1, 2, -2, 3, 100, -100, 65535, -65536, 4294967295LL, -4294967295LL};
  std::mt19937 rng(5);
  for (int i = 0; i < 3000; ++i) values.push_back(static_cast<std::int64_t>(rng() % 41) - 20);
  RangeEncoder enc;
  SignedModel m;
  for (std::size_t i = 0; i < values.size(); ++i)
    encode_signed(enc, m, values[i], static_cast<int>(i % kZeroContexts), static_cast<int>(i % kActivityClasses));
  const std::string bytes = enc.finish();
  RangeDecoder dec(bytes);
  SignedModel n;
  for (std::size_t i = 0; i < values.size(); ++i)
    ASSERT_EQ(decode_signed(dec, n, static_cast<int>(i % kZeroContexts), static_cast<int>(i % kActivityClasses)), values[i]);
  EXPECT_FALSE(dec.overrun());
}

TEST(ResidualCoder, ActivityClasses) {
  EXPECT_EQ(activity_class(0), 0);
  EXPECT_EQ(activity_class(-1), 1);
  EXPECT_EQ(activity_class(4), 2);
  EXPECT_EQ(activity_class(-5), 3);
}

}  // namespace
}  // namespace mc::proto

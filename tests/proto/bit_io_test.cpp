#include "proto/bit_io.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace mc::proto {
namespace {

TEST(BitIo, FieldsRoundTripLsbFirst) {
  BitWriter w;
  w.put(1, 1);
  w.put(0x5, 3);
  w.put(0xabcd, 16);
  w.put(0xffffffffu, 32);
  w.put_varbits(0);
  w.put_varbits(1);
  w.put_varbits(0x409);
  const std::string bytes = w.finish();
  EXPECT_EQ(static_cast<unsigned char>(bytes[0]) & 0x0f, 0x0b);  // 1, then 101 above it
  BitReader r(bytes);
  EXPECT_EQ(r.get(1), 1u);
  EXPECT_EQ(r.get(3), 5u);
  EXPECT_EQ(r.get(16), 0xabcdu);
  EXPECT_EQ(r.get(32), 0xffffffffu);
  EXPECT_EQ(r.get_varbits(), 0u);
  EXPECT_EQ(r.get_varbits(), 1u);
  EXPECT_EQ(r.get_varbits(), 0x409u);
  EXPECT_FALSE(r.overrun());
}

TEST(BitIo, ReadingPastTheEndSetsOverrunAndReturnsZero) {
  const std::string one_byte(1, '\xff');
  BitReader r(one_byte);
  EXPECT_EQ(r.get(8), 0xffu);
  EXPECT_FALSE(r.overrun());
  EXPECT_EQ(r.get(4), 0u);
  EXPECT_TRUE(r.overrun());
}

TEST(BitIo, ZigzagMapsSmallMagnitudesToSmallCodes) {
  EXPECT_EQ(zigzag(0), 0u);
  EXPECT_EQ(zigzag(-1), 1u);
  EXPECT_EQ(zigzag(1), 2u);
  EXPECT_EQ(zigzag(-2), 3u);
  for (std::int32_t v : {0, 1, -1, 1000, -1000, 2147483647, -2147483647 - 1}) EXPECT_EQ(unzigzag(zigzag(v)), v);
}

TEST(BitIo, AdaptiveRiceRoundTripsIncludingEscapes) {
  std::mt19937 rng(7);
  std::vector<std::int32_t> values;
  for (int i = 0; i < 2000; ++i) {
    const int scale = (i / 200) % 3 == 0 ? 2 : (i / 200) % 3 == 1 ? 200 : 100000;
    values.push_back(static_cast<std::int32_t>(rng() % (2 * scale + 1)) - scale);
  }
  values.push_back(2147483647);
  values.push_back(-2147483647 - 1);
  BitWriter w;
  RiceContext enc;
  for (auto v : values) enc.write(w, v);
  const std::string bytes = w.finish();
  BitReader r(bytes);
  RiceContext dec;
  for (auto v : values) ASSERT_EQ(dec.read(r), v);
  EXPECT_FALSE(r.overrun());
}

TEST(BitIo, RiceAdaptsSoThatZerosCostAboutOneBit) {
  BitWriter w;
  RiceContext c;
  for (int i = 0; i < 800; ++i) c.write(w, 0);
  EXPECT_LT(w.finish().size(), 120u);
}

}  // namespace
}  // namespace mc::proto

// Numbers in JSON from elsewhere: an integer field holding 1.6e81, or a
// float field holding 1e300, is refused with a reason, never converted
// (undefined behaviour). The cases are those the fuzzers found.
#include "proto/json_number.hpp"

#include <gtest/gtest.h>

#include "proto/control_messages.hpp"
#include "proto/hello.hpp"
#include "tests/proto/support/synthetic.hpp"

namespace mc::proto {
namespace {

TEST(JsonNumber, IntegersInRangeAndWholeFloatsPassTheRestIsRefused) {
  using nlohmann::json;
  EXPECT_EQ(json_integer<int>(json(42)), 42);
  EXPECT_EQ(json_integer<int>(json(-7)), -7);
  EXPECT_EQ(json_integer<int>(json(12.0)), 12);
  EXPECT_EQ(json_integer<std::uint32_t>(json(4294967295u)), 4294967295u);
  EXPECT_EQ(json_integer<std::uint64_t>(json(18446744073709551615ull)), 18446744073709551615ull);
  EXPECT_THROW(json_integer<int>(json(1.66667e81)), std::out_of_range);
  EXPECT_THROW(json_integer<int>(json(12.5)), std::out_of_range);
  EXPECT_THROW(json_integer<int>(json(4294967296ll)), std::out_of_range);
  EXPECT_THROW(json_integer<std::uint32_t>(json(-1)), std::out_of_range);
  EXPECT_THROW(json_integer<std::uint32_t>(json(-0.5)), std::out_of_range);
  EXPECT_THROW(json_integer<int>(json("12")), std::invalid_argument);
  EXPECT_FLOAT_EQ(json_float(json(1.5)), 1.5f);
  EXPECT_THROW(json_float(json(1e300)), std::out_of_range);
  EXPECT_THROW(json_float(json(true)), std::invalid_argument);
}

TEST(JsonNumber, ControlMessagesAndHelloRefuseNumbersOutOfRange) {
  ControlMessage m;
  std::string error;
  EXPECT_FALSE(control_from_json(R"({"type":"director","seq":1,"time":1.66667e81,"cut":true,"shot":"wide"})", m, error));
  EXPECT_FALSE(error.empty());
  EXPECT_FALSE(control_from_json(R"({"type":"score","seq":1e20,"time":5,"left":0,"right":1})", m, error));
  Hello h;
  h.skeleton = testing::humanoid_skeleton();
  auto j = nlohmann::json::parse(to_json(h));
  EXPECT_TRUE(hello_from_json(j.dump(), h, error)) << error;
  j["keyframe_interval"] = 1e300;
  EXPECT_FALSE(hello_from_json(j.dump(), h, error));
  j = nlohmann::json::parse(to_json(h));
  j["skeleton"]["joints"][1]["offset"][0] = 1e300;
  EXPECT_FALSE(hello_from_json(j.dump(), h, error));
}

}  // namespace
}  // namespace mc::proto

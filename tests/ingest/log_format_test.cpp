// Format sniffing from the first decoded bytes (never the file name).
#include "server/ingest/log_format.hpp"

#include <gtest/gtest.h>

namespace mc::ingest {
namespace {

TEST(LogFormat, EveryHeader) {
  EXPECT_EQ(sniff_log_format(std::string_view("\x00\x02\x00\x01(referee", 12)), LogFormat::BinaryV1);
  EXPECT_EQ(sniff_log_format(std::string_view("\x00\x01\x01\x00", 4)), LogFormat::BinaryV1);
  EXPECT_EQ(sniff_log_format(std::string_view("ULG\x02\x00\x01", 6)), LogFormat::BinaryV2);
  EXPECT_EQ(sniff_log_format(std::string_view("ULG\x03\x00\x08", 6)), LogFormat::BinaryV3);
  EXPECT_EQ(sniff_log_format("ULG4\n(server_param"), LogFormat::TextV4);
  EXPECT_EQ(sniff_log_format("ULG5\n(server_param"), LogFormat::TextV5);
  EXPECT_EQ(sniff_log_format("ULG6\n(server_param"), LogFormat::TextV6);
  EXPECT_EQ(sniff_log_format("ULG6\n[\n{\"type\""), LogFormat::Json17);
  EXPECT_EQ(sniff_log_format("JSON\n[{"), LogFormat::Json18);
  EXPECT_EQ(sniff_log_format("[\n{\"version\""), LogFormat::Json19);
  EXPECT_EQ(sniff_log_format("ULG7\n"), LogFormat::Unknown);
  EXPECT_EQ(sniff_log_format("hello"), LogFormat::Unknown);
  EXPECT_EQ(sniff_log_format(""), LogFormat::Unknown);
  EXPECT_EQ(sniff_log_format("U"), LogFormat::Unknown);
}

}  // namespace
}  // namespace mc::ingest

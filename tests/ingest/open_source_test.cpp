// open_source(): log paths and udp:// specs for the live feed.
#include "server/ingest/state_source.hpp"

#include <gtest/gtest.h>

#include "server/ingest/monitor_client.hpp"
#include "tests/ingest/test_data.hpp"

namespace mc::ingest {
namespace {

TEST(OpenSource, LogPathsGoToOpenLog) {
  std::string err;
  EXPECT_TRUE(open_source(testing::rcg("real/20190926071807-HELIOS_base_0-vs-null.rcg"), err)) << err;
  EXPECT_FALSE(open_source("/nonexistent.rcg", err));
  EXPECT_FALSE(is_live_spec("/x/udp://y"));
}

TEST(OpenSource, UdpSpecs) {
  std::string err;
  for (const char* ok : {"udp://", "udp://127.0.0.1:6000", "udp://127.0.0.1:6000/-1", "udp://:6100", "udp://localhost/3"}) {
    auto src = open_source(ok, err);
    ASSERT_TRUE(src) << ok << ": " << err;
    EXPECT_TRUE(dynamic_cast<MonitorClient*>(src.get())) << ok;
  }
  for (const char* bad : {"udp://127.0.0.1:0", "udp://127.0.0.1:x", "udp://127.0.0.1:6000/7", "udp://no.such.host.invalid:6000"})
    EXPECT_FALSE(open_source(bad, err)) << bad;
}

}  // namespace
}  // namespace mc::ingest

// The control-message DEFLATE (proto/text_deflate.hpp): round trips, and the
// refusals. Each thread keeps one inflater and resets it per chunk, so a
// refused stream must leave nothing behind: the next chunk inflates exactly.
#include "proto/text_deflate.hpp"

#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

namespace mc::proto::rec {
namespace {

const std::string kText =
    R"({"left":[8000,7743],"right":[8000,7539],"seq":4,"time":12,"type":"stamina"})" "\n"
    R"({"contact_time_ms":313250,"foot":"left","seq":5,"side":"right","time":12,"type":"kick","unum":10})" "\n";

TEST(TextDeflate, RoundTrip) {
  const std::string z = deflate_text(kText);
  ASSERT_FALSE(z.empty());
  EXPECT_LT(z.size(), kText.size() / 2);  // the dictionary has every key
  std::string out;
  ASSERT_TRUE(inflate_text(z, kText.size(), out));
  EXPECT_EQ(out, kText);
}

TEST(TextDeflate, ARefusedStreamLeavesTheNextWhole) {
  const std::string z = deflate_text(kText);
  std::string corrupt = z;
  corrupt[corrupt.size() / 2] = static_cast<char>(corrupt[corrupt.size() / 2] ^ 0x5a);
  const std::vector<std::pair<std::string, std::size_t>> refused = {
      {z.substr(0, z.size() / 2), kText.size()},  // cut short
      {z + "junk", kText.size()},                // runs on
      {z, kText.size() - 1},                     // longer than said
      {z, kText.size() + 1},                     // shorter than said
      {std::string(40, '\xff'), kText.size()},   // not deflate
  };
  for (const auto& [bytes, size] : refused) {
    std::string out;
    EXPECT_FALSE(inflate_text(bytes, size, out)) << bytes.size() << " bytes, size " << size;
    std::string good;
    ASSERT_TRUE(inflate_text(z, kText.size(), good));
    EXPECT_EQ(good, kText);
  }
  std::string out;
  (void)inflate_text(corrupt, kText.size(), out);  // refused, or other text: as the flipped bit falls
  ASSERT_TRUE(inflate_text(z, kText.size(), out));
  EXPECT_EQ(out, kText);
}

TEST(TextDeflate, ThreadsInflateAtOnce) {
  const std::string z = deflate_text(kText);
  std::vector<int> good(4, 0);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < good.size(); ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < 200; ++i) {
        std::string out;
        if (inflate_text(z, kText.size(), out) && out == kText) ++good[t];
        inflate_text(z.substr(0, 10), kText.size(), out);  // a refusal between
      }
    });
  for (auto& th : threads) th.join();
  for (const int g : good) EXPECT_EQ(g, 200);
}

}  // namespace
}  // namespace mc::proto::rec

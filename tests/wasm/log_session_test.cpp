// LogSession (wasm/log_session.hpp) natively: the page's way of reading a
// log (decoded bytes pushed in chunks, the reader run only with a margin
// buffered) makes exactly what the server's reader and pipeline make from
// the file, for every log version; and each kind of bad input ends with a
// message, never a hang.
#include "wasm/log_session.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "server/ingest/byte_source.hpp"
#include "wasm/log_reference.hpp"

namespace mc::wasm {
namespace {

const std::string kGenerated = std::string(MATCHCAST_TEST_RCG_DIR) + "/generated/";

// The decoded bytes of a log (gzip inflated by the server's byte source).
std::string decoded(const std::string& path) {
  std::string error;
  auto src = ingest::open_file_source(path, error);
  EXPECT_TRUE(src) << error;
  std::string out;
  char buf[1 << 16];
  while (src && true) {
    const std::size_t n = src->read(buf, sizeof buf);
    if (n == 0) break;
    out.append(buf, n);
  }
  return out;
}

struct Fed {
  LogSession::Status status = LogSession::Status::NeedInput;
  std::string out;
  std::string status_json;
  int steps = 0;
};

// Feeds `bytes` in random chunks of 1 B .. `max_chunk`, as the worker does:
// input while the session wants it, then a step of a few states.
Fed feed(LogSessionOptions options, const std::string& bytes, std::size_t max_chunk, std::uint64_t seed,
         const std::string& end_error = {}) {
  LogSession s(std::move(options));
  std::mt19937_64 rng(seed);
  std::size_t at = 0;
  Fed r;
  for (int guard = 0; guard < 10000000; ++guard) {
    while (s.wants() > 0 && at < bytes.size()) {
      const std::size_t n = std::min<std::size_t>(bytes.size() - at, 1 + rng() % max_chunk);
      s.input(std::string_view(bytes).substr(at, n));
      at += n;
    }
    if (at == bytes.size() && s.wants() > 0) s.end_input(end_error);
    r.status = s.step(1 + static_cast<int>(rng() % 50));
    ++r.steps;
    r.out += s.output();
    s.clear_output();
    if (r.status == LogSession::Status::Done || r.status == LogSession::Status::Failed) break;
  }
  r.status_json = s.status_json();
  return r;
}

LogSessionOptions options_for(const std::string& id) {
  LogSessionOptions o;
  o.match_id = id;
  o.server_time_base_ms = 1764000000000;
  o.margin_bytes = 256 << 10;
  return o;
}

class EveryVersion : public ::testing::TestWithParam<const char*> {};

TEST_P(EveryVersion, StreamedInChunksItMakesTheServerPipelinesBytes) {
  const std::string path = kGenerated + GetParam();
  const LogSessionOptions o = options_for("x.rcg");
  std::string want, error;
  ASSERT_TRUE(broadcast_log_file(path, o, want, error)) << error;
  const std::string bytes = decoded(path);
  for (std::size_t chunk : {std::size_t{1} << 20, std::size_t{4096}, std::size_t{97}}) {
    const Fed r = feed(o, bytes, chunk, chunk);
    EXPECT_EQ(r.status, LogSession::Status::Done) << r.status_json;
    ASSERT_EQ(r.out.size(), want.size()) << GetParam() << " chunk " << chunk;
    EXPECT_TRUE(r.out == want) << GetParam() << " chunk " << chunk;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Logs, EveryVersion,
    ::testing::Values("gen19-v1-20261122025913-Alpha_0-vs-Beta_0.rcg.gz",
                      "gen19-v2-20261122025747-Alpha_1-vs-Beta_2.rcg.gz",
                      "gen19-v3-20261122025631-Alpha_0-vs-Beta_1.rcg.gz",
                      "gen19-v4-20261122025515-Alpha_1-vs-Beta_0.rcg.gz",
                      "gen19-v5-20261122025405-Alpha_0-vs-Beta_0.rcg.gz",
                      "gen19-v6-20261122025254-Alpha_0-vs-Beta_0.rcg.gz",
                      "gen19-json-20261122030023-Alpha_1-vs-Beta_1.rcg.gz"));

TEST(LogSession, NotALogSaysSo) {
  std::mt19937_64 rng(9);
  std::string junk(100000, '\0');
  for (char& c : junk) c = static_cast<char>(rng());
  junk[0] = 'P';  // not a v1 record either
  const Fed r = feed(options_for("junk"), junk, 4096, 1);
  EXPECT_EQ(r.status, LogSession::Status::Failed);
  EXPECT_NE(r.status_json.find("not a game log"), std::string::npos) << r.status_json;
  EXPECT_TRUE(r.out.empty());
}

TEST(LogSession, AnUnsupportedVersionIsNamed) {
  const Fed r = feed(options_for("v7"), "ULG7\n(server_param (goal_width 14.02))\n", 4096, 1);
  EXPECT_EQ(r.status, LogSession::Status::Failed);
  EXPECT_NE(r.status_json.find("version 7"), std::string::npos) << r.status_json;
}

TEST(LogSession, EmptyAndStillCompressedInput) {
  Fed r = feed(options_for("empty"), "", 4096, 1);
  EXPECT_EQ(r.status, LogSession::Status::Failed);
  EXPECT_NE(r.status_json.find("empty"), std::string::npos) << r.status_json;
  r = feed(options_for("gz"), std::string("\x1f\x8b\x08\x00rest of a gzip stream", 25), 4096, 1);
  EXPECT_EQ(r.status, LogSession::Status::Failed);
  EXPECT_NE(r.status_json.find("gzip"), std::string::npos) << r.status_json;
}

TEST(LogSession, ALogWithoutStatesSaysSo) {
  const Fed r = feed(options_for("nostates"), "ULG5\n(server_param (goal_width 14.02))\n", 4096, 1);
  EXPECT_EQ(r.status, LogSession::Status::Failed);
  EXPECT_NE(r.status_json.find("no game states"), std::string::npos) << r.status_json;
}

TEST(LogSession, ACutLogPlaysUpToTheCutAndSaysWhy) {
  const std::string bytes = decoded(kGenerated + "gen19-v5-20261122025405-Alpha_0-vs-Beta_0.rcg.gz");
  const std::string half = bytes.substr(0, bytes.size() / 2);
  const Fed r = feed(options_for("cut"), half, 65536, 3, "the gzip stream ends early");
  EXPECT_EQ(r.status, LogSession::Status::Done) << r.status_json;
  EXPECT_NE(r.status_json.find("\"ended_early\":\"the gzip stream ends early\""), std::string::npos) << r.status_json;
  // About half the game's 600 cycles went out, as frames.
  const auto t = r.status_json.find("\"time\":");
  ASSERT_NE(t, std::string::npos);
  const int time = std::stoi(r.status_json.substr(t + 7));
  EXPECT_GT(time, 200);
  EXPECT_LT(time, 400);
  EXPECT_GT(r.out.size(), 100000u);
}

TEST(LogSession, AReaderThatWouldOutrunTheMarginStopsWithAMessage) {
  LogSessionOptions o = options_for("tiny-margin");
  o.margin_bytes = 64;  // less than one parameter line
  const std::string bytes = decoded(kGenerated + "gen19-v6-20261122025254-Alpha_0-vs-Beta_0.rcg.gz");
  const Fed r = feed(o, bytes, 128, 4);
  EXPECT_EQ(r.status, LogSession::Status::Failed);
  EXPECT_NE(r.status_json.find("longer than"), std::string::npos) << r.status_json;
}

TEST(LogSession, AHugeLogStopsAtTheStateCap) {
  LogSessionOptions o = options_for("capped");
  o.max_states = 100;
  const std::string bytes = decoded(kGenerated + "gen19-v4-20261122025515-Alpha_1-vs-Beta_0.rcg.gz");
  const Fed r = feed(o, bytes, 1 << 20, 5);
  EXPECT_EQ(r.status, LogSession::Status::Done);
  EXPECT_NE(r.status_json.find("\"capped\":100"), std::string::npos) << r.status_json;
  EXPECT_NE(r.status_json.find("\"states\":100"), std::string::npos) << r.status_json;
}

}  // namespace
}  // namespace mc::wasm

// What the server tells strangers: no message a spectator receives (live,
// replay, time shift, their errors) and no HTTP answer (pages, errors,
// lists, control) names a path on the server's file system. The server here
// is assembled as main.cpp does: feeds, recorder, replay catalog, relay.
#include <gtest/gtest.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "proto/hello.hpp"
#include "proto/match_id.hpp"
#include "server/app/feed_control.hpp"
#include "server/app/recorder.hpp"
#include "server/record/recording_writer.hpp"
#include "server/relay/relay_server.hpp"
#include "server/replay/replay_catalog.hpp"
#include "tests/relay/channel_collector.hpp"
#include "tests/relay/ws_test_client.hpp"

namespace fs = std::filesystem;
using mc::relay::testing::WsTestClient;

namespace mc::app {
namespace {

const std::string kLog = std::string(MATCHCAST_SOURCE_DIR) +
                         "/data/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz";

// The whole answer to one raw HTTP request (the connection is closed after it).
std::string http_exchange(std::uint16_t port, const std::string& request) {
  boost::asio::io_context ioc;
  boost::asio::ip::tcp::socket s(ioc);
  s.connect({boost::asio::ip::make_address("127.0.0.1"), port});
  boost::asio::write(s, boost::asio::buffer(request));
  std::string out;
  boost::system::error_code ec;
  char buf[4096];
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  s.non_blocking(true);
  while (std::chrono::steady_clock::now() < deadline) {
    const std::size_t n = s.read_some(boost::asio::buffer(buf), ec);
    if (ec == boost::asio::error::would_block) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      continue;
    }
    if (ec) break;
    out.append(buf, n);
  }
  return out;
}

std::string get(std::uint16_t port, const std::string& target, const std::string& extra = "",
                const std::string& method = "GET") {
  return http_exchange(port, method + " " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n" +
                                 extra + "\r\n");
}

std::string upgrade(std::uint16_t port, const std::string& target) {
  return get(port, target,
             "Upgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 13\r\n"
             "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n");
}

class ServerPathsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mc-paths-" + std::to_string(::getpid()));
    fs::create_directories(dir_ / "web");
    fs::create_directories(dir_ / "recordings");
    fs::create_directories(dir_ / "logs");
    fs::copy_file(kLog, dir_ / "logs" / "copy.rcg.gz");
    channels_ = std::make_shared<relay::ChannelRegistry>();
    feeds_ = std::make_unique<FeedControl>(channels_);
    FeedConfig feed;
    feed.log_path = kLog;
    feed.speed = 10;
    std::string error;
    ASSERT_TRUE(feeds_->add("live", feed, error)) << error;
    feed.log_path = (dir_ / "logs" / "copy.rcg.gz").string();
    ASSERT_TRUE(feeds_->add("copy", feed, error)) << error;
    recorder_ = Recorder::start(channels_->find("live"), (dir_ / "recordings" / "live.mcrec").string(), error);
    ASSERT_TRUE(recorder_) << error;
    catalog_ = std::make_unique<replay::ReplayCatalog>((dir_ / "recordings").string());
    catalog_->set_live_recording("live", "live.mcrec");
    // A channel said to be recorded into a file that is not there: the
    // reader's error names the file.
    channels_->open("ghost")->set_hello(R"({"type":"hello"})");
    catalog_->set_live_recording("ghost", "ghost.mcrec");
    write_legacy_recording();
    relay::RelayConfig config;
    config.port = 0;
    config.web_root = (dir_ / "web").string();
    config.threads = 2;
    config.control_token = "secret";
    server_ = std::make_unique<relay::RelayServer>(config, channels_, feeds_.get(), catalog_.get());
    ASSERT_TRUE(server_->start(error)) << error;
    for (int i = 0; i < 500 && fs::file_size(dir_ / "recordings" / "live.mcrec") < 20000; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  void TearDown() override {
    if (server_) server_->stop();
    if (feeds_) feeds_->stop_all();
    if (recorder_) recorder_->stop();
    fs::remove_all(dir_);
  }

  // A recording made before match_ids were public: its hello names the log
  // by its path on the server.
  void write_legacy_recording() {
    auto collector = std::make_shared<relay::testing::ChannelCollector>();
    auto live = channels_->find("live");
    auto first = live->join(collector);
    for (int i = 0; i < 300 && collector->count() < 60; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    live->leave(collector.get());
    auto hello = nlohmann::json::parse(*first.at(0).bytes);
    // Built from parts: the repository check refuses any home path in a tracked file.
    hello["match_id"] = std::string("/") + "home" + "/operator/secret-folder/legacy.rcg.gz";
    record::RecordingWriter writer;
    std::string error;
    ASSERT_TRUE(writer.open((dir_ / "recordings" / "legacy.mcrec").string(), hello.dump(), error)) << error;
    auto all = first;
    for (auto& m : collector->snapshot()) all.push_back(m);
    for (std::size_t i = 1; i < all.size(); ++i)
      ASSERT_TRUE(all[i].binary() ? writer.add_frame(*all[i].bytes, error) : writer.add_control(*all[i].bytes, error))
          << error;
    ASSERT_TRUE(writer.close(error)) << error;
  }

  // Every text message of the next `n` messages of `c`, or of those that
  // come before a second of silence (a replay at its end says no more).
  static void read_texts(WsTestClient& c, int n, std::vector<std::string>& texts) {
    for (int i = 0; i < n; ++i) {
      relay::testing::Received m;
      try {
        m = c.read(std::chrono::seconds(1));
      } catch (const boost::system::system_error&) {
        return;
      }
      if (!m.binary) texts.push_back(m.data);
    }
  }

  // Fails for each text that names a server path.
  void expect_no_path(const std::vector<std::string>& texts, const std::string& what) {
    // Two or more path components after a '/' that does not end a scheme
    // ("http://" is not a path): "/srv/x", "/tmp/mc-paths-1/recordings".
    static const std::regex kPath(R"((^|[^:/A-Za-z0-9_.-])/[A-Za-z0-9_.-]+/[A-Za-z0-9_.-]+)");
    const std::vector<std::string> secrets = {dir_.string(), MATCHCAST_SOURCE_DIR, fs::current_path().string(),
                                              "secret-folder", "/home/", ".rcg", "udp://"};
    for (const auto& t : texts) {
      for (const auto& s : secrets) EXPECT_EQ(t.find(s), std::string::npos) << what << " names '" << s << "': " << t;
      EXPECT_FALSE(std::regex_search(t, kPath)) << what << " holds a path: " << t;
    }
  }

  fs::path dir_;
  std::shared_ptr<relay::ChannelRegistry> channels_;
  std::unique_ptr<FeedControl> feeds_;
  std::shared_ptr<Recorder> recorder_;
  std::unique_ptr<replay::ReplayCatalog> catalog_;
  std::unique_ptr<relay::RelayServer> server_;
};

TEST(MatchId, IsTheGameNameNeverAPathOrAnAddress) {
  EXPECT_EQ(proto::match_id_of_source("/srv/x/data/20261122-A_1-vs-B_5.rcg.gz", "A", "B"), "20261122-A_1-vs-B_5");
  EXPECT_EQ(proto::match_id_of_source("C:\\logs\\game.rcg", "", ""), "game");
  EXPECT_EQ(proto::match_id_of_source("relative/dir/game.json", "", ""), "game");
  EXPECT_EQ(proto::match_id_of_source("udp://10.0.0.7:6000", "HELIOS", "CYRUS"), "HELIOS-vs-CYRUS");
  EXPECT_EQ(proto::match_id_of_source("udp://10.0.0.7:6000", "", ""), "live");
  EXPECT_EQ(proto::public_match_id("final"), "final");
  EXPECT_EQ(proto::hello_without_paths(R"({"type":"hello","match_id":"plain"})"),
            R"({"type":"hello","match_id":"plain"})");
  EXPECT_EQ(nlohmann::json::parse(proto::hello_without_paths(R"({"type":"hello","match_id":"/srv/a/b.rcg.gz"})"))
                .value("match_id", ""),
            "b");
}

TEST_F(ServerPathsTest, NoSpectatorMessageNamesAServerPath) {
  std::vector<std::string> texts;
  {
    WsTestClient live(server_->port(), "/ws?channel=live");
    read_texts(live, 40, texts);
    ASSERT_FALSE(texts.empty());
    proto::Hello hello;
    std::string error;
    ASSERT_TRUE(proto::hello_from_json(texts.front(), hello, error)) << error;
    EXPECT_EQ(hello.match_id, "20261122030423-HELIOS_A_1-vs-HELIOS_B_5");
    // Time shift into the channel's recording, and back.
    live.write_text(R"({"type":"timeshift","action":"seek","time":10})");
    read_texts(live, 40, texts);
    live.write_text(R"({"type":"timeshift","action":"live"})");
    read_texts(live, 10, texts);
  }
  {
    // A time shift that fails because the recording cannot be read.
    WsTestClient ghost(server_->port(), "/ws?channel=ghost");
    ghost.write_text(R"({"type":"timeshift","action":"seek","time":10})");
    read_texts(ghost, 2, texts);
    EXPECT_NE(texts.back().find("\"error\""), std::string::npos) << texts.back();
  }
  {
    // The replay of a recording whose hello still names the log's path.
    WsTestClient replay(server_->port(), "/ws?recording=legacy.mcrec");
    std::vector<std::string> legacy;
    read_texts(replay, 10, legacy);
    ASSERT_FALSE(legacy.empty());
    EXPECT_EQ(nlohmann::json::parse(legacy.front()).value("match_id", ""), "legacy");
    replay.write_text(R"({"type":"replay","action":"seek","time":1000000})");
    read_texts(replay, 5, legacy);
    texts.insert(texts.end(), legacy.begin(), legacy.end());
  }
  expect_no_path(texts, "a spectator message");
}

TEST_F(ServerPathsTest, NoHttpAnswerNamesAServerPath) {
  const auto port = server_->port();
  // The copy's log goes away: starting its feed again fails, and the
  // operator's answer does not name the file either.
  std::vector<std::string> answers = {
      get(port, "/no-such-file.html"),
      get(port, "/../../etc/passwd"),
      get(port, "/%2e%2e/%2e%2e/etc/passwd"),
      get(port, "/recordings"),
      get(port, "/channels"),
      get(port, "/metrics"),
      get(port, "/healthz"),
      get(port, "/", "", "DELETE"),
      upgrade(port, "/ws?recording=../../etc/passwd"),
      upgrade(port, "/ws?recording=nope.mcrec"),
      upgrade(port, "/ws?channel=nope"),
      upgrade(port, "/elsewhere"),
      get(port, "/control/feed/stop?channel=copy", "", "POST"),
      get(port, "/control/feed/stop?channel=copy", "Authorization: Bearer secret\r\n", "POST"),
  };
  fs::remove(dir_ / "logs" / "copy.rcg.gz");
  answers.push_back(get(port, "/control/feed/start?channel=copy", "Authorization: Bearer secret\r\n", "POST"));
  EXPECT_NE(answers.back().find("400 Bad Request"), std::string::npos) << answers.back();
  answers.push_back(http_exchange(port, "GARBAGE\r\n\r\n"));
  answers.push_back(http_exchange(port, "GET / HTTP/1.1\r\nHost: x\r\nContent-Length: 99999999\r\n\r\n"));
  for (const auto& a : answers) EXPECT_NE(a.find("HTTP/1.1 "), std::string::npos) << "no answer: " << a;
  expect_no_path(answers, "an HTTP answer");
}

}  // namespace
}  // namespace mc::app

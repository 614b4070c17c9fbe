// What a WebSocket spectator of the NATS tests receives, recorded on its own
// thread with arrival times, and the checks on frame sequences.
#pragma once

#include <sys/socket.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "proto/frame_header.hpp"
#include "tests/relay/ws_test_client.hpp"

namespace mc::nats::testing {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

struct Frame {
  std::uint32_t seq = 0;
  bool key = false;
  std::string bytes;
  Clock::time_point at;
};

// A WebSocket client like tests/relay's WsTestClient, whose connect and
// handshake are bounded too: a server that never answers the upgrade fails
// the test instead of hanging it.
class BoundedWsClient {
 public:
  BoundedWsClient(std::uint16_t port, const std::string& target, std::chrono::milliseconds timeout = 10s)
      : ws_(ioc_) {
    const boost::asio::ip::tcp::endpoint ep(boost::asio::ip::make_address("127.0.0.1"), port);
    boost::system::error_code result = boost::asio::error::timed_out;
    bool done = false;
    ws_.next_layer().async_connect(ep, [&](boost::system::error_code ec) {
      if (ec) {
        result = ec;
        done = true;
        return;
      }
      ws_.async_handshake("127.0.0.1", target, [&](boost::system::error_code ec2) {
        result = ec2;
        done = true;
      });
    });
    ioc_.run_for(timeout);
    if (!done) abandon();
    if (result) throw boost::system::system_error(result);
  }
  // One message; throws on close, or timed_out after `timeout`.
  mc::relay::testing::Received read(std::chrono::milliseconds timeout) {
    boost::beast::flat_buffer buf;
    boost::system::error_code result = boost::asio::error::timed_out;
    bool done = false;
    ws_.async_read(buf, [&](boost::system::error_code ec, std::size_t) {
      result = ec;
      done = true;
    });
    ioc_.restart();
    ioc_.run_for(timeout);
    if (!done) {
      abandon();
      throw boost::system::system_error(boost::asio::error::timed_out);
    }
    if (result) throw boost::system::system_error(result);
    return {ws_.got_binary(), boost::beast::buffers_to_string(buf.data())};
  }
  boost::beast::websocket::stream<boost::asio::ip::tcp::socket>& stream() { return ws_; }

 private:
  // Ends an operation that did not complete: the connection is unusable.
  void abandon() {
    boost::system::error_code ignored;
    ws_.next_layer().close(ignored);
    ioc_.restart();
    ioc_.run_for(std::chrono::seconds(1));
  }
  boost::asio::io_context ioc_;
  boost::beast::websocket::stream<boost::asio::ip::tcp::socket> ws_;
};

// One spectator reading on its own thread until the connection ends.
class Spectator {
 public:
  explicit Spectator(std::uint16_t port, const std::string& target = "/ws") : client_(port, target) {
    thread_ = std::thread([this] {
      try {
        for (;;) {
          auto m = client_.read(30s);
          std::lock_guard lock(mutex_);
          if (!m.binary) {
            texts_.push_back({m.data, Clock::now(), frames_.size()});
            continue;
          }
          Frame f;
          mc::proto::FrameHeader h;
          std::string error;
          if (!mc::proto::peek_header(m.data, h, error)) {
            ++bad_;
            continue;
          }
          f.seq = h.seq;
          f.key = h.keyframe;
          f.bytes = std::move(m.data);
          f.at = Clock::now();
          frames_.push_back(std::move(f));
        }
      } catch (const std::exception&) {
        // The server's close frame, if it sent one.
        std::lock_guard lock(mutex_);
        close_code_ = client_.stream().reason().code;
        close_reason_ = std::string(client_.stream().reason().reason.c_str());
        closed_at_ = Clock::now();
        closed_ = true;
      }
    });
  }
  ~Spectator() {
    // Ends the reader's blocking read (shutdown(2) is safe from any thread),
    // then waits for it: the client must outlive its reader.
    ::shutdown(client_.stream().next_layer().native_handle(), SHUT_RDWR);
    if (thread_.joinable()) thread_.join();
  }
  struct Text {
    std::string data;
    Clock::time_point at;
    std::size_t frames_before;  // frames received before this message
  };
  std::vector<Frame> frames() {
    std::lock_guard lock(mutex_);
    return frames_;
  }
  std::vector<Text> texts() {
    std::lock_guard lock(mutex_);
    return texts_;
  }
  std::size_t frame_count() {
    std::lock_guard lock(mutex_);
    return frames_.size();
  }
  bool closed() const { return closed_; }
  int bad() const { return bad_; }
  // After closed(): the close frame's code and reason (0 and "": none), and when.
  std::uint16_t close_code() {
    std::lock_guard lock(mutex_);
    return close_code_;
  }
  std::string close_reason() {
    std::lock_guard lock(mutex_);
    return close_reason_;
  }
  Clock::time_point closed_at() {
    std::lock_guard lock(mutex_);
    return closed_at_;
  }

 private:
  BoundedWsClient client_;
  std::thread thread_;
  std::mutex mutex_;
  std::vector<Frame> frames_;
  std::vector<Text> texts_;
  std::atomic<bool> closed_{false};
  std::atomic<int> bad_{0};
  std::uint16_t close_code_ = 0;
  std::string close_reason_;
  Clock::time_point closed_at_{};
};

// Waits until `pred` or `timeout`; returns pred().
template <class Pred>
bool eventually(Pred pred, std::chrono::milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  while (!pred() && Clock::now() < deadline) std::this_thread::sleep_for(50ms);
  return pred();
}

// Every seq from first to last present once, in order.
inline ::testing::AssertionResult consecutive(const std::vector<Frame>& f, std::size_t from = 0) {
  for (std::size_t i = from + 1; i < f.size(); ++i)
    if (f[i].seq != f[i - 1].seq + 1)
      return ::testing::AssertionFailure() << "seq " << f[i - 1].seq << " then " << f[i].seq << " (frame " << i << ")";
  return ::testing::AssertionSuccess();
}

// What a spectator saw, for failure messages.
inline std::string describe(Spectator& s) {
  std::string out;
  for (const auto& t : s.texts()) out += "[after " + std::to_string(t.frames_before) + " frames] " + t.data.substr(0, 120) + "\n";
  const auto f = s.frames();
  out += std::to_string(f.size()) + " frames";
  for (std::size_t i = 1; i < f.size(); ++i)
    if (f[i].seq != f[i - 1].seq + 1 || f[i].key)
      out += ", #" + std::to_string(i) + " seq " + std::to_string(f[i].seq) + (f[i].key ? "K" : "D");
  return out;
}

// A spectator that joined as its edge was syncing may get the snapshot's
// keyframe, then (after a jump) the live stream from the next keyframe;
// from there on everything is in sequence. True when that jump, if any, is
// within the first `within` frames.
inline ::testing::AssertionResult in_sequence_after_sync(const std::vector<Frame>& f, std::size_t within = 45) {
  for (std::size_t i = 0; i < f.size() && i < within; ++i)
    if (f[i].key && consecutive(f, i)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "no keyframe among the first " << within
                                       << " frames from which all is in sequence: " << consecutive(f);
}

}  // namespace mc::nats::testing

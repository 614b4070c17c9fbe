#include "viewer/ws_source.hpp"

#include <algorithm>
#include <chrono>
#include <deque>
#include <optional>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>

#include "proto/control_messages.hpp"
#include "proto/frame_header.hpp"
#include "proto/frame_codec.hpp"

namespace mc::viewer {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

bool parse_ws_url(const std::string& text, WsUrl& out, std::string& error) {
  std::string rest = text;
  bool page = false;
  for (const char* scheme : {"ws://", "http://"}) {
    if (rest.rfind(scheme, 0) == 0) {
      rest = rest.substr(std::string(scheme).size());
      page = scheme[0] == 'h';
    }
  }
  if (rest.rfind("wss://", 0) == 0 || rest.rfind("https://", 0) == 0) {
    error = "TLS (wss://, https://) is not supported by the viewer: " + text;
    return false;
  }
  const auto slash = rest.find_first_of("/?");
  const std::string authority = rest.substr(0, slash);
  std::string target = slash == std::string::npos ? "" : rest.substr(slash);
  if (target.empty() || target == "/" || (page && target.rfind("/ws", 0) != 0)) {
    // The page's address (or a bare host): the stream is /ws, keep the query.
    const auto q = target.find('?');
    target = "/ws" + (q == std::string::npos ? std::string() : target.substr(q));
  } else if (target[0] == '?') {
    target = "/ws" + target;
  }
  const auto colon = authority.rfind(':');
  WsUrl url;
  url.host = authority.substr(0, colon);
  if (colon != std::string::npos) url.port = authority.substr(colon + 1);
  url.target = target;
  const bool digits = !url.port.empty() && url.port.size() <= 5 &&
                      std::all_of(url.port.begin(), url.port.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (url.host.empty() || !digits) {
    error = "not a relay address (expected ws://HOST:PORT/ws): " + text;
    return false;
  }
  out = url;
  return true;
}

// Everything that lives on the io_context thread. Handlers capture `this`:
// the thread is joined before the session is destroyed.
struct WsSource::Session {
  Session(WsSource& owner) : owner(owner), resolver(ioc), timer(ioc) {}

  WsSource& owner;
  asio::io_context ioc;
  tcp::resolver resolver;
  asio::steady_timer timer;
  std::optional<websocket::stream<beast::tcp_stream>> ws;
  beast::flat_buffer read_buffer;
  std::unique_ptr<proto::FrameDecoder> decoder;  // large: on the heap
  PoseFrame frame;
  double backoff_s = 0;
  bool stopping = false;
  bool open = false;
  std::deque<std::string> outbox;
  bool writing = false;

  std::string where() const { return owner.url_.host + ":" + owner.url_.port + owner.url_.target; }

  void connect() {
    if (stopping) return;
    ++owner.attempts_;
    ws.emplace(ioc);
    decoder.reset();
    resolver.async_resolve(owner.url_.host, owner.url_.port,
                           [this](beast::error_code ec, tcp::resolver::results_type results) {
                             if (ec) return fail("cannot resolve", ec);
                             beast::get_lowest_layer(*ws).expires_after(std::chrono::seconds(5));
                             beast::get_lowest_layer(*ws).async_connect(
                                 results, [this](beast::error_code ec2, const tcp::endpoint&) { on_connect(ec2); });
                           });
  }

  void on_connect(beast::error_code ec) {
    if (ec) return fail("cannot connect to", ec);
    beast::get_lowest_layer(*ws).expires_after(std::chrono::seconds(5));
    ws->async_handshake(owner.url_.host + ":" + owner.url_.port, owner.url_.target,
                        [this](beast::error_code ec2) { on_handshake(ec2); });
  }

  void on_handshake(beast::error_code ec) {
    if (ec) return fail("WebSocket handshake failed with", ec);
    beast::get_lowest_layer(*ws).expires_never();
    ws->set_option(websocket::stream_base::timeout::suggested(beast::role_type::client));
    ws->read_message_max(4u << 20);
    open = true;
    owner.buffer_.set_status("connected to " + where() + ", waiting for the hello");
    do_read();
    flush();
  }

  void do_read() {
    ws->async_read(read_buffer, [this](beast::error_code ec, std::size_t) { on_read(ec); });
  }

  void on_read(beast::error_code ec) {
    if (ec) {
      open = false;
      owner.buffer_.set_connected(false);
      return fail("connection lost to", ec);
    }
    const std::string_view bytes(static_cast<const char*>(read_buffer.data().data()), read_buffer.size());
    if (ws->got_text())
      on_text(bytes);
    else
      on_binary(bytes);
    read_buffer.consume(read_buffer.size());
    backoff_s = 0;  // a working connection resets the backoff
    do_read();
  }

  void on_text(std::string_view text) {
    std::string error;
    const std::string type = proto::control_type(text, error);
    if (type == "hello") {
      proto::Hello hello;
      if (!proto::hello_from_json(text, hello, error)) {
        owner.buffer_.set_status("the relay's hello is not usable: " + error);
        return;
      }
      decoder = std::make_unique<proto::FrameDecoder>(hello.skeleton);
      owner.buffer_.set_hello(hello);
      owner.buffer_.set_status("");
      return;
    }
    if (type == "replay") {
      const auto j = nlohmann::json::parse(text, nullptr, false);
      if (j.is_object() && j.contains("speed") && j["speed"].is_number())
        owner.speed_ = std::clamp(j["speed"].get<double>(), 0.25, 8.0);
      if (j.is_object() && j.contains("paused") && j["paused"].is_boolean()) owner.paused_ = j["paused"].get<bool>();
      return;
    }
    apply_control_message(text, owner.buffer_);
  }

  void on_binary(std::string_view bytes) {
    if (!decoder) {
      ++owner.corrupt_;
      return;
    }
    proto::FrameHeader header;
    std::string error;
    if (!proto::peek_header(bytes, header, error) || !decoder->decode(bytes, frame, error)) {
      // The decoder now waits for the next keyframe (at most 1 s).
      ++owner.corrupt_;
      owner.buffer_.set_status("frame refused (" + error + "), waiting for the next keyframe");
      return;
    }
    ++owner.frames_;
    owner.last_time_ = frame.time;
    owner.buffer_.set_connected(true);
    if (header.keyframe && owner.corrupt_ > 0) owner.buffer_.set_status("");
    owner.buffer_.push(frame, header.keyframe);
  }

  void fail(const std::string& what, beast::error_code ec) {
    if (stopping) return;
    open = false;
    outbox.clear();
    writing = false;
    backoff_s = backoff_s == 0 ? owner.retry_.initial_s : std::min(backoff_s * 2, owner.retry_.max_s);
    char delay[32];
    std::snprintf(delay, sizeof delay, "%.1f", backoff_s);
    owner.buffer_.set_connected(false);
    owner.buffer_.set_status(what + " ws://" + where() + ": " + ec.message() + "; retrying in " + delay +
                             " s (attempt " + std::to_string(owner.attempts_.load()) + ")");
    beast::error_code ignored;
    beast::get_lowest_layer(*ws).socket().close(ignored);
    timer.expires_after(std::chrono::milliseconds(static_cast<int>(backoff_s * 1000)));
    timer.async_wait([this](beast::error_code ec2) {
      if (!ec2) connect();
    });
  }

  void send(std::string text) {
    if (!open) return;
    outbox.push_back(std::move(text));
    flush();
  }

  void flush() {
    if (writing || outbox.empty() || !open) return;
    writing = true;
    ws->text(true);
    ws->async_write(asio::buffer(outbox.front()), [this](beast::error_code ec, std::size_t) {
      writing = false;
      if (ec) return;  // the read side reports the failure
      outbox.pop_front();
      flush();
    });
  }

  void shutdown() {
    stopping = true;
    timer.cancel();
    resolver.cancel();
    if (ws) {
      beast::error_code ignored;
      beast::get_lowest_layer(*ws).socket().close(ignored);
    }
  }
};

WsSource::WsSource(WsUrl url, FrameBuffer& buffer, RetryPolicy retry)
    : url_(std::move(url)), buffer_(buffer), retry_(retry) {}

WsSource::~WsSource() { stop(); }

void WsSource::start() {
  if (session_) return;
  session_ = std::make_shared<Session>(*this);
  buffer_.set_status("connecting to ws://" + session_->where());
  session_->connect();
  thread_ = std::thread([s = session_] { s->ioc.run(); });
}

void WsSource::stop() {
  if (!session_) return;
  asio::post(session_->ioc, [s = session_.get()] { s->shutdown(); });
  // Handlers finish quickly once the socket is closed; the io_context is
  // then stopped so that a pending timer cannot hold the thread.
  asio::post(session_->ioc, [s = session_.get()] { s->ioc.stop(); });
  if (thread_.joinable()) thread_.join();
  session_.reset();
}

std::string WsSource::describe() const { return "ws://" + url_.host + ":" + url_.port + url_.target; }

void WsSource::send_text(std::string text) {
  if (!session_ || url_.target.find("recording=") == std::string::npos) return;
  asio::post(session_->ioc, [s = session_.get(), t = std::move(text)]() mutable { s->send(std::move(t)); });
}

void WsSource::toggle_pause() { send_text(R"({"type":"replay","action":"toggle"})"); }

void WsSource::seek_by(double seconds) {
  const int time = std::max(0, last_time_.load() + static_cast<int>(seconds * 10.0));
  send_text(R"({"type":"replay","action":"seek","time":)" + std::to_string(time) + "}");
}

void WsSource::set_speed(double speed) {
  speed = std::clamp(speed, 0.25, 8.0);
  send_text(R"({"type":"replay","action":"speed","speed":)" + std::to_string(speed) + "}");
}

}  // namespace mc::viewer

#include "server/tools/loadgen/load_client.hpp"

#include <boost/beast/core/bind_handler.hpp>

#include "server/tools/loadgen/ws_frame_parser.hpp"

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;

namespace mc::loadgen {

double unix_ms_now() {
  using namespace std::chrono;
  return duration<double, std::milli>(system_clock::now().time_since_epoch()).count();
}

void ClientStats::merge(const ClientStats& o) {
  connected += o.connected;
  failed += o.failed;
  closed_by_server += o.closed_by_server;
  messages += o.messages;
  bytes += o.bytes;
  frames += o.frames;
  gaps += o.gaps;
  frames_skipped += o.frames_skipped;
  out_of_order += o.out_of_order;
  decode_errors += o.decode_errors;
  resync_gaps += o.resync_gaps;
  stalled_cut += o.stalled_cut;
  stalled_not_cut += o.stalled_not_cut;
  abandoned += o.abandoned;
  if (first_error.empty()) first_error = o.first_error;
  delay.merge(o.delay);
}

LoadClient::LoadClient(net::io_context& ioc, ClientOptions options, ClientStats& stats)
    : options_(std::move(options)), stats_(stats), stream_(ioc), pause_(ioc) {
  if (options_.decode && options_.skeleton)
    decoder_ = std::make_unique<proto::FrameDecoder>(*options_.skeleton);
}

void LoadClient::start() {
  auto& socket = stream_.socket();
  beast::error_code ec;
  socket.open(options_.server.protocol(), ec);
  if (!ec) socket.bind({options_.source, 0}, ec);
  // A stalled spectator with a small window fills up in seconds, not
  // minutes: the relay's stall handling is then what is measured.
  if (!ec && options_.behaviour == Behaviour::Stalled)
    socket.set_option(net::socket_base::receive_buffer_size(4096), ec);
  if (ec) {
    note_failure("bind", ec);
    return;
  }
  stream_.expires_after(std::chrono::seconds(30));
  stream_.async_connect(options_.server,
                        beast::bind_front_handler(&LoadClient::on_connect, shared_from_this()));
}

void LoadClient::stop() {
  if (!open_ && !ended_) ++stats_.abandoned;
  ended_ = true;
  beast::error_code ec;
  pause_.cancel();
  open_ = false;
  stream_.socket().close(ec);
}

void LoadClient::note_failure(const char* step, beast::error_code ec) {
  // A client stopped mid-connect or mid-upgrade (the end of a run) was
  // counted as abandoned by stop(); its cancelled operation is no failure.
  if (ended_) return;
  ended_ = true;
  ++stats_.failed;
  if (stats_.first_error.empty()) stats_.first_error = std::string(step) + ": " + ec.message();
}

void LoadClient::on_connect(beast::error_code ec) {
  if (ec) return note_failure("connect", ec);
  // The upgrade request (RFC 6455 section 4.1); any key will do for a test client.
  request_ = std::make_unique<http::request<http::empty_body>>(http::verb::get, options_.target, 11);
  request_->set(http::field::host, options_.host);
  request_->set(http::field::upgrade, "websocket");
  request_->set(http::field::connection, "Upgrade");
  request_->set(http::field::sec_websocket_key, "dGhlIHNhbXBsZSBub25jZQ==");
  request_->set(http::field::sec_websocket_version, "13");
  http::async_write(stream_, *request_,
                    beast::bind_front_handler(&LoadClient::on_request_sent, shared_from_this()));
}

void LoadClient::on_request_sent(beast::error_code ec, std::size_t) {
  request_.reset();
  if (ec) return note_failure("handshake", ec);
  response_ = std::make_unique<http::response<http::string_body>>();
  // Bytes after the response (the hello, the first frames) stay in buffer_.
  http::async_read(stream_, buffer_, *response_,
                   beast::bind_front_handler(&LoadClient::on_handshake, shared_from_this()));
}

void LoadClient::on_handshake(beast::error_code ec, std::size_t) {
  if (!ec && response_->result() != http::status::switching_protocols) ec = net::error::connection_refused;
  response_.reset();
  if (ec) return note_failure("handshake", ec);
  stream_.expires_never();
  ++stats_.connected;
  open_ = true;
  connected_at_ms_ = static_cast<std::uint64_t>(unix_ms_now());
  if (options_.behaviour == Behaviour::Stalled) {
    // Never reads (the socket fills up), or only after stall_for.
    if (options_.stall_for.count() > 0) {
      pause_.expires_after(options_.stall_for);
      pause_.async_wait([self = shared_from_this()](beast::error_code e) {
        if (e) return;
        self->draining_ = true;
        self->resumed_at_ms_ = unix_ms_now();
        if (self->take_frames()) self->do_read();
      });
    }
    return;
  }
  if (take_frames()) do_read();
}

void LoadClient::do_read() {
  // A slow client takes little at a time; the others all the socket holds.
  const std::size_t want = options_.behaviour == Behaviour::Slow ? 2048 : 16384;
  // Straight on the socket: tcp_stream's timeout bookkeeping on every read
  // costs the load generator CPU that the relay under test then lacks.
  stream_.socket().async_read_some(buffer_.prepare(want),
                          beast::bind_front_handler(&LoadClient::on_read, shared_from_this()));
}

void LoadClient::on_read(beast::error_code ec, std::size_t bytes) {
  if (ec) {
    if (open_ && ec != net::error::operation_aborted) {
      ++stats_.closed_by_server;
      if (draining_ && !stall_settled_) {
        ++stats_.stalled_cut;
        stall_settled_ = true;
      }
    }
    open_ = false;
    ended_ = true;
    return;
  }
  buffer_.commit(bytes);
  stats_.bytes += bytes;
  if (!take_frames()) return;
  if (options_.behaviour == Behaviour::Slow) {
    pause_.expires_after(options_.slow_read_pause);
    pause_.async_wait([self = shared_from_this()](beast::error_code e) {
      if (!e) self->do_read();
    });
    return;
  }
  do_read();
}

bool LoadClient::take_frames() {
  for (;;) {
    const auto data = buffer_.data();
    const std::string_view bytes(static_cast<const char*>(data.data()), data.size());
    WsFrame frame;
    const auto result = parse_frame(bytes, frame);
    if (result == ParseResult::NeedMore) return true;
    if (result == ParseResult::Bad || !frame.fin) {
      ++stats_.decode_errors;
      if (stats_.first_error.empty()) stats_.first_error = "malformed or fragmented WebSocket frame";
      stop();
      return false;
    }
    if (frame.opcode == 0x8) {  // close
      ++stats_.closed_by_server;
      if (draining_ && !stall_settled_) {
        ++stats_.stalled_cut;
        stall_settled_ = true;
      }
      stop();
      return false;
    }
    if (frame.opcode == 0x1 || frame.opcode == 0x2) ++stats_.messages;
    if (frame.opcode == 0x1 && frame.payload.find("\"type\":\"feed\"") != std::string_view::npos)
      last_feed_message_ms_ = unix_ms_now();
    if (frame.opcode == 0x2) handle_frame(frame.payload);
    buffer_.consume(frame.size);
  }
}

void LoadClient::handle_frame(std::string_view bytes) {
  const double now = unix_ms_now();
  ++stats_.frames;
  proto::FrameHeader header;
  std::string error;
  if (!proto::peek_header(bytes, header, error)) {
    if (stats_.first_error.empty()) stats_.first_error = error;
    ++stats_.decode_errors;
    return;
  }
  if (have_seq_) {
    if (header.seq == last_seq_ + 1) {
      // the normal case
    } else if (header.seq > last_seq_ + 1) {
      ++stats_.gaps;
      stats_.frames_skipped += header.seq - last_seq_ - 1;
      if (header.keyframe && now - last_feed_message_ms_ < 10000) ++stats_.resync_gaps;
    } else {
      ++stats_.out_of_order;
    }
  }
  last_seq_ = header.seq;
  have_seq_ = true;
  // A stalled client reading again gets a frame sent after it resumed: the
  // relay had not cut it off.
  if (draining_ && !stall_settled_ && static_cast<double>(header.server_time_ms) > resumed_at_ms_) {
    ++stats_.stalled_not_cut;
    stall_settled_ = true;
    stop();
  }
  // The catch-up burst at join was stamped before this client existed: its
  // age says nothing about the relay's delay.
  if (header.server_time_ms >= connected_at_ms_)
    stats_.delay.record(now - static_cast<double>(header.server_time_ms));
  if (decoder_ && !decoder_->decode(bytes, frame_, error)) {
    if (stats_.first_error.empty()) stats_.first_error = error;
    ++stats_.decode_errors;
  }
}

}  // namespace mc::loadgen

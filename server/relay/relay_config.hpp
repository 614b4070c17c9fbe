// Everything the relay can be told, as one struct of named limits (after
// uWebSockets' settings struct). Defaults say why they are what they are.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mc::relay {

struct RelayConfig {
  // Loopback by default: exposing a server to a network is a decision.
  std::string address = "127.0.0.1";
  // 0 lets the OS pick a free port (tests); the demo uses 8080.
  std::uint16_t port = 8080;
  // Static files are served from here and never from outside it.
  std::string web_root;
  // Threads running the I/O loop; 0 = one per core.
  unsigned threads = 0;

  // Per-client outbound queue bound. A pose frame is ~0.3-1.5 KB and a
  // keyframe interval is 20 frames, so 256 KiB holds several seconds: a client
  // over it is behind by more than a hiccup, and skips to the next keyframe.
  std::size_t max_queue_bytes = 256 * 1024;
  // A client whose write has not completed for this long is stalled, not
  // slow: it is closed (close code 1008, reason "too slow").
  std::chrono::milliseconds stall_timeout{5000};

  // Kernel send buffer of each connection (SO_SNDBUF; 0 = the OS's
  // autotuning, up to 4 MB per socket on Linux). Bounds the kernel memory a
  // stalled spectator holds and makes its stall visible to stall_timeout;
  // 64 KiB is still 10 s of a 20 Hz stream.
  std::size_t socket_send_buffer = 64 * 1024;

  // Inbound limits: spectators send almost nothing (small JSON controls).
  std::size_t max_inbound_message = 4096;
  std::size_t max_http_body = 8192;
  std::size_t max_clients = 20000;
  // Connections one client address may hold (0 = no limit). A household
  // behind one NAT has a few spectators, not hundreds.
  std::size_t max_connections_per_ip = 64;
  // The headers (and small body) of a request, and a TLS handshake, must
  // arrive whole within this time, or the connection is closed: a client
  // that sends a byte a second (slowloris) or nothing at all (a half-open
  // connection) holds its slot for at most this long. Counted per
  // connection, and every connection, HTTP or WebSocket, counts against
  // max_connections_per_ip from the moment it is accepted.
  std::chrono::milliseconds header_timeout{10000};

  // If not empty, a WebSocket upgrade must carry one of these Origin
  // headers ("https://example.org"); others get 403. Empty = any origin.
  std::vector<std::string> allowed_origins;
  // Bearer token for the control endpoints (/control/...). Empty = control
  // disabled: spectators are read-only either way.
  std::string control_token;

  // TLS: both set = the port speaks HTTPS and WSS only (PEM files; the
  // certificate file may hold the chain). Both empty = plain HTTP and WS.
  std::string tls_cert_file;
  std::string tls_key_file;
};

}  // namespace mc::relay

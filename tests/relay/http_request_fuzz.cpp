// libFuzzer target: what reaches the relay's router from the network. The
// bytes are parsed as the HTTP session parses a request (Beast's parser with
// the session's header and body limits), then routed as the session routes
// it: the path, the upgrade test, the query parameters (channel,
// recording), the recording name check and the static file lookup under a
// web root. Must never crash, hang or read out of bounds (ASan/UBSan), and
// a file it resolves must be inside the web root.
#include <boost/beast/http.hpp>
#include <boost/beast/websocket/rfc6455.hpp>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "server/relay/http_session.hpp"
#include "server/relay/static_files.hpp"
#include "server/replay/replay_catalog.hpp"

namespace http = boost::beast::http;
namespace fs = std::filesystem;

namespace {

// A web root with a page, a script in a folder, and a secret beside it.
struct Fixture {
  fs::path dir = fs::temp_directory_path() / ("mc-http-fuzz-" + std::to_string(::getpid()));
  std::unique_ptr<mc::relay::StaticFiles> files;
  Fixture() {
    fs::create_directories(dir / "web" / "src");
    std::ofstream(dir / "web" / "index.html") << "<!doctype html>";
    std::ofstream(dir / "web" / "src" / "main.js") << "//";
    std::ofstream(dir / "secret") << "s";
    files = std::make_unique<mc::relay::StaticFiles>((dir / "web").string());
  }
  ~Fixture() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Fixture fx;
  http::request_parser<http::string_body> parser;
  parser.header_limit(8 * 1024);  // as HttpSession::do_read
  parser.body_limit(8192);
  parser.eager(true);
  boost::beast::error_code ec;
  std::size_t used = 0;
  while (used < size && !parser.is_done()) {
    const std::size_t n = parser.put(boost::asio::buffer(data + used, size - used), ec);
    if (ec == http::error::need_more) break;
    if (ec || n == 0) break;
    used += n;
  }
  if (!parser.is_header_done()) return 0;
  const auto& req = parser.get();
  const std::string_view target(req.target().data(), req.target().size());
  const std::string_view path = target.substr(0, target.find('?'));
  (void)boost::beast::websocket::is_upgrade(req);
  (void)mc::relay::query_param(target, "channel");
  const std::string recording = mc::relay::query_param(target, "recording");
  (void)mc::replay::valid_recording_name(recording);
  (void)mc::relay::url_decode(path);
  if (auto file = fx.files->resolve(target)) {
    const std::string& root = fx.files->root();
    if (file->compare(0, root.size(), root) != 0 || (file->size() > root.size() && (*file)[root.size()] != '/'))
      std::abort();  // a file outside the web root
    (void)mc::relay::mime_type(*file);
  }
  (void)req[http::field::origin];
  (void)req[http::field::authorization];
  return 0;
}

#include "server/relay/static_files.hpp"

#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace mc::relay {

StaticFiles::StaticFiles(const std::string& root) {
  std::error_code ec;
  auto canon = fs::canonical(root, ec);
  root_ = ec ? root : canon.string();
}

std::vector<std::string> StaticFiles::missing_page_files() const {
  static constexpr const char* kNeeded[] = {"index.html", "node_modules/three/build/three.module.js"};
  std::vector<std::string> missing;
  for (const char* rel : kNeeded) {
    std::error_code ec;
    if (!fs::is_regular_file(fs::path(root_) / rel, ec)) missing.emplace_back(rel);
  }
  return missing;
}

std::optional<std::string> url_decode(std::string_view in) {
  auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  std::string out;
  out.reserve(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    char c = in[i];
    if (c == '%') {
      if (i + 2 >= in.size()) return std::nullopt;
      int hi = hex(in[i + 1]), lo = hex(in[i + 2]);
      if (hi < 0 || lo < 0) return std::nullopt;
      c = static_cast<char>(hi * 16 + lo);
      i += 2;
    }
    if (c == '\0') return std::nullopt;
    out.push_back(c);
  }
  return out;
}

std::optional<std::string> StaticFiles::resolve(std::string_view target) const {
  if (target.empty() || target.front() != '/') return std::nullopt;
  target = target.substr(0, target.find_first_of("?#"));
  auto decoded = url_decode(target);
  if (!decoded) return std::nullopt;
  std::string rel = *decoded;
  if (rel.back() == '/') rel += "index.html";
  // Refuse any ".." segment and backslashes outright, before touching the
  // filesystem: a request never has a good reason for them.
  if (rel.find('\\') != std::string::npos) return std::nullopt;
  for (std::size_t pos = 0; pos < rel.size();) {
    std::size_t end = rel.find('/', pos);
    if (end == std::string::npos) end = rel.size();
    if (rel.compare(pos, end - pos, "..") == 0) return std::nullopt;
    pos = end + 1;
  }
  // Then check the real location: a symlink inside web/ must not lead out.
  std::error_code ec;
  fs::path full = fs::canonical(fs::path(root_) / fs::path(rel).relative_path(), ec);
  if (ec) return std::nullopt;
  const std::string s = full.string();
  if (s.compare(0, root_.size(), root_) != 0 || (s.size() > root_.size() && s[root_.size()] != '/'))
    return std::nullopt;
  if (!fs::is_regular_file(full, ec)) return std::nullopt;
  return s;
}

std::string_view mime_type(std::string_view path) {
  auto ext = path.substr(path.rfind('.') == std::string_view::npos ? path.size() : path.rfind('.'));
  if (ext == ".html" || ext == ".htm") return "text/html; charset=utf-8";
  if (ext == ".js" || ext == ".mjs") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".json" || ext == ".map") return "application/json";
  if (ext == ".png") return "image/png";
  if (ext == ".jpg" || ext == ".jpeg") return "image/jpeg";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".ico") return "image/x-icon";
  if (ext == ".wasm") return "application/wasm";
  if (ext == ".txt" || ext == ".md") return "text/plain; charset=utf-8";
  return "application/octet-stream";
}

}  // namespace mc::relay

// Maps an HTTP request target to a file under the web root, safely: no
// target can name a file outside the root (no "..", no encoded tricks, no
// symlink escape). Pure path logic plus one filesystem check; no sockets.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mc::relay {

class StaticFiles {
 public:
  // `root` must exist; it is canonicalised once.
  explicit StaticFiles(const std::string& root);

  // The file to serve for `target` ("/", "/src/main.js?x=1"), or nullopt when
  // the target is malformed, escapes the root, or names no regular file.
  std::optional<std::string> resolve(std::string_view target) const;

  const std::string& root() const { return root_; }

  // Files the page cannot start without that are not under the root (the
  // page itself, three.js from npm), as paths relative to it. A server run
  // before `npm ci` in web/ would otherwise serve a blank page and say nothing.
  std::vector<std::string> missing_page_files() const;

 private:
  std::string root_;
};

// Content type for a file name, by extension ("application/octet-stream" if unknown).
std::string_view mime_type(std::string_view path);

// Percent-decodes a URL path; nullopt on a malformed escape or a NUL byte.
std::optional<std::string> url_decode(std::string_view in);

}  // namespace mc::relay

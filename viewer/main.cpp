// matchcast-viewer: the broadcast in a native OpenGL window, from a live
// relay or a recording file; --screenshot renders one frame offscreen.
// viewer/README.md describes the options and the keys.
#include <cstdio>

#include "viewer/app.hpp"
#include "viewer/options.hpp"

int main(int argc, char** argv) {
  std::string message;
  int code = 0;
  auto options = mc::viewer::parse_options(argc, argv, message, code);
  if (!options) {
    std::fprintf(code ? stderr : stdout, "%s\n", message.c_str());
    return code;
  }
  mc::viewer::App app(std::move(*options));
  return app.run();
}

// OpenGL 3.3 core entry points and the few helpers the renderer and the HUD
// share: shader programs, vertex buffers, an offscreen framebuffer. Mesa's
// libGL exports every core function, so no loader library is needed.
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstddef>
#include <string>
#include <vector>

namespace mc::viewer::gl {

// Compiles and links; 0 + error (the driver's log) on failure.
GLuint make_program(const char* vertex_src, const char* fragment_src, std::string& error);

// A vertex array with one interleaved buffer of floats. `layout` gives the
// size (in floats) of each attribute, in location order.
class Mesh {
 public:
  Mesh() = default;
  Mesh(const Mesh&) = delete;
  Mesh& operator=(const Mesh&) = delete;
  ~Mesh() { destroy(); }
  void upload(const float* data, std::size_t floats, const std::vector<int>& layout, GLenum usage = GL_STATIC_DRAW);
  void draw(GLenum mode = GL_TRIANGLES) const;
  void destroy();
  GLsizei count() const { return count_; }

 private:
  GLuint vao_ = 0, vbo_ = 0;
  GLsizei count_ = 0;
};

// A colour + depth render target for --screenshot.
class Framebuffer {
 public:
  ~Framebuffer() { destroy(); }
  bool create(int width, int height, std::string& error);
  void bind() const { glBindFramebuffer(GL_FRAMEBUFFER, fbo_); }
  // RGB rows, top to bottom.
  std::vector<unsigned char> read_rgb() const;
  void destroy();

 private:
  GLuint fbo_ = 0, color_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace mc::viewer::gl

#include "viewer/gl_util.hpp"

#include <cstring>

namespace mc::viewer::gl {
namespace {

GLuint compile(GLenum kind, const char* src, std::string& error) {
  const GLuint s = glCreateShader(kind);
  glShaderSource(s, 1, &src, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    error = std::string(kind == GL_VERTEX_SHADER ? "vertex" : "fragment") + " shader: " + log;
    glDeleteShader(s);
    return 0;
  }
  return s;
}

}  // namespace

GLuint make_program(const char* vertex_src, const char* fragment_src, std::string& error) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex_src, error);
  if (!vs) return 0;
  const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment_src, error);
  if (!fs) {
    glDeleteShader(vs);
    return 0;
  }
  const GLuint p = glCreateProgram();
  glAttachShader(p, vs);
  glAttachShader(p, fs);
  glLinkProgram(p);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(p, sizeof log, nullptr, log);
    error = std::string("shader link: ") + log;
    glDeleteProgram(p);
    return 0;
  }
  return p;
}

void Mesh::upload(const float* data, std::size_t floats, const std::vector<int>& layout, GLenum usage) {
  if (!vao_) {
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vbo_);
  }
  int stride = 0;
  for (int n : layout) stride += n;
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(floats * sizeof(float)), data, usage);
  std::size_t offset = 0;
  for (std::size_t i = 0; i < layout.size(); ++i) {
    glEnableVertexAttribArray(static_cast<GLuint>(i));
    glVertexAttribPointer(static_cast<GLuint>(i), layout[i], GL_FLOAT, GL_FALSE,
                          static_cast<GLsizei>(stride * sizeof(float)),
                          reinterpret_cast<const void*>(offset * sizeof(float)));
    offset += static_cast<std::size_t>(layout[i]);
  }
  glBindVertexArray(0);
  count_ = stride ? static_cast<GLsizei>(floats / static_cast<std::size_t>(stride)) : 0;
}

void Mesh::draw(GLenum mode) const {
  if (!vao_ || count_ == 0) return;
  glBindVertexArray(vao_);
  glDrawArrays(mode, 0, count_);
}

void Mesh::destroy() {
  if (vbo_) glDeleteBuffers(1, &vbo_);
  if (vao_) glDeleteVertexArrays(1, &vao_);
  vao_ = vbo_ = 0;
  count_ = 0;
}

bool Framebuffer::create(int width, int height, std::string& error) {
  destroy();
  width_ = width;
  height_ = height;
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glGenRenderbuffers(1, &color_);
  glBindRenderbuffer(GL_RENDERBUFFER, color_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    error = "the offscreen framebuffer is not complete";
    return false;
  }
  return true;
}

std::vector<unsigned char> Framebuffer::read_rgb() const {
  std::vector<unsigned char> rgba(static_cast<std::size_t>(width_) * height_ * 4), rgb;
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  rgb.resize(static_cast<std::size_t>(width_) * height_ * 3);
  // GL rows are bottom to top.
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x)
      std::memcpy(&rgb[(static_cast<std::size_t>(y) * width_ + x) * 3],
                  &rgba[(static_cast<std::size_t>(height_ - 1 - y) * width_ + x) * 4], 3);
  return rgb;
}

void Framebuffer::destroy() {
  if (depth_) glDeleteRenderbuffers(1, &depth_);
  if (color_) glDeleteRenderbuffers(1, &color_);
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  fbo_ = color_ = depth_ = 0;
}

}  // namespace mc::viewer::gl

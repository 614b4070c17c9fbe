#include "viewer/body_renderer.hpp"

#include <algorithm>
#include <string>

#include "viewer/font.hpp"

namespace mc::viewer {
namespace {

// Quads for the set pixels of `text` in a plane facing `normal`, centred on
// `center`, `height` tall, columns along `right` (as renderer.cpp's).
void glyph_quads(std::vector<float>& out, const std::string& text, glm::vec3 center, float height, glm::vec3 normal,
                 glm::vec3 right) {
  const float px = height / kGlyphH;
  const float width = static_cast<float>(text_columns(text)) * px;
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const glm::vec3 origin = center - right * (width / 2) + up * (height / 2);
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto& g = glyph(text[i]);
    for (int r = 0; r < kGlyphH; ++r)
      for (int c = 0; c < kGlyphW; ++c) {
        if (!(g[static_cast<std::size_t>(r)] & (1u << (kGlyphW - 1 - c)))) continue;
        const float x0 = static_cast<float>(static_cast<int>(i) * kGlyphAdvance + c) * px;
        const glm::vec3 a = origin + right * x0 - up * (static_cast<float>(r) * px), b = a + right * px,
                        d = a - up * px, e = b - up * px;
        for (const auto& p : {a, b, e, a, e, d})
          out.insert(out.end(), {p.x, p.y, p.z, normal.x, normal.y, normal.z, 1.0f, 1.0f, 1.0f});
      }
  }
}

}  // namespace

BodyRenderer::~BodyRenderer() { release(); }

void BodyRenderer::release() {
  for (Level& l : levels_) {
    if (l.vao) glDeleteVertexArrays(1, &l.vao);
    if (l.vbo) glDeleteBuffers(1, &l.vbo);
    if (l.ebo) glDeleteBuffers(1, &l.ebo);
    l.vao = l.vbo = l.ebo = 0;
  }
  number_meshes_.clear();
  ready_ = false;
}

bool BodyRenderer::set_skeleton(const SkeletonDef& skeleton) {
  release();
  for (int lod = 0; lod < 2; ++lod) {
    std::string error;
    auto mesh = build_body(body_spec_json(), skeleton, lod, error);
    if (!mesh) return false;
    Level& l = levels_[static_cast<std::size_t>(lod)];
    l.mesh = std::move(*mesh);
    l.normals = rest_normals(l.mesh);
    glGenVertexArrays(1, &l.vao);
    glGenBuffers(1, &l.vbo);
    glGenBuffers(1, &l.ebo);
    glBindVertexArray(l.vao);
    glBindBuffer(GL_ARRAY_BUFFER, l.vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(l.mesh.positions.size() * 9 * sizeof(float)), nullptr,
                 GL_STREAM_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, l.ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(l.mesh.index.size() * sizeof(std::uint32_t)),
                 l.mesh.index.data(), GL_STATIC_DRAW);
    for (GLuint a = 0; a < 3; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribPointer(a, 3, GL_FLOAT, GL_FALSE, 9 * sizeof(float),
                            reinterpret_cast<const void*>(static_cast<std::uintptr_t>(a * 3 * sizeof(float))));
    }
    glBindVertexArray(0);
  }
  rest_ = rest_positions(skeleton);
  numbers_ = body_numbers(body_spec_json(), skeleton);
  for (int side = 0; side < 2; ++side)
    for (int unum = 0; unum < 12; ++unum)
      tones_[static_cast<std::size_t>(side * 12 + unum)] =
          body_tones(body_spec_json(), side == 0 ? Side::Left : Side::Right, unum);
  ready_ = true;
  return true;
}

glm::vec3 BodyRenderer::shorts_ink(const Kit& kit) {
  const float l = 0.2126f * kit.shorts.r + 0.7152f * kit.shorts.g + 0.0722f * kit.shorts.b;
  return l > 0.45f ? glm::vec3(0.07f) : glm::vec3(1.0f);
}

const gl::Mesh& BodyRenderer::number_mesh(int unum, std::size_t decal) {
  auto& mesh = number_meshes_[{unum, decal}];
  if (!mesh) {
    const BodyNumber& n = numbers_[decal];
    std::vector<float> v;
    // Seen from behind, the body's right (+Z) is on the right; from the front, on the left.
    const glm::vec3 normal(static_cast<float>(n.face), 0.0f, 0.0f);
    const glm::vec3 right(0.0f, 0.0f, n.face < 0 ? 1.0f : -1.0f);
    glyph_quads(v, std::to_string(unum), n.at + normal * 0.004f, n.size * 0.62f, normal, right);
    mesh = std::make_unique<gl::Mesh>();
    mesh->upload(v.data(), v.size(), {3, 3, 3});
  }
  return *mesh;
}

void BodyRenderer::draw_body(const PlayerPose& pose, const std::vector<glm::mat4>& joints, const Kit& kit, bool far) {
  if (!ready_) return;
  Level& l = levels_[far ? 1 : 0];
  skin_body(l.mesh, rest_, joints, l.normals, pos_, normal_);
  const auto& tones = tones_[static_cast<std::size_t>((pose.side == Side::Right ? 12 : 0) + std::min<int>(pose.unum, 11))];
  std::array<glm::vec3, 8> table{};
  for (std::size_t r = 0; r < l.mesh.regions.size() && r < table.size(); ++r) {
    const std::string& name = l.mesh.regions[r];
    table[r] = name == "shirt"    ? kit.shirt
               : name == "shorts" ? kit.shorts
               : name == "sock"   ? kit.sock
               : name == "boot"   ? kit.boot
               : name == "skin"   ? tones[0]
               : name == "hair"   ? tones[1]
                                  : kit.shirt;
  }
  interleaved_.resize(pos_.size() * 9);
  for (std::size_t i = 0; i < pos_.size(); ++i) {
    const glm::vec3& c = table[std::min<std::size_t>(l.mesh.region[i], table.size() - 1)];
    float* o = &interleaved_[i * 9];
    o[0] = pos_[i].x; o[1] = pos_[i].y; o[2] = pos_[i].z;
    o[3] = normal_[i].x; o[4] = normal_[i].y; o[5] = normal_[i].z;
    o[6] = c.r; o[7] = c.g; o[8] = c.b;
  }
  glBindVertexArray(l.vao);
  glBindBuffer(GL_ARRAY_BUFFER, l.vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(interleaved_.size() * sizeof(float)), nullptr, GL_STREAM_DRAW);
  glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(interleaved_.size() * sizeof(float)), interleaved_.data());
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(l.mesh.index.size()), GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

}  // namespace mc::viewer

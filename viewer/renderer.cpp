#include "viewer/renderer.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "viewer/font.hpp"

namespace mc::viewer {
namespace {

const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
uniform mat4 u_mvp;
uniform mat4 u_model;
out vec3 v_normal;
out vec3 v_color;
void main() {
  gl_Position = u_mvp * vec4(a_pos, 1.0);
  v_normal = transpose(inverse(mat3(u_model))) * a_normal;
  v_color = a_color;
}
)";

// Sky light plus one sun, so that shaded sides are never black.
const char* kFragment = R"(#version 330 core
in vec3 v_normal;
in vec3 v_color;
uniform vec3 u_tint;
uniform float u_use_tint;
uniform float u_alpha;
uniform float u_lit;
out vec4 o_color;
void main() {
  vec3 base = mix(v_color, u_tint, u_use_tint);
  vec3 n = normalize(v_normal);
  float sun = max(dot(n, normalize(vec3(0.35, 0.85, 0.40))), 0.0);
  float light = mix(1.0, 0.55 + 0.45 * sun, u_lit);
  o_color = vec4(base * light, u_alpha);
}
)";

void push(std::vector<float>& out, glm::vec3 p, glm::vec3 n, glm::vec3 c) {
  out.insert(out.end(), {p.x, p.y, p.z, n.x, n.y, n.z, c.x, c.y, c.z});
}

std::vector<float> cube_vertices() {
  std::vector<float> v;
  const glm::vec3 white(1.0f);
  for (int axis = 0; axis < 3; ++axis) {
    for (const float s : {-1.0f, 1.0f}) {
      glm::vec3 n(0.0f);
      n[axis] = s;
      const glm::vec3 u = axis == 0 ? glm::vec3(0, 1, 0) : (axis == 1 ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0));
      const glm::vec3 w = glm::cross(n, u);
      const glm::vec3 c = n * 0.5f;
      const glm::vec3 a = c - u * 0.5f - w * 0.5f, b = c + u * 0.5f - w * 0.5f, d = c + u * 0.5f + w * 0.5f,
                      e = c - u * 0.5f + w * 0.5f;
      for (const auto& p : {a, b, d, a, d, e}) push(v, p, n, white);
    }
  }
  return v;
}

std::vector<float> sphere_vertices(int rings, int sectors) {
  std::vector<float> v;
  const float pi = 3.14159265358979f;
  const auto at = [&](int r, int s) {
    const float th = pi * r / rings, ph = 2 * pi * s / sectors;
    return glm::vec3(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
  };
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < sectors; ++s) {
      const glm::vec3 a = at(r, s), b = at(r + 1, s), c = at(r + 1, s + 1), d = at(r, s + 1);
      for (const auto& p : {a, b, c, a, c, d}) push(v, p, p, glm::vec3(1.0f));
    }
  return v;
}

std::vector<float> disc_vertices(int n) {
  std::vector<float> v;
  const float pi = 3.14159265358979f;
  const glm::vec3 up(0, 1, 0), c(1.0f);
  for (int i = 0; i < n; ++i) {
    const float a0 = 2 * pi * i / n, a1 = 2 * pi * (i + 1) / n;
    push(v, glm::vec3(0.0f), up, c);
    push(v, {std::cos(a1), 0, std::sin(a1)}, up, c);
    push(v, {std::cos(a0), 0, std::sin(a0)}, up, c);
  }
  return v;
}

std::vector<float> flatten(const std::vector<Vertex>& in) {
  std::vector<float> v;
  v.reserve(in.size() * 9);
  for (const auto& x : in) push(v, x.pos, x.normal, x.color);
  return v;
}

const std::vector<int> kLayout = {3, 3, 3};

// Quads for the set pixels of `text`, in a plane facing `normal` (+X or
// -X in the chest's local space), centred on `center`, `height` tall.
// Columns run along `right` (what a viewer facing that side sees as right).
void number_quads(std::vector<float>& out, const std::string& text, glm::vec3 center, float height,
                  glm::vec3 normal, glm::vec3 right) {
  const float px = height / kGlyphH;
  const float width = static_cast<float>(text_columns(text)) * px;
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const glm::vec3 origin = center - right * (width / 2) + up * (height / 2);
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto& g = glyph(text[i]);
    for (int r = 0; r < kGlyphH; ++r)
      for (int c = 0; c < kGlyphW; ++c) {
        if (!(g[r] & (1u << (kGlyphW - 1 - c)))) continue;
        const float x0 = static_cast<float>(i * kGlyphAdvance + c) * px;
        const glm::vec3 a = origin + right * x0 - up * (r * px), b = a + right * px, d = a - up * px, e = b - up * px;
        for (const auto& p : {a, b, e, a, e, d}) push(out, p, normal, glm::vec3(1.0f));
      }
  }
}

}  // namespace

Renderer::~Renderer() {
  if (program_) glDeleteProgram(program_);
}

bool Renderer::init(std::string& error) {
  program_ = gl::make_program(kVertex, kFragment, error);
  if (!program_) return false;
  u_mvp_ = glGetUniformLocation(program_, "u_mvp");
  u_model_ = glGetUniformLocation(program_, "u_model");
  u_tint_ = glGetUniformLocation(program_, "u_tint");
  u_use_tint_ = glGetUniformLocation(program_, "u_use_tint");
  u_alpha_ = glGetUniformLocation(program_, "u_alpha");
  u_lit_ = glGetUniformLocation(program_, "u_lit");
  auto v = cube_vertices();
  cube_.upload(v.data(), v.size(), kLayout);
  v = sphere_vertices(10, 16);
  sphere_.upload(v.data(), v.size(), kLayout);
  v = disc_vertices(20);
  disc_.upload(v.data(), v.size(), kLayout);
  set_field(proto::FieldGeometry{});
  return true;
}

void Renderer::set_field(const proto::FieldGeometry& field) {
  const PitchGeometry pitch = build_pitch(field);
  auto v = flatten(pitch.ground);
  ground_.upload(v.data(), v.size(), kLayout);
  v = flatten(pitch.markings);
  markings_.upload(v.data(), v.size(), kLayout);
  v = flatten(pitch.center_lines);
  center_lines_.upload(v.data(), v.size(), kLayout);
  goals_ = pitch.goals;
}

const gl::Mesh& Renderer::number_mesh(int number, const Segment& chest) {
  const std::array<float, 6> shape{chest.size[0], chest.size[1], chest.size[2],
                                   chest.center[0], chest.center[1], chest.center[2]};
  if (shape != numbers_chest_) {
    numbers_.clear();
    numbers_chest_ = shape;
  }
  auto& mesh = numbers_[number];
  if (!mesh) {
    const glm::vec3 size(chest.size[0], chest.size[1], chest.size[2]);
    const glm::vec3 c(chest.center[0], chest.center[1], chest.center[2]);
    const float h = std::min(size.y, size.z) * 0.55f;
    std::vector<float> v;
    const std::string text = std::to_string(number);
    // Back (-X): seen from behind, the body's right (+Z) is on the right.
    number_quads(v, text, c - glm::vec3(size.x / 2 + 0.004f, 0.0f, 0.0f), h, {-1, 0, 0}, {0, 0, 1});
    // Front (+X), half size and a little higher, as the page.
    number_quads(v, text, c + glm::vec3(size.x / 2 + 0.004f, h * 0.2f, 0.0f), h * 0.5f, {1, 0, 0}, {0, 0, -1});
    mesh = std::make_unique<gl::Mesh>();
    mesh->upload(v.data(), v.size(), kLayout);
  }
  return *mesh;
}

void Renderer::clear(int width, int height) {
  glBindVertexArray(0);
  glViewport(0, 0, width, height);
  glClearColor(kSkyColor.r, kSkyColor.g, kSkyColor.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void Renderer::draw_mesh(const gl::Mesh& mesh, const glm::mat4& model, const glm::vec3& color, float alpha,
                         bool lit) {
  const glm::mat4 mvp = view_proj_ * model;
  glUniformMatrix4fv(u_mvp_, 1, GL_FALSE, glm::value_ptr(mvp));
  glUniformMatrix4fv(u_model_, 1, GL_FALSE, glm::value_ptr(model));
  glUniform3fv(u_tint_, 1, glm::value_ptr(color));
  glUniform1f(u_use_tint_, 1.0f);
  glUniform1f(u_alpha_, alpha);
  glUniform1f(u_lit_, lit ? 1.0f : 0.0f);
  mesh.draw();
}

void Renderer::draw(const PoseFrame& frame, const proto::Hello& hello, const PlayerModel& model,
                    const Camera& camera, int width, int height, int hidden_slot, int selected_slot) {
  clear(width, height);
  view_proj_ = camera.projection(static_cast<float>(width) / static_cast<float>(std::max(height, 1))) *
               camera.view();
  glUseProgram(program_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  const glm::mat4 identity(1.0f);

  // Ground with its vertex colours, then the markings and shadows on top of
  // it without depth (they lie on the grass; everything later covers them).
  glUniform1f(u_use_tint_, 0.0f);
  glUniformMatrix4fv(u_mvp_, 1, GL_FALSE, glm::value_ptr(view_proj_));
  glUniformMatrix4fv(u_model_, 1, GL_FALSE, glm::value_ptr(identity));
  glUniform1f(u_alpha_, 1.0f);
  glUniform1f(u_lit_, 1.0f);
  ground_.draw();
  glDisable(GL_DEPTH_TEST);
  markings_.draw();
  center_lines_.draw(GL_LINES);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int i = 0; i < kMaxPlayers; ++i) {
    const PlayerPose& p = frame.players[i];
    if (!player_visible(p) || i == hidden_slot) continue;
    const glm::mat4 m = glm::scale(glm::translate(identity, {p.x, 0.01f, p.y}), glm::vec3(0.45f));
    draw_mesh(disc_, m, glm::vec3(0.0f), 0.28f, false);
    if (i == selected_slot) {
      // The chosen player's ring, like the page's.
      const glm::mat4 r = glm::scale(glm::translate(identity, {p.x, 0.012f, p.y}), glm::vec3(0.75f));
      draw_mesh(disc_, r, glm::vec3(1.0f), 0.55f, false);
    }
  }
  const float bh = std::max(frame.ball.z, 0.0f);
  const float shadow = std::clamp(1.0f - bh / 10.0f, 0.3f, 1.0f);
  draw_mesh(disc_, glm::scale(glm::translate(identity, {frame.ball.x, 0.01f, frame.ball.y}), glm::vec3(kBallRadius * shadow)),
            glm::vec3(0.0f), 0.35f * shadow, false);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);

  for (const auto& g : goals_) draw_mesh(cube_, g.model, g.color);

  const std::string skeleton_key = model.skeleton().name + "/" + std::to_string(model.skeleton().joints.size());
  if (skeleton_key != body_skeleton_) {
    body_skeleton_ = skeleton_key;
    bodies_.set_skeleton(model.skeleton());
  }
  for (int i = 0; i < kMaxPlayers; ++i) {
    const PlayerPose& p = frame.players[i];
    if (!player_visible(p) || i == hidden_slot) continue;
    if (!model.joints(p, joints_)) continue;
    const Kit kit = team_kit(p.side == Side::Right ? hello.right : hello.left, p.side,
                             (p.state & state_bits::kGoalie) != 0);
    if (bodies_.ready()) {
      // The skinned body, in scene space; its numbers when near.
      const bool far = glm::length(camera.eye() - to_scene(p.x, p.y, p.z)) > kBodyFarMetres;
      glUniformMatrix4fv(u_mvp_, 1, GL_FALSE, glm::value_ptr(view_proj_));
      glUniformMatrix4fv(u_model_, 1, GL_FALSE, glm::value_ptr(identity));
      glUniform1f(u_use_tint_, 0.0f);
      glUniform1f(u_alpha_, 1.0f);
      glUniform1f(u_lit_, 1.0f);
      bodies_.draw_body(p, joints_, kit, far);
      if (!far && p.unum > 0 && p.unum < 100)
        bodies_.draw_numbers(p, joints_, kit,
                             [&](const gl::Mesh& m, const glm::mat4& at, glm::vec3 ink) { draw_mesh(m, at, ink); });
      continue;
    }
    model.segments(joints_, segments_);
    for (const auto& s : segments_) draw_mesh(s.sphere ? sphere_ : cube_, s.model, kit.color(s.part));
    const int chest = model.chest_joint();
    if (chest >= 0 && p.unum > 0 && p.unum < 100)
      draw_mesh(number_mesh(p.unum, model.skeleton().joints[static_cast<std::size_t>(chest)].segment),
                joints_[static_cast<std::size_t>(chest)], kit.number);
  }

  const glm::vec3 ball(frame.ball.x, std::max(frame.ball.z, kBallRadius), frame.ball.y);
  draw_mesh(sphere_, glm::scale(glm::translate(identity, ball), glm::vec3(kBallRadius)), glm::vec3(0.97f));
  glBindVertexArray(0);
}

}  // namespace mc::viewer

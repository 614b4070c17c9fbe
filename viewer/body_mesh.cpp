#include "viewer/body_mesh.hpp"

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "viewer/player_model.hpp"

namespace mc::viewer {

extern const char* const kBodySpecJson;  // body_spec.cpp, made by CMake from web/assets/body.json

std::string_view body_spec_json() { return kBodySpecJson; }

namespace {

using nlohmann::json;
using glm::dvec3;
constexpr double kPi = 3.14159265358979323846;

dvec3 cross(dvec3 a, dvec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double dot(dvec3 a, dvec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The page's generator (web/src/model/body_geometry.js), statement for statement.
class Builder {
 public:
  BodyMesh mesh;

  std::uint32_t vertex(dvec3 p, int joint, int blend, double blend_weight, int region) {
    mesh.positions.push_back(p);
    mesh.bones.push_back({joint, blend < 0 ? 0 : blend});
    mesh.weights.push_back({blend < 0 ? 1.0 : 1.0 - blend_weight, blend < 0 ? 0.0 : blend_weight});
    mesh.region.push_back(static_cast<std::uint8_t>(region));
    return static_cast<std::uint32_t>(mesh.positions.size() - 1);
  }
  void tri(std::uint32_t a, std::uint32_t b, std::uint32_t c, dvec3 inside) {
    const dvec3& pa = mesh.positions[a];
    const dvec3 n = cross(mesh.positions[b] - pa, mesh.positions[c] - pa);
    if (dot(n, pa - inside) < 0) mesh.index.insert(mesh.index.end(), {a, c, b});
    else mesh.index.insert(mesh.index.end(), {a, b, c});
  }
};

int region_index(const std::vector<std::string>& regions, const std::string& name) {
  for (std::size_t i = 0; i < regions.size(); ++i)
    if (regions[i] == name) return static_cast<int>(i);
  return -1;
}

glm::vec3 hex_color(const std::string& hex) { return parse_color(hex, glm::vec3(0.8f)); }

}  // namespace

std::vector<dvec3> rest_positions(const SkeletonDef& skeleton) {
  std::vector<dvec3> out;
  for (std::size_t i = 0; i < skeleton.joints.size(); ++i) {
    const JointDef& j = skeleton.joints[i];
    const dvec3 off(j.offset_ls[0], j.offset_ls[1], j.offset_ls[2]);
    out.push_back(i == 0 || j.parent < 0 ? dvec3(0.0) : out[static_cast<std::size_t>(j.parent)] + off);
  }
  return out;
}

std::optional<BodyMesh> build_body(std::string_view spec_json, const SkeletonDef& skeleton, int lod,
                                   std::string& error) {
  const json spec = json::parse(spec_json, nullptr, false);
  if (spec.is_discarded() || !spec.is_object()) {
    error = "the body description is not JSON";
    return std::nullopt;
  }
  try {
    std::map<std::string, int> joint_index;
    for (std::size_t i = 0; i < skeleton.joints.size(); ++i) joint_index.emplace(skeleton.joints[i].name, static_cast<int>(i));
    const auto find = [&](const std::string& name) {
      const auto it = joint_index.find(name);
      if (it == joint_index.end()) throw std::runtime_error("the skeleton has no joint \"" + name + "\"");
      return it->second;
    };
    const std::vector<dvec3> rest = rest_positions(skeleton);
    Builder b;
    b.mesh.regions = spec.at("regions").get<std::vector<std::string>>();
    const auto& points = spec.at("points");
    const int N = points.at(std::min<std::size_t>(static_cast<std::size_t>(lod), points.size() - 1)).get<int>();

    struct Ring {
      std::uint32_t first;
      dvec3 centre;
      int j, blend;
      double bw;
      int m;
    };
    std::vector<std::pair<const json*, bool>> chains;
    for (const json& c : spec.at("chains")) {
      chains.emplace_back(&c, false);
      if (c.contains("mirror")) chains.emplace_back(&c, true);
    }
    for (const auto& [chain_ptr, mirror] : chains) {
      const json& chain = *chain_ptr;
      const auto rename = [&](const std::string& name) {
        return mirror && name.rfind("r_", 0) == 0 ? chain.at("mirror").get<std::string>() + name.substr(2) : name;
      };
      const bool along_x = chain.at("axis").get<std::string>() == "x";
      std::vector<Ring> rings;
      for (const json& r : chain.at("rings")) {
        const int j = find(rename(r.at("j").get<std::string>()));
        int blend = -1;
        double bw = 0;
        if (r.contains("b")) {
          blend = find(rename(r.at("b").at(0).get<std::string>()));
          bw = r.at("b").at(1).get<double>();
        }
        const int m = region_index(b.mesh.regions, r.at("m").get<std::string>());
        const double c0 = r.contains("c") ? r.at("c").at(0).get<double>() : 0.0;
        const double c1 = r.contains("c") ? r.at("c").at(1).get<double>() : 0.0;
        const double s = mirror ? -1.0 : 1.0;
        const double at = r.at("at").get<double>();
        const dvec3 local = along_x ? dvec3(at, c0, c1 * s) : dvec3(c0, at, c1 * s);
        const dvec3 centre = local + rest[static_cast<std::size_t>(j)];
        const double r0 = r.at("r").at(0).get<double>(), r1 = r.at("r").at(1).get<double>();
        const std::uint32_t first = static_cast<std::uint32_t>(b.mesh.positions.size());
        for (int k = 0; k < N; ++k) {
          const double th = (2 * kPi * k) / N;
          const double u = r0 * std::cos(th), v = r1 * std::sin(th) * s;
          const dvec3 off = along_x ? dvec3(0, u, v) : dvec3(u, 0, v);
          b.vertex(centre + off, j, blend, bw, m);
        }
        rings.push_back({first, centre, j, blend, bw, m});
      }
      for (std::size_t i = 0; i + 1 < rings.size(); ++i) {
        const Ring &A = rings[i], &B = rings[i + 1];
        for (int k = 0; k < N; ++k) {
          const std::uint32_t a = A.first + k, bb = A.first + (k + 1) % N, c = B.first + (k + 1) % N, d = B.first + k;
          b.tri(a, bb, c, A.centre);
          b.tri(a, c, d, A.centre);
        }
      }
      const auto cap = [&](const Ring& R, const Ring& away) {
        const dvec3 dir = R.centre - away.centre;
        double len = std::hypot(dir.x, dir.y, dir.z);
        if (len == 0) len = 1;
        const dvec3 tip = R.centre + (dir / len) * 0.01;
        const std::uint32_t t = b.vertex(tip, R.j, R.blend, R.bw, R.m);
        for (int k = 0; k < N; ++k) b.tri(t, R.first + k, R.first + (k + 1) % N, away.centre);
      };
      const json caps = chain.value("caps", json::array({false, false}));
      if (caps.at(0).get<bool>() && rings.size() > 1) cap(rings[0], rings[1]);
      if (caps.at(1).get<bool>() && rings.size() > 1) cap(rings.back(), rings[rings.size() - 2]);
    }

    const json& h = spec.at("head");
    const int hj = find(h.at("j").get<std::string>());
    const auto& head_rings = h.at("rings");
    const int R = head_rings.at(std::min<std::size_t>(static_cast<std::size_t>(lod), head_rings.size() - 1)).get<int>();
    const dvec3 hc = dvec3(h.at("c").at(0).get<double>(), h.at("c").at(1).get<double>(), h.at("c").at(2).get<double>()) +
                     rest[static_cast<std::size_t>(hj)];
    const dvec3 hr(h.at("r").at(0).get<double>(), h.at("r").at(1).get<double>(), h.at("r").at(2).get<double>());
    const int skin = region_index(b.mesh.regions, h.at("m").get<std::string>());
    const int hair = region_index(b.mesh.regions, "hair");
    const json& hair_rule = h.at("hair");
    const double above = hair_rule.at("above").get<double>(), behind = hair_rule.at("behind").get<double>(),
                 behind_above = hair_rule.at("behind_above").get<double>();
    const bool nose = h.contains("nose");
    const dvec3 nose_at = nose ? dvec3(h["nose"]["at"][0].get<double>(), h["nose"]["at"][1].get<double>(),
                                       h["nose"]["at"][2].get<double>())
                               : dvec3(0.0);
    const double nose_r = nose ? h["nose"]["radius"].get<double>() : 0, nose_push = nose ? h["nose"]["push"].get<double>() : 0;
    const auto head_vertex = [&](dvec3 p) {
      const dvec3 rel = p - hc;
      if (nose) {
        const dvec3 d3 = rel - nose_at;
        const double d = std::hypot(d3.x, d3.y, d3.z);
        if (d < nose_r) p = dvec3(p.x + nose_push * (1 - d / nose_r), p.y, p.z);
      }
      const bool is_hair = rel.y > above || (rel.x < behind && rel.y > behind_above);
      return b.vertex(p, hj, -1, 0, is_hair ? hair : skin);
    };
    const std::uint32_t head_first = static_cast<std::uint32_t>(b.mesh.positions.size());
    for (int i = 1; i < R; ++i) {
      const double phi = (kPi * i) / R;
      for (int k = 0; k < N; ++k) {
        const double th = (2 * kPi * k) / N;
        head_vertex({hc.x + hr.x * std::sin(phi) * std::cos(th), hc.y + hr.y * std::cos(phi),
                     hc.z + hr.z * std::sin(phi) * std::sin(th)});
      }
    }
    const std::uint32_t top = head_vertex({hc.x, hc.y + hr.y, hc.z});
    const std::uint32_t bottom = head_vertex({hc.x, hc.y - hr.y, hc.z});
    for (int i = 0; i + 1 < R - 1; ++i)
      for (int k = 0; k < N; ++k) {
        const std::uint32_t a = head_first + i * N + k, bb = head_first + i * N + (k + 1) % N;
        const std::uint32_t c = head_first + (i + 1) * N + (k + 1) % N, d = head_first + (i + 1) * N + k;
        b.tri(a, bb, c, hc);
        b.tri(a, c, d, hc);
      }
    const std::uint32_t last = head_first + static_cast<std::uint32_t>((R - 2) * N);
    for (int k = 0; k < N; ++k) {
      b.tri(top, head_first + k, head_first + (k + 1) % N, hc);
      b.tri(bottom, last + k, last + (k + 1) % N, hc);
    }
    return std::move(b.mesh);
  } catch (const std::exception& e) {
    error = std::string("body description: ") + e.what();
    return std::nullopt;
  }
}

std::vector<BodyNumber> body_numbers(std::string_view spec_json, const SkeletonDef& skeleton) {
  std::vector<BodyNumber> out;
  const json spec = json::parse(spec_json, nullptr, false);
  if (spec.is_discarded() || !spec.contains("numbers")) return out;
  for (const json& n : spec["numbers"]) {
    for (std::size_t i = 0; i < skeleton.joints.size(); ++i) {
      if (skeleton.joints[i].name != n.value("j", "")) continue;
      BodyNumber b;
      b.joint = static_cast<int>(i);
      b.at = glm::vec3(n["at"][0].get<float>(), n["at"][1].get<float>(), n["at"][2].get<float>());
      b.size = n.value("size", 0.1f);
      b.face = n.value("face", 1);
      out.push_back(b);
    }
  }
  return out;
}

BodySummary summarize(const BodyMesh& mesh) {
  BodySummary s;
  s.vertices = mesh.positions.size();
  s.triangles = mesh.index.size() / 3;
  s.min = {INFINITY, INFINITY, INFINITY};
  s.max = {-INFINITY, -INFINITY, -INFINITY};
  double sum = 0;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const double v = static_cast<double>(static_cast<float>(mesh.positions[i][k]));  // the page keeps float32
      s.min[static_cast<std::size_t>(k)] = std::min(s.min[static_cast<std::size_t>(k)], v);
      s.max[static_cast<std::size_t>(k)] = std::max(s.max[static_cast<std::size_t>(k)], v);
      sum += v * (k + 1);
    }
    s.bone_region_sum += mesh.bones[i][0] * 3 + mesh.bones[i][1] + mesh.region[i] * 7;
  }
  for (std::size_t t = 0; t + 2 < mesh.index.size(); t += 3)
    s.index_sum += mesh.index[t] + 2LL * mesh.index[t + 1] + 3LL * mesh.index[t + 2];
  const auto r = [](double v) { return std::round(v * 1000) / 1000; };
  for (auto& v : s.min) v = r(v);
  for (auto& v : s.max) v = r(v);
  s.position_sum = r(sum);
  return s;
}

std::array<glm::vec3, 2> body_tones(std::string_view spec_json, Side side, int unum) {
  const json spec = json::parse(spec_json, nullptr, false);
  const int s = side == Side::Left ? 0 : 1;
  std::array<glm::vec3, 2> out{glm::vec3(0.8f, 0.6f, 0.45f), glm::vec3(0.15f)};
  if (spec.is_discarded()) return out;
  const auto& skin = spec["skin_tones"];
  const auto& hair = spec["hair_tones"];
  if (!skin.empty()) out[0] = hex_color(skin[static_cast<std::size_t>((unum * 7 + s * 3) % static_cast<int>(skin.size()))]);
  if (!hair.empty()) out[1] = hex_color(hair[static_cast<std::size_t>((unum * 5 + s * 2 + 1) % static_cast<int>(hair.size()))]);
  return out;
}

std::vector<glm::vec3> rest_normals(const BodyMesh& mesh) {
  std::vector<dvec3> acc(mesh.positions.size(), dvec3(0.0));
  for (std::size_t t = 0; t + 2 < mesh.index.size(); t += 3) {
    const auto a = mesh.index[t], b = mesh.index[t + 1], c = mesh.index[t + 2];
    const dvec3 n = cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    acc[a] += n;
    acc[b] += n;
    acc[c] += n;
  }
  std::vector<glm::vec3> out(acc.size());
  for (std::size_t i = 0; i < acc.size(); ++i) {
    const double l = std::hypot(acc[i].x, acc[i].y, acc[i].z);
    out[i] = l > 0 ? glm::vec3(acc[i] / l) : glm::vec3(0, 1, 0);
  }
  return out;
}

void skin_body(const BodyMesh& mesh, const std::vector<dvec3>& rest, const std::vector<glm::mat4>& joints,
               const std::vector<glm::vec3>& normals, std::vector<glm::vec3>& out_pos,
               std::vector<glm::vec3>& out_normal) {
  const std::size_t n = mesh.positions.size();
  out_pos.resize(n);
  out_normal.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    glm::vec3 p(0.0f), nn(0.0f);
    for (int k = 0; k < 2; ++k) {
      const double w = mesh.weights[i][static_cast<std::size_t>(k)];
      if (w <= 0) continue;
      const auto j = static_cast<std::size_t>(mesh.bones[i][static_cast<std::size_t>(k)]);
      if (j >= joints.size()) continue;
      const glm::vec3 local(mesh.positions[i] - rest[j]);
      p += static_cast<float>(w) * glm::vec3(joints[j] * glm::vec4(local, 1.0f));
      nn += static_cast<float>(w) * glm::vec3(joints[j] * glm::vec4(normals[i], 0.0f));
    }
    out_pos[i] = p;
    const float l = glm::length(nn);
    out_normal[i] = l > 0 ? nn / l : glm::vec3(0, 1, 0);
  }
}

}  // namespace mc::viewer

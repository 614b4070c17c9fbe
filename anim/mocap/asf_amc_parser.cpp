#include "anim/mocap/asf_amc_parser.hpp"

#include <cmath>
#include <map>
#include <numbers>

#include <glm/geometric.hpp>

#include "anim/mocap/bvh_parser.hpp"
#include "anim/mocap/text_cursor.hpp"

namespace mc::anim::mocap {

std::string cgspeed_name(const std::string& b) {
  static const std::map<std::string, std::string> names = {
      {"root", "Hips"}, {"lowerback", "LowerBack"}, {"upperback", "Spine"}, {"thorax", "Spine1"},
      {"lowerneck", "Neck"}, {"upperneck", "Neck1"}, {"head", "Head"},
      {"lhipjoint", "LHipJoint"}, {"lfemur", "LeftUpLeg"}, {"ltibia", "LeftLeg"}, {"lfoot", "LeftFoot"},
      {"ltoes", "LeftToeBase"}, {"rhipjoint", "RHipJoint"}, {"rfemur", "RightUpLeg"}, {"rtibia", "RightLeg"},
      {"rfoot", "RightFoot"}, {"rtoes", "RightToeBase"}, {"lclavicle", "LeftShoulder"}, {"lhumerus", "LeftArm"},
      {"lradius", "LeftForeArm"}, {"lwrist", "LeftHand"}, {"lhand", "LeftFingerBase"}, {"lfingers", "LeftHandIndex1"},
      {"lthumb", "LThumb"}, {"rclavicle", "RightShoulder"}, {"rhumerus", "RightArm"}, {"rradius", "RightForeArm"},
      {"rwrist", "RightHand"}, {"rhand", "RightFingerBase"}, {"rfingers", "RightHandIndex1"}, {"rthumb", "RThumb"}};
  const auto it = names.find(b);
  return it == names.end() ? b : it->second;
}

namespace {

// The whitespace-separated tokens of `line`, into `out` (reused from line to
// line: one allocation per file, not one per line).
void split(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t s = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > s) out.push_back(line.substr(s, i - s));
  }
}

// Rotation for an axis order string such as "XYZ": rotate about X first, so
// R = R_Z * R_Y * R_X (the ASF convention).
glm::quat ordered_rotation(const std::string& order, const double* deg_xyz) {
  char axes[3];
  double deg[3];
  const int n = static_cast<int>(order.size());
  for (int i = 0; i < n; ++i) {
    axes[i] = order[static_cast<std::size_t>(n - 1 - i)];
    const char c = static_cast<char>(axes[i] | 0x20);
    deg[i] = deg_xyz[c - 'x'];
  }
  return euler_to_quat(axes, n, deg);
}

bool valid_axis_order(std::string_view s) {
  if (s.size() != 3) return false;
  int seen = 0;
  for (char c : s) {
    const char l = static_cast<char>(c | 0x20);
    if (l < 'x' || l > 'z') return false;
    seen |= 1 << (l - 'x');
  }
  return seen == 7;
}

}  // namespace

AsfResult parse_asf(std::string_view text) {
  AsfResult r;
  TextCursor cur(text);
  auto fail = [&](const std::string& m) { r.ok = false; r.error = cur.error_at(m); return r; };
  std::string section;
  std::map<std::string, int> by_asf_name;
  std::vector<std::string> asf_names;
  std::vector<std::pair<std::string, std::string>> links;  // parent, child (ASF names)
  double angle_scale = 1;
  AsfBone bone;
  bool in_bone = false, in_limits = false;
  std::string root_axis = "XYZ";
  double root_orient[3] = {0, 0, 0};
  std::vector<std::string_view> tok;
  while (!cur.at_end()) {
    const auto line = cur.rest_of_line();
    split(line, tok);
    if (tok.empty() || tok[0][0] == '#') continue;
    if (tok[0][0] == ':') {
      section = std::string(tok[0]);
      in_limits = false;
      continue;
    }
    if (section == ":units") {
      if (tok.size() >= 2 && tok[0] == "length" && !parse_double(tok[1], r.skeleton.length_unit)) return fail("bad length unit");
      if (tok.size() >= 2 && tok[0] == "angle") angle_scale = tok[1] == "rad" ? 180.0 / std::numbers::pi : 1.0;
    } else if (section == ":root") {
      if (tok[0] == "axis" && tok.size() >= 2) {
        if (!valid_axis_order(tok[1])) return fail("bad root axis order");
        root_axis = std::string(tok[1]);
      } else if (tok[0] == "orientation" && tok.size() >= 4) {
        for (int i = 0; i < 3; ++i)
          if (!parse_double(tok[static_cast<std::size_t>(i + 1)], root_orient[i])) return fail("bad root orientation");
      } else if (tok[0] == "order") {
        r.skeleton.root_order.clear();
        for (std::size_t i = 1; i < tok.size(); ++i) {
          const auto t = tok[i];
          if (t.size() != 2 || (t[0] != 'T' && t[0] != 'R') || t[1] < 'X' || t[1] > 'Z') return fail("bad root order");
          r.skeleton.root_order += static_cast<char>(t[0] == 'T' ? (t[1] | 0x20) : t[1]);
        }
      }
    } else if (section == ":bonedata") {
      if (tok[0] == "begin") { bone = AsfBone(); in_bone = true; in_limits = false; continue; }
      if (!in_bone) continue;
      if (tok[0] == "end") {
        if (bone.name.empty()) return fail("bone without a name");
        if (by_asf_name.count(bone.name) || bone.name == "root") return fail("duplicate bone '" + bone.name + "'");
        by_asf_name[bone.name] = static_cast<int>(asf_names.size());
        asf_names.push_back(bone.name);
        r.skeleton.bones.push_back(bone);
        in_bone = false;
        continue;
      }
      if (tok[0] == "name" && tok.size() >= 2) bone.name = std::string(tok[1]);
      else if (tok[0] == "direction" && tok.size() >= 4) {
        double d[3];
        for (int i = 0; i < 3; ++i)
          if (!parse_double(tok[static_cast<std::size_t>(i + 1)], d[i])) return fail("bad direction");
        bone.direction = glm::vec3(static_cast<float>(d[0]), static_cast<float>(d[1]), static_cast<float>(d[2]));
        const float len = glm::length(bone.direction);
        if (len > 1e-9f) bone.direction /= len;
      } else if (tok[0] == "length" && tok.size() >= 2) {
        if (!parse_double(tok[1], bone.length) || bone.length < 0) return fail("bad length");
      } else if (tok[0] == "axis" && tok.size() >= 5) {
        double a[3];
        for (int i = 0; i < 3; ++i) {
          if (!parse_double(tok[static_cast<std::size_t>(i + 1)], a[i])) return fail("bad axis");
          a[i] *= angle_scale;
        }
        if (!valid_axis_order(tok[4])) return fail("bad axis order");
        bone.axis = ordered_rotation(std::string(tok[4]), a);
      } else if (tok[0] == "dof") {
        for (std::size_t i = 1; i < tok.size(); ++i) {
          const auto t = tok[i];
          if (t != "rx" && t != "ry" && t != "rz") return fail("unsupported dof '" + std::string(t.substr(0, 16)) + "'");
          bone.dofs += t[1];
        }
      } else if (tok[0] == "limits") {
        in_limits = true;
      }
    } else if (section == ":hierarchy") {
      if (tok[0] == "begin" || tok[0] == "end") continue;
      for (std::size_t i = 1; i < tok.size(); ++i) links.emplace_back(std::string(tok[0]), std::string(tok[i]));
    }
  }
  (void)in_limits;
  // Parents from the hierarchy, then a parents-first order.
  const std::size_t n = r.skeleton.bones.size();
  std::vector<int> parent(n, -2);
  for (const auto& [p, c] : links) {
    const auto ci = by_asf_name.find(c);
    if (ci == by_asf_name.end()) return fail("hierarchy names unknown bone '" + c + "'");
    int pi = -1;
    if (p != "root") {
      const auto it = by_asf_name.find(p);
      if (it == by_asf_name.end()) return fail("hierarchy names unknown bone '" + p + "'");
      pi = it->second;
    }
    if (parent[static_cast<std::size_t>(ci->second)] != -2) return fail("bone '" + c + "' has two parents");
    parent[static_cast<std::size_t>(ci->second)] = pi;
  }
  std::vector<int> order, placed(n, -1);
  // Breadth-first from the root: each pass places the bones whose parent is placed.
  for (bool progress = true; progress;) {
    progress = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (placed[i] >= 0 || parent[i] == -2) continue;
      if (parent[i] == -1 || placed[static_cast<std::size_t>(parent[i])] >= 0) {
        placed[i] = static_cast<int>(order.size());
        order.push_back(static_cast<int>(i));
        progress = true;
      }
    }
  }
  std::vector<AsfBone> sorted;
  for (int i : order) {
    AsfBone b = r.skeleton.bones[static_cast<std::size_t>(i)];
    const int p = parent[static_cast<std::size_t>(i)];
    b.parent = p < 0 ? -1 : placed[static_cast<std::size_t>(p)];
    b.name = cgspeed_name(b.name);
    sorted.push_back(std::move(b));
  }
  r.skeleton.bones = std::move(sorted);  // bones outside the hierarchy are dropped
  const double ro[3] = {root_orient[0] * angle_scale, root_orient[1] * angle_scale, root_orient[2] * angle_scale};
  r.skeleton.root_axis = ordered_rotation(root_axis, ro);
  r.skeleton.root_axis_order = root_axis;
  if (r.skeleton.root_order.empty()) r.skeleton.root_order = "xyzXYZ";
  if (!(r.skeleton.length_unit > 0)) return fail("length unit must be positive");
  r.ok = true;
  return r;
}

AmcResult parse_amc(std::string_view text, const AsfSkeleton& asf, const AmcOptions& options) {
  AmcResult r;
  TextCursor cur(text);
  auto fail = [&](const std::string& m) { r.ok = false; r.error = cur.error_at(m); return r; };
  const double to_m = 0.0254 / asf.length_unit;
  const std::size_t nb = asf.bones.size();
  // Internal skeleton: joint 0 = root (Hips), joint 1 + i = bone i, then end sites.
  MocapSkeleton& s = r.clip.skeleton;
  s.names.push_back("Hips"); s.parents.push_back(-1); s.offsets.emplace_back(0); s.end_site.push_back(false);
  std::vector<bool> has_child(nb, false);
  std::map<std::string, int> bone_index;
  for (std::size_t i = 0; i < nb; ++i) {
    const auto& b = asf.bones[i];
    bone_index[b.name] = static_cast<int>(i);
    s.names.push_back(b.name);
    s.parents.push_back(b.parent < 0 ? 0 : b.parent + 1);
    glm::vec3 off(0);
    if (b.parent >= 0) {
      const auto& p = asf.bones[static_cast<std::size_t>(b.parent)];
      off = p.direction * static_cast<float>(p.length * to_m);
      has_child[static_cast<std::size_t>(b.parent)] = true;
    }
    s.offsets.push_back(off);
    s.end_site.push_back(false);
  }
  for (std::size_t i = 0; i < nb; ++i) {
    if (has_child[i]) continue;
    const auto& b = asf.bones[i];
    s.names.push_back(b.name + "_end");
    s.parents.push_back(static_cast<int>(i) + 1);
    s.offsets.push_back(b.direction * static_cast<float>(b.length * to_m));
    s.end_site.push_back(true);
  }
  // CMU names for the AMC lines: AMC uses the ASF names, which cgspeed_name renamed.
  const std::size_t nj = s.names.size();
  std::vector<glm::quat> pose(nj, glm::quat(1, 0, 0, 0));
  glm::vec3 root(0);
  bool in_frame = false;
  auto flush = [&]() {
    r.clip.root_position.push_back(root);
    r.clip.local.insert(r.clip.local.end(), pose.begin(), pose.end());
    ++r.clip.frames;
    std::fill(pose.begin(), pose.end(), glm::quat(1, 0, 0, 0));
  };
  std::vector<std::string_view> tok;
  std::vector<double> vals;
  while (!cur.at_end()) {
    const auto line = cur.rest_of_line();
    split(line, tok);
    if (tok.empty() || tok[0][0] == '#' || tok[0][0] == ':') continue;
    double v = 0;
    if (tok.size() == 1 && parse_double(tok[0], v)) {
      if (in_frame) flush();
      if (r.clip.frames >= options.max_frames) return fail("too many frames");
      in_frame = true;
      continue;
    }
    if (!in_frame) return fail("bone values before the first frame number");
    const std::string name(tok[0]);
    vals.clear();
    for (std::size_t i = 1; i < tok.size(); ++i) {
      if (!parse_double(tok[i], v)) return fail("bad value '" + std::string(tok[i].substr(0, 32)) + "'");
      vals.push_back(v);
    }
    if (name == "root") {
      if (vals.size() != asf.root_order.size()) return fail("root has " + std::to_string(vals.size()) + " values, expected " + std::to_string(asf.root_order.size()));
      double rot[3] = {0, 0, 0};
      for (std::size_t i = 0; i < vals.size(); ++i) {
        const char c = asf.root_order[i];
        if (c >= 'x') root[c - 'x'] = static_cast<float>(vals[i] * to_m);
        else rot[c - 'X'] = vals[i];
      }
      pose[0] = asf.root_axis * ordered_rotation(asf.root_axis_order, rot) * glm::conjugate(asf.root_axis);
      continue;
    }
    const auto it = bone_index.find(cgspeed_name(name));
    if (it == bone_index.end()) return fail("unknown bone '" + name.substr(0, 32) + "'");
    const auto& b = asf.bones[static_cast<std::size_t>(it->second)];
    if (vals.size() != b.dofs.size()) return fail("bone '" + name + "' expects " + std::to_string(b.dofs.size()) + " values");
    double rot[3] = {0, 0, 0};
    for (std::size_t i = 0; i < vals.size(); ++i) rot[b.dofs[i] - 'x'] = vals[i];
    // M = Rz Ry Rx whatever the dof order (CMU).
    pose[static_cast<std::size_t>(it->second) + 1] = b.axis * ordered_rotation("XYZ", rot) * glm::conjugate(b.axis);
  }
  if (in_frame) flush();
  if (r.clip.frames == 0) return fail("no frames");
  r.clip.frame_time = options.frame_time;
  r.ok = true;
  return r;
}

}  // namespace mc::anim::mocap

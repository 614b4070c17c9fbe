#include "anim/mocap/bvh_parser.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "anim/mocap/text_cursor.hpp"

namespace mc::anim::mocap {

glm::quat euler_to_quat(const char* axes, int count, const double* degrees) {
  glm::quat q(1, 0, 0, 0);
  for (int i = 0; i < count; ++i) {
    const float a = static_cast<float>(degrees[i] * std::numbers::pi / 180.0);
    glm::vec3 axis(0);
    const char c = axes[i];
    axis[c == 'X' || c == 'x' ? 0 : (c == 'Y' || c == 'y' ? 1 : 2)] = 1;
    q = q * glm::angleAxis(a, axis);
  }
  return q;
}

namespace {

struct JointChannels {
  int pos[3] = {-1, -1, -1};  // channel index (within the joint) of X/Y/Z position
  char rot_axes[3] = {0, 0, 0};
  int rot_index[3] = {-1, -1, -1};
  int rot_count = 0;
  int first = 0;  // first channel in the frame line
  int count = 0;
};

class BvhParser {
 public:
  BvhParser(std::string_view text, const BvhOptions& o) : cur_(text), opt_(o) {}

  BvhResult run() {
    BvhResult r;
    if (!expect("HIERARCHY") || !expect("ROOT")) return fail(r);
    if (!joint(-1)) return fail(r);
    if (!expect("MOTION") || !motion(r)) return fail(r);
    r.ok = true;
    return r;
  }

 private:
  BvhResult& fail(BvhResult& r) { r.ok = false; r.error = error_; return r; }

  bool expect(std::string_view word) {
    const auto t = cur_.next();
    if (t == word) return true;
    error_ = cur_.error_at("expected '" + std::string(word) + "', found '" + std::string(t.substr(0, 32)) + "'");
    return false;
  }

  bool vec3(glm::vec3& v) {
    double x, y, z;
    if (!cur_.number(x, error_) || !cur_.number(y, error_) || !cur_.number(z, error_)) return false;
    v = glm::vec3(static_cast<float>(x * opt_.unit_to_metres), static_cast<float>(y * opt_.unit_to_metres),
                  static_cast<float>(z * opt_.unit_to_metres));
    return true;
  }

  int add_joint(std::string name, int parent, bool end) {
    auto& s = clip_.skeleton;
    s.names.push_back(std::move(name));
    s.parents.push_back(parent);
    s.offsets.emplace_back(0);
    s.end_site.push_back(end);
    chans_.emplace_back();
    return s.size() - 1;
  }

  // After "ROOT"/"JOINT": name { OFFSET x y z CHANNELS n ... children }
  bool joint(int parent) {
    const auto name = cur_.next();
    if (name.empty() || name == "{") { error_ = cur_.error_at("expected a joint name"); return false; }
    if (clip_.skeleton.size() >= opt_.max_joints) { error_ = cur_.error_at("too many joints"); return false; }
    const int j = add_joint(std::string(name), parent, false);
    if (!expect("{") || !expect("OFFSET") || !vec3(clip_.skeleton.offsets[j]) || !expect("CHANNELS")) return false;
    if (!channels(j, parent < 0)) return false;
    for (;;) {
      const auto t = cur_.next();
      if (t == "}") return true;
      if (t == "JOINT") {
        if (!joint(j)) return false;
      } else if (t == "End") {
        if (!expect("Site") || !end_site(j)) return false;
      } else {
        error_ = cur_.error_at("expected JOINT, End Site or '}', found '" + std::string(t.substr(0, 32)) + "'");
        return false;
      }
    }
  }

  bool end_site(int parent) {
    if (clip_.skeleton.size() >= opt_.max_joints) { error_ = cur_.error_at("too many joints"); return false; }
    const int j = add_joint(clip_.skeleton.names[static_cast<std::size_t>(parent)] + "_end", parent, true);
    return expect("{") && expect("OFFSET") && vec3(clip_.skeleton.offsets[j]) && expect("}");
  }

  bool channels(int j, bool root) {
    double n = 0;
    if (!cur_.number(n, error_)) return false;
    if (n < 0 || n > 6 || n != std::floor(n)) { error_ = cur_.error_at("CHANNELS count must be 0..6"); return false; }
    auto& c = chans_[static_cast<std::size_t>(j)];
    c.first = channel_count_;
    c.count = static_cast<int>(n);
    channel_count_ += c.count;
    for (int i = 0; i < c.count; ++i) {
      const auto t = cur_.next();
      if (t.size() == 9 && t.substr(1) == "position" && (t[0] == 'X' || t[0] == 'Y' || t[0] == 'Z')) {
        if (!root) { error_ = cur_.error_at("position channels are supported on the root only"); return false; }
        c.pos[t[0] - 'X'] = i;
      } else if (t.size() == 9 && t.substr(1) == "rotation" && (t[0] == 'X' || t[0] == 'Y' || t[0] == 'Z')) {
        if (c.rot_count == 3) { error_ = cur_.error_at("more than 3 rotation channels"); return false; }
        c.rot_axes[c.rot_count] = t[0];
        c.rot_index[c.rot_count++] = i;
      } else {
        error_ = cur_.error_at("unknown channel '" + std::string(t.substr(0, 32)) + "'");
        return false;
      }
    }
    return true;
  }

  bool motion(BvhResult& r) {
    double frames = 0, ft = 0;
    if (!expect("Frames:") || !cur_.number(frames, error_)) return false;
    if (frames < 1 || frames > opt_.max_frames || frames != std::floor(frames)) {
      error_ = cur_.error_at("bad frame count"); return false;
    }
    if (!expect("Frame") || !expect("Time:") || !cur_.number(ft, error_)) return false;
    if (!(ft > 1e-5 && ft < 10)) { error_ = cur_.error_at("bad frame time"); return false; }
    const int n = static_cast<int>(frames);
    const auto& s = clip_.skeleton;
    const std::size_t nj = static_cast<std::size_t>(s.size());
    std::vector<double> values(static_cast<std::size_t>(channel_count_));
    std::vector<double> rot_degrees;
    clip_.frame_time = ft;
    clip_.root_position.reserve(static_cast<std::size_t>(n));
    clip_.local.reserve(static_cast<std::size_t>(n) * nj);
    for (int f = 0; f < n; ++f) {
      for (auto& v : values)
        if (!cur_.number(v, error_)) return false;
      glm::vec3 root(0);
      const auto& rc = chans_[0];
      for (int a = 0; a < 3; ++a)
        if (rc.pos[a] >= 0) root[a] = static_cast<float>(values[static_cast<std::size_t>(rc.first + rc.pos[a])] * opt_.unit_to_metres);
      clip_.root_position.push_back(root);
      rot_degrees.clear();
      for (std::size_t j = 0; j < nj; ++j) {
        const auto& c = chans_[j];
        double deg[3] = {0, 0, 0};
        for (int k = 0; k < c.rot_count; ++k) {
          deg[k] = values[static_cast<std::size_t>(c.first + c.rot_index[k])];
          rot_degrees.push_back(deg[k]);
        }
        clip_.local.push_back(euler_to_quat(c.rot_axes, c.rot_count, deg));
      }
      if (f == 0 && opt_.drop_cgspeed_tpose && n > 1 && looks_like_cgspeed_tpose(rot_degrees)) r.dropped_tpose = true;
    }
    clip_.frames = n;
    if (!cur_.at_end()) { cur_.next(); error_ = cur_.error_at("more values than the frame count says"); return false; }
    if (r.dropped_tpose) drop_frames(clip_, 1);
    r.clip = std::move(clip_);
    return true;
  }

  TextCursor cur_;
  BvhOptions opt_;
  MocapClip clip_;
  std::vector<JointChannels> chans_;
  int channel_count_ = 0;
  std::string error_;
};

}  // namespace

BvhResult parse_bvh(std::string_view text, const BvhOptions& options) {
  return BvhParser(text, options).run();
}

}  // namespace mc::anim::mocap

#include "proto/hello.hpp"

#include "proto/json_number.hpp"
#include "proto/json_text.hpp"

#include "proto/pose_frame.hpp"
#include "proto/quantizer.hpp"

namespace mc::proto {
namespace {

using nlohmann::json;

// The server_param entries a client uses: clock, sizes for drawing, and the
// areas it may show. Everything else stays on the server.
constexpr const char* kClientParams[] = {
    "half_time", "extra_half_time", "nr_normal_halfs", "nr_extra_halfs", "simulator_step",
    "ball_size", "player_size", "kickable_margin", "goal_width", "catchable_area_l",
    "catchable_area_w", "tackle_dist", "tackle_back_dist", "tackle_width", "visible_distance",
    "ball_speed_max", "player_speed_max", "penalty_shoot_outs", "stamina_max"};

json arr3(const std::array<float, 3>& a) { return json::array({a[0], a[1], a[2]}); }

std::array<float, 3> get3(const json& j) {
  if (!j.is_array() || j.size() != 3) throw std::runtime_error("expected an array of 3 numbers");
  return {json_float(j.at(0)), json_float(j.at(1)), json_float(j.at(2))};
}

}  // namespace

void fill_from_params(const GameParams& params, Hello& hello) {
  hello.field.goal_width = params.goal_width();
  hello.field.ball_radius = params.ball_size();
  for (const char* name : kClientParams)
    if (params.server.has(name)) hello.server_params[name] = params.server.number(name, 0.0);
}

json skeleton_to_json(const SkeletonDef& s) {
  json joints = json::array();
  for (const auto& j : s.joints) {
    json limits = json::array();
    for (const auto& l : j.limits) limits.push_back(json::array({l[0], l[1]}));
    joints.push_back({{"name", j.name},
                      {"parent", j.parent},
                      {"offset", arr3(j.offset_ls)},
                      {"dofs", j.dofs},
                      {"limits", limits},
                      {"segment",
                       {{"shape", j.segment.shape == SegmentShape::Sphere ? "sphere" : "box"},
                        {"size", arr3(j.segment.size)},
                        {"center", arr3(j.segment.center)}}}});
  }
  return {{"name", s.name}, {"dof_count", s.dof_count()}, {"joints", joints}};
}

bool skeleton_from_json(const json& j, SkeletonDef& out, std::string& error) {
  try {
    out = SkeletonDef{};
    out.name = j.at("name").get<std::string>();
    for (const auto& jj : j.at("joints")) {
      JointDef d;
      d.name = jj.at("name").get<std::string>();
      d.parent = json_integer<int>(jj.at("parent"));
      if (d.parent < -1 || d.parent >= static_cast<int>(out.joints.size()))
        throw std::runtime_error("joint '" + d.name + "' has a parent that does not come before it");
      d.offset_ls = get3(jj.at("offset"));
      d.dofs = jj.at("dofs").get<std::string>();
      for (const auto& l : jj.at("limits")) {
        if (!l.is_array() || l.size() != 2) throw std::runtime_error("a limit is not [min, max]");
        d.limits.push_back({json_float(l.at(0)), json_float(l.at(1))});
      }
      if (const auto seg = jj.find("segment"); seg != jj.end()) {
        d.segment.shape = seg->value("shape", "box") == "sphere" ? SegmentShape::Sphere : SegmentShape::Box;
        d.segment.size = get3(seg->at("size"));
        d.segment.center = get3(seg->at("center"));
      }
      out.joints.push_back(std::move(d));
    }
    if (out.dof_count() > kMaxDof) throw std::runtime_error("more than 64 degrees of freedom");
  } catch (const std::exception& e) {
    error = std::string("bad skeleton: ") + e.what();
    return false;
  }
  return true;
}

json hello_to_json_value(const Hello& h) {
  const FieldGeometry& f = h.field;
  const auto team = [](const TeamHello& t) { return json{{"name", t.name}, {"color", t.color}, {"color2", t.color2}}; };
  return {{"type", "hello"},
          {"protocol", {{"major", h.protocol_major}, {"minor", h.protocol_minor}}},
          {"match_id", h.match_id},
          {"frame_rate", h.frame_rate},
          {"keyframe_interval", h.keyframe_interval},
          {"quantization", {{"angle_step_deg", kAngleStepDeg}, {"heading_steps", kHeadingSteps}, {"position_step_m", kPositionStepM}}},
          {"skeleton", skeleton_to_json(h.skeleton)},
          {"field",
           {{"length", f.length}, {"width", f.width}, {"goal_width", f.goal_width}, {"goal_depth", f.goal_depth},
            {"goal_height", f.goal_height}, {"penalty_area_length", f.penalty_area_length},
            {"penalty_area_width", f.penalty_area_width}, {"goal_area_length", f.goal_area_length},
            {"goal_area_width", f.goal_area_width}, {"center_circle_radius", f.center_circle_radius},
            {"penalty_spot_distance", f.penalty_spot_distance}, {"corner_arc_radius", f.corner_arc_radius},
            {"ball_radius", f.ball_radius}}},
          {"teams", {{"left", team(h.left)}, {"right", team(h.right)}}},
          {"server_params", h.server_params}};
}

std::string to_json(const Hello& hello) { return hello_to_json_value(hello).dump(); }

bool hello_from_json(std::string_view text, Hello& out, std::string& error) {
  const json j = parse_json_text(text);
  if (j.is_discarded() || !j.is_object()) {
    error = "hello is not a JSON object";
    return false;
  }
  try {
    if (j.value("type", "") != "hello") throw std::runtime_error("\"type\" is not \"hello\"");
    out = Hello{};
    out.protocol_major = json_integer<int>(j.at("protocol").at("major"));
    out.protocol_minor = json_integer<int>(j.at("protocol").at("minor"));
    if (out.protocol_major != kProtocolMajor) {
      error = "unsupported protocol major version " + std::to_string(out.protocol_major) +
              " (this client reads version " + std::to_string(kProtocolMajor) + ")";
      return false;
    }
    out.match_id = j.value("match_id", "");
    out.frame_rate = j.at("frame_rate").get<double>();
    out.keyframe_interval = json_integer<int>(j.at("keyframe_interval"));
    if (!skeleton_from_json(j.at("skeleton"), out.skeleton, error)) return false;
    const json& f = j.at("field");
    FieldGeometry& g = out.field;
    for (auto [key, ptr] : {std::pair{"length", &g.length}, {"width", &g.width}, {"goal_width", &g.goal_width},
                            {"goal_depth", &g.goal_depth}, {"goal_height", &g.goal_height},
                            {"penalty_area_length", &g.penalty_area_length},
                            {"penalty_area_width", &g.penalty_area_width}, {"goal_area_length", &g.goal_area_length},
                            {"goal_area_width", &g.goal_area_width}, {"center_circle_radius", &g.center_circle_radius},
                            {"penalty_spot_distance", &g.penalty_spot_distance},
                            {"corner_arc_radius", &g.corner_arc_radius}, {"ball_radius", &g.ball_radius}})
      if (f.contains(key)) *ptr = f.at(key).get<double>();
    for (auto [key, team] : {std::pair{"left", &out.left}, {"right", &out.right}}) {
      const json& t = j.at("teams").at(key);
      team->name = t.value("name", "");
      team->color = t.value("color", team->color);
      team->color2 = t.value("color2", team->color2);
    }
    if (j.contains("server_params")) out.server_params = j.at("server_params").get<std::map<std::string, double>>();
  } catch (const std::exception& e) {
    error = std::string("bad hello: ") + e.what();
    return false;
  }
  return true;
}

}  // namespace mc::proto

#include "anim/tools/stream_view.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "anim/event_messages.hpp"
#include "proto/frame_codec.hpp"
#include "proto/hello.hpp"

namespace mc::anim::tools {

bool view_stream(const SkeletonDef& skeleton, const GameParams& params, const std::vector<PoseFrame>& frames,
                 const std::vector<AnimEvent>& events, StreamView& out, std::string& error) {
  out = StreamView{};
  proto::Hello hello;
  hello.skeleton = skeleton;
  proto::fill_from_params(params, hello);
  proto::Hello received;
  if (!proto::hello_from_json(proto::to_json(hello), received, error)) return false;
  out.skeleton = received.skeleton;
  out.ball_radius = received.field.ball_radius;

  proto::FrameEncoder encoder(skeleton, proto::EncoderOptions{hello.keyframe_interval});
  proto::FrameDecoder decoder(out.skeleton);
  out.frames.resize(frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    bool key = false;
    const std::string bytes = encoder.encode(frames[i], key);
    out.encoded_bytes += bytes.size();
    if (!decoder.decode(bytes, out.frames[i], error)) {
      error = "frame " + std::to_string(frames[i].seq) + ": " + error;
      return false;
    }
  }
  for (const AnimEvent& e : events) {
    if (e.type != AnimEventType::Kick) continue;
    proto::ControlMessage m;
    if (!proto::control_from_json(proto::to_json(to_control_message(e)), m, error)) return false;
    if (const auto* k = std::get_if<proto::KickEvent>(&m)) out.kicks.push_back(*k);
  }
  return true;
}

void blend_like_clients(const PoseFrame& a, const PoseFrame& b, float t, int dof_count, PoseFrame& out,
                        const LegBlend* legs) {
  auto lerp = [](float p, float q, float s) { return p + (q - p) * s; };
  out.seq = a.seq;
  out.time = a.time;
  out.stoppage = a.stoppage;
  out.substep = a.substep;
  out.play_mode = a.play_mode;
  out.score_left = a.score_left;
  out.score_right = a.score_right;
  out.ball.x = lerp(a.ball.x, b.ball.x, t);
  out.ball.y = lerp(a.ball.y, b.ball.y, t);
  out.ball.z = lerp(a.ball.z, b.ball.z, t);
  const int n = std::clamp(dof_count, 0, kMaxDof);
  for (std::size_t i = 0; i < kMaxPlayers; ++i) {
    const PlayerPose& pa = a.players[i];
    const PlayerPose& pb = b.players[i].side == pa.side && b.players[i].unum == pa.unum ? b.players[i] : pa;
    PlayerPose& o = out.players[i];
    o.side = pa.side;
    o.unum = pa.unum;
    o.state = pa.state;
    const bool jump = std::hypot(pb.x - pa.x, pb.y - pa.y) > 5.0f;
    const float tt = jump ? (t < 0.5f ? 0.0f : 1.0f) : t;
    o.x = lerp(pa.x, pb.x, tt);
    o.y = lerp(pa.y, pb.y, tt);
    o.z = lerp(pa.z, pb.z, tt);
    float d = std::fmod(pb.heading - pa.heading, 360.0f);
    if (d >= 180.0f) d -= 360.0f;
    if (d < -180.0f) d += 360.0f;
    o.heading = pa.heading + d * tt;
    for (int k = 0; k < n; ++k)
      o.angles[static_cast<std::size_t>(k)] = lerp(pa.angles[static_cast<std::size_t>(k)], pb.angles[static_cast<std::size_t>(k)], tt);
  }
  if (legs) legs->apply(a, b, t, out);
}

}  // namespace mc::anim::tools

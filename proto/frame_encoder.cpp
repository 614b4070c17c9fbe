#include "proto/frame_codec.hpp"

namespace mc::proto {
namespace {

std::uint32_t pos_bits(std::int32_t v) { return static_cast<std::uint32_t>(v) & 0xffffu; }

bool meta_differs(const QuantPlayer& a, const QuantPlayer& b) {
  return a.side != b.side || a.unum != b.unum || a.state != b.state;
}

void write_meta(const QuantPlayer& p, BitWriter& w) {
  w.put(p.side, 2);
  w.put(p.unum, 4);
  w.put_varbits(p.state);
}

}  // namespace

FrameEncoder::FrameEncoder(const SkeletonDef& skeleton, EncoderOptions options)
    : quant_(skeleton), options_(options) {
  if (options_.keyframe_interval < 1) options_.keyframe_interval = 1;
}

std::string FrameEncoder::encode(const PoseFrame& frame, bool& is_keyframe) {
  is_keyframe = !started_ || force_key_ || since_key_ >= options_.keyframe_interval ||
                frame.seq != last_seq_ + 1;
  const QuantFrame q = quant_.quantize(frame);

  FrameHeader h;
  h.keyframe = is_keyframe;
  h.seq = frame.seq;
  h.time = frame.time;
  h.stoppage = frame.stoppage;
  h.substep = frame.substep;
  h.play_mode = static_cast<std::uint8_t>(frame.play_mode);
  h.score_left = frame.score_left;
  h.score_right = frame.score_right;
  h.server_time_ms = frame.server_time_ms;
  std::string out;
  out.reserve(kFrameHeaderSize + 256);
  write_header(h, out);

  BitWriter w;
  if (is_keyframe) {
    write_keyframe(q, w);
    model_.start_keyframe(q);
    since_key_ = 1;
  } else {
    write_delta(q, w);
    model_.push(q);
    ++since_key_;
  }
  out += w.finish();
  started_ = true;
  force_key_ = false;
  last_seq_ = frame.seq;
  return out;
}

void FrameEncoder::write_keyframe(const QuantFrame& q, BitWriter& w) {
  w.put(quant_.fingerprint(), 32);
  for (int a = 0; a < 3; ++a) w.put(pos_bits(q.ball[a]), kPositionBits);
  for (const QuantPlayer& p : q.players) {
    write_meta(p, w);
    w.put(pos_bits(p.x), kPositionBits);
    w.put(pos_bits(p.y), kPositionBits);
    w.put(pos_bits(p.z), kPositionBits);
    w.put(static_cast<std::uint32_t>(p.heading), 9);
    for (int d = 0; d < quant_.dof_count(); ++d)
      w.put(static_cast<std::uint32_t>(p.angles[static_cast<std::size_t>(d)]), quant_.grid(d).bits);
  }
}

void FrameEncoder::write_delta(const QuantFrame& q, BitWriter& w) {
  detail::CodecModel& m = model_;
  const QuantFrame& p1 = m.prev;
  const QuantFrame& p0 = m.prev2;

  std::int32_t ball_r[3];
  bool ball_moved = false;
  for (int a = 0; a < 3; ++a) {
    ball_r[a] = q.ball[a] - m.predict(p1.ball[a], p0.ball[a], kPositionMin, kPositionMax);
    ball_moved |= ball_r[a] != 0;
  }
  w.put_bit(ball_moved);
  if (ball_moved) {
    m.ball_xy.write(w, ball_r[0]);
    m.ball_xy.write(w, ball_r[1]);
    m.ball_z.write(w, ball_r[2]);
  }

  const int dofs = quant_.dof_count();
  for (std::size_t i = 0; i < q.players.size(); ++i) {
    const QuantPlayer& p = q.players[i];
    const QuantPlayer& a1 = p1.players[i];
    const QuantPlayer& a0 = p0.players[i];

    const bool meta = meta_differs(p, a1);
    w.put_bit(meta);
    if (meta) write_meta(p, w);

    const std::int32_t rx = p.x - m.predict(a1.x, a0.x, kPositionMin, kPositionMax);
    const std::int32_t ry = p.y - m.predict(a1.y, a0.y, kPositionMin, kPositionMax);
    const std::int32_t rz = p.z - m.predict(a1.z, a0.z, kPositionMin, kPositionMax);
    const std::int32_t rh = detail::CodecModel::wrap_signed(p.heading - m.predict_heading(a1.heading, a0.heading));
    const bool root = rx != 0 || ry != 0 || rz != 0 || rh != 0;
    w.put_bit(root);
    if (root) {
      m.pos_xy.write(w, rx);
      m.pos_xy.write(w, ry);
      m.pos_z.write(w, rz);
      m.heading.write(w, rh);
    }

    std::array<std::int32_t, kMaxDof> ra{};
    bool pose = false;
    for (int d = 0; d < dofs; ++d) {
      const auto k = static_cast<std::size_t>(d);
      ra[k] = p.angles[k] - m.predict(a1.angles[k], a0.angles[k], 0, quant_.grid(d).steps - 1);
      pose |= ra[k] != 0;
    }
    w.put_bit(pose);
    if (pose)
      for (int d = 0; d < dofs; ++d) m.angle[static_cast<std::size_t>(d)].write(w, ra[static_cast<std::size_t>(d)]);
  }
}

}  // namespace mc::proto

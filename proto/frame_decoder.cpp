#include "proto/frame_codec.hpp"

namespace mc::proto {
namespace {

std::int32_t read_pos(BitReader& r) {
  return static_cast<std::int32_t>(static_cast<std::int16_t>(static_cast<std::uint16_t>(r.get(kPositionBits))));
}

void read_meta(BitReader& r, QuantPlayer& p) {
  p.side = static_cast<std::uint8_t>(r.get(2));
  p.unum = static_cast<std::uint8_t>(r.get(4));
  p.state = r.get_varbits();
}

// Adds a residual to a prediction; false when the sum leaves [lo, hi]
// (only corrupt input does that).
bool apply(std::int32_t pred, std::int64_t residual, std::int32_t lo, std::int32_t hi, std::int32_t& out) {
  const std::int64_t v = pred + residual;
  if (v < lo || v > hi) return false;
  out = static_cast<std::int32_t>(v);
  return true;
}

}  // namespace

FrameDecoder::FrameDecoder(const SkeletonDef& skeleton) : quant_(skeleton) {}

bool FrameDecoder::decode(std::string_view bytes, PoseFrame& out, std::string& error) {
  FrameHeader h;
  if (!peek_header(bytes, h, error)) return false;
  if (h.play_mode >= kPlayModeCount) {
    error = "corrupt pose frame: play mode " + std::to_string(h.play_mode) + " is not defined";
    model_.history = 0;
    return false;
  }
  if (!h.keyframe) {
    if (model_.history == 0) {
      error = "delta frame " + std::to_string(h.seq) + " without its base: waiting for a keyframe";
      return false;
    }
    if (h.seq != last_seq_ + 1) {
      error = "gap before delta frame " + std::to_string(h.seq) + " (last frame was " +
              std::to_string(last_seq_) + "): waiting for a keyframe";
      model_.history = 0;
      return false;
    }
  }

  BitReader r(bytes.substr(kFrameHeaderSize));
  QuantFrame q;
  const bool ok = h.keyframe ? read_keyframe(r, q, error) : read_delta(r, q, error);
  if (ok && r.overrun()) {
    error = std::string(h.keyframe ? "key" : "delta ") + "frame " + std::to_string(h.seq) + " truncated";
  } else if (ok && h.minor == kProtocolMinor && r.bits_total() - r.bits_read() >= 8) {
    // A newer minor version may append data; our own version must not.
    error = "corrupt pose frame " + std::to_string(h.seq) + ": " +
            std::to_string((r.bits_total() - r.bits_read()) / 8) + " unexpected trailing bytes";
  } else if (ok) {
    if (h.keyframe) {
      model_.start_keyframe(q);
    } else {
      model_.push(q);
    }
    last_seq_ = h.seq;
    out.seq = h.seq;
    out.time = h.time;
    out.stoppage = h.stoppage;
    out.substep = h.substep;
    out.server_time_ms = h.server_time_ms;
    out.play_mode = static_cast<PlayMode>(h.play_mode);
    out.score_left = h.score_left;
    out.score_right = h.score_right;
    quant_.dequantize(q, out);
    return true;
  }
  model_.history = 0;  // the stream state is unknown now: wait for a keyframe
  return false;
}

bool FrameDecoder::read_keyframe(BitReader& r, QuantFrame& q, std::string& error) {
  const std::uint32_t fp = r.get(32);
  if (!r.overrun() && fp != quant_.fingerprint()) {
    error = "keyframe was encoded for a different skeleton (fingerprint " + std::to_string(fp) +
            ", expected " + std::to_string(quant_.fingerprint()) + ")";
    return false;
  }
  for (int a = 0; a < 3; ++a) q.ball[a] = read_pos(r);
  for (QuantPlayer& p : q.players) {
    read_meta(r, p);
    p.x = read_pos(r);
    p.y = read_pos(r);
    p.z = read_pos(r);
    p.heading = static_cast<std::int32_t>(r.get(9));
    if (p.heading >= kHeadingSteps) {
      error = "corrupt keyframe: heading index " + std::to_string(p.heading) + " out of range";
      return false;
    }
    for (int d = 0; d < quant_.dof_count(); ++d) {
      const auto v = static_cast<std::int32_t>(r.get(quant_.grid(d).bits));
      if (v >= quant_.grid(d).steps) {
        error = "corrupt keyframe: angle index out of range for dof " + std::to_string(d);
        return false;
      }
      p.angles[static_cast<std::size_t>(d)] = v;
    }
    if (r.overrun()) return true;  // reported by the caller as truncation
  }
  return true;
}

bool FrameDecoder::read_delta(BitReader& r, QuantFrame& q, std::string& error) {
  detail::CodecModel& m = model_;
  const QuantFrame& p1 = m.prev;
  const QuantFrame& p0 = m.prev2;
  const auto corrupt = [&](const char* what) {
    error = r.overrun() ? std::string("delta frame truncated")
                        : std::string("corrupt delta frame: ") + what + " out of range";
    return false;
  };

  q.ball[0] = p1.ball[0], q.ball[1] = p1.ball[1], q.ball[2] = p1.ball[2];
  const bool ball_moved = r.get_bit();
  for (int a = 0; a < 3; ++a) {
    const std::int64_t res = !ball_moved ? 0 : a < 2 ? m.ball_xy.read(r) : m.ball_z.read(r);
    if (!apply(m.predict(p1.ball[a], p0.ball[a], kPositionMin, kPositionMax), res, kPositionMin, kPositionMax, q.ball[a]))
      return corrupt("ball position");
  }

  const int dofs = quant_.dof_count();
  for (std::size_t i = 0; i < q.players.size(); ++i) {
    QuantPlayer& p = q.players[i];
    const QuantPlayer& a1 = p1.players[i];
    const QuantPlayer& a0 = p0.players[i];

    p.side = a1.side, p.unum = a1.unum, p.state = a1.state;
    if (r.get_bit()) read_meta(r, p);

    std::int64_t rx = 0, ry = 0, rz = 0, rh = 0;
    if (r.get_bit()) {
      rx = m.pos_xy.read(r);
      ry = m.pos_xy.read(r);
      rz = m.pos_z.read(r);
      rh = m.heading.read(r);
    }
    if (!apply(m.predict(a1.x, a0.x, kPositionMin, kPositionMax), rx, kPositionMin, kPositionMax, p.x) ||
        !apply(m.predict(a1.y, a0.y, kPositionMin, kPositionMax), ry, kPositionMin, kPositionMax, p.y) ||
        !apply(m.predict(a1.z, a0.z, kPositionMin, kPositionMax), rz, kPositionMin, kPositionMax, p.z))
      return corrupt("player position");
    if (rh < -kHeadingSteps / 2 || rh >= kHeadingSteps / 2) return corrupt("heading change");
    p.heading = detail::CodecModel::wrap(m.predict_heading(a1.heading, a0.heading) + rh);

    const bool pose = r.get_bit();
    for (int d = 0; d < dofs; ++d) {
      const auto k = static_cast<std::size_t>(d);
      const std::int32_t hi = quant_.grid(d).steps - 1;
      const std::int64_t res = pose ? m.angle[k].read(r) : 0;
      if (!apply(m.predict(a1.angles[k], a0.angles[k], 0, hi), res, 0, hi, p.angles[k])) return corrupt("joint angle");
    }
    if (r.overrun()) return true;  // reported by the caller as truncation
  }
  return true;
}

}  // namespace mc::proto

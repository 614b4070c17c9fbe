#include "viewer/director_view.hpp"

#include <algorithm>
#include <cmath>

#include "viewer/interpolate.hpp"

namespace mc::viewer {
namespace {

constexpr float kDeg = 3.14159265358979f / 180.0f;

int side_sign(Side s) { return s == Side::Left ? 1 : s == Side::Right ? -1 : 0; }

}  // namespace

ShotRig shot_rig(const proto::DirectorCue& cue, std::optional<proto::ReplayAngle> angle, const PoseFrame& frame,
                 const proto::FieldGeometry& field, float aspect) {
  const float halfW = static_cast<float>(field.width) / 2, halfL = static_cast<float>(field.length) / 2;
  const proto::Framing& f = cue.framing;
  const float bx = std::clamp(frame.ball.x, -halfL - 3, halfL + 3), by = std::clamp(frame.ball.y, -halfW - 3, halfW + 3);
  const bool portrait = aspect < 1;
  const float widen = portrait ? 1.5f : 1.0f;
  const float dir = static_cast<float>(side_sign(cue.attack));
  const float goal_x = cue.goal != Side::Neutral ? -side_sign(cue.goal) * halfL : dir * halfL;
  const PlayerPose* subject = nullptr;
  if (cue.subject_unum >= 1 && cue.subject_unum <= kPlayersPerSide && cue.subject_side != Side::Neutral) {
    const PlayerPose& p = frame.players[static_cast<std::size_t>(player_index(cue.subject_side, cue.subject_unum))];
    if (p.state != 0) subject = &p;
  }
  // Field (x, y) and a height -> scene.
  const auto S = [](float x, float h, float y) { return glm::vec3(x, h, y); };
  ShotRig r;
  switch (cue.shot) {
    case proto::Shot::Wide: {
      const float lx = bx * 0.35f;
      r = {S(lx, static_cast<float>(f.height) * widen, halfW + static_cast<float>(f.distance) * widen * 0.7f),
           S(lx, 0, by * 0.2f), static_cast<float>(f.fov)};
      break;
    }
    case proto::Shot::SetPiece: {
      const float px = subject ? subject->x : bx, py = subject ? subject->y : by;
      float dx = goal_x - px, dy = -py;
      float n = std::hypot(dx, dy);
      if (n == 0) n = 1;
      dx /= n;
      dy /= n;
      const float d = static_cast<float>(f.distance);
      r = {S(px - dx * d, static_cast<float>(f.height), py - dy * d), S(px + dx * 16, 0.6f, py + dy * 16),
           static_cast<float>(f.fov) * (portrait ? 1.2f : 1.0f)};
      break;
    }
    case proto::Shot::Attack: {
      const float lx = bx + (goal_x - bx) * 0.35f, ly = by * 0.7f;
      const float g = goal_x >= 0 ? 1.0f : -1.0f;
      const float d = static_cast<float>(f.distance);
      r = {S(lx - g * d * 0.3f, static_cast<float>(f.height), std::min(ly + d * widen, halfW + d)), S(lx, 0.5f, ly),
           static_cast<float>(f.fov)};
      break;
    }
    case proto::Shot::Scorer: {
      if (subject) {
        const float n = std::hypot(0.5f, 1.0f);
        const float fx = (dir != 0 ? dir : 1.0f) * 0.5f / n, fy = 1.0f / n;
        const float d = static_cast<float>(f.distance);
        r = {S(subject->x + fx * d, static_cast<float>(f.height), subject->y + fy * d), S(subject->x, 1.1f, subject->y),
             static_cast<float>(f.fov)};
        break;
      }
      [[fallthrough]];
    }
    case proto::Shot::Tracking: {
      const float lead = cue.shot == proto::Shot::Tracking ? static_cast<float>(f.lead) : 9.0f;
      const float dist = cue.shot == proto::Shot::Tracking ? static_cast<float>(f.distance) : 40.0f;
      const float height = cue.shot == proto::Shot::Tracking ? static_cast<float>(f.height) : 17.0f;
      const float fov = cue.shot == proto::Shot::Tracking ? static_cast<float>(f.fov) : 26.0f;
      const float lx = bx + dir * lead, ly = by * 0.6f;
      r = {S(lx, height * (portrait ? 1.4f : 1.0f), std::max(ly + dist * widen, halfW + 6)), S(lx, 0, ly),
           fov * (portrait ? 1.6f : 1.0f)};
      break;
    }
    case proto::Shot::Replay: {
      const float gx = cue.goal != Side::Neutral ? -side_sign(cue.goal) * halfL : (bx >= 0 ? halfL : -halfL);
      const float g = gx >= 0 ? 1.0f : -1.0f;
      const proto::ReplayAngle a = angle.value_or(proto::ReplayAngle::BehindGoal);
      if (a == proto::ReplayAngle::LowSide) {
        const float z = halfW + 3;
        const float d = std::max(4.0f, std::fabs(z - by));
        r = {S(bx - g * 3, 1.3f, z), S(bx, 0.6f, by), std::clamp(2 * std::atan(9 / d) / kDeg, 14.0f, 50.0f)};
      } else if (a == proto::ReplayAngle::High) {
        r = {S(bx, 38, halfW + 45), S(bx, 0, by * 0.5f), 34.0f};
      } else {
        const float out = std::clamp(std::fabs(bx - gx) * 0.6f, 14.0f, 40.0f);
        r = {S(gx + g * 9, 9, std::clamp(by * 0.25f, -6.0f, 6.0f)), S(gx - g * out, 0, by * 0.5f), portrait ? 66.0f : 55.0f};
      }
      break;
    }
  }
  return r;
}

void FrameHistory::add(const PoseFrame& f) {
  if (!frames_.empty()) {
    const std::uint32_t newest = frames_.back().seq;
    if (f.seq <= newest) {
      if (newest - f.seq > 200) frames_.clear();  // a new timeline (seek, new stream)
      else return;
    }
  }
  frames_.push_back(f);
  while (frames_.size() > capacity_) frames_.pop_front();
}

bool FrameHistory::covers(double from, double to) const {
  return !frames_.empty() && frames_.front().seq <= from && frames_.back().seq >= to;
}

bool FrameHistory::at(double seq, int dof_count, PoseFrame& out, const anim::LegBlend* feet) const {
  if (frames_.empty() || seq < frames_.front().seq || seq > frames_.back().seq) return false;
  const auto it = std::upper_bound(frames_.begin(), frames_.end(), seq,
                                   [](double s, const PoseFrame& f) { return s < static_cast<double>(f.seq); });
  const PoseFrame& a = *(it - 1);
  const PoseFrame& b = it == frames_.end() ? a : *it;
  const double span = static_cast<double>(b.seq) - a.seq;
  blend_frames(a, b, span > 0 ? static_cast<float>((seq - a.seq) / span) : 0.0f, dof_count, out, feet);
  return true;
}

bool DirectorView::show(const proto::DirectorCue& cue, bool jumped) {
  const bool same = has_current_ && current_.seq == cue.seq && current_.shot == cue.shot;
  if (same) return false;
  const bool cut = !has_current_ || cue.cut || jumped;
  current_ = cue;
  has_current_ = true;
  if (cut) ++cuts_;
  return cut;
}

std::optional<proto::ReplayAngle> DirectorView::angle() const {
  if (!replay_ || segment_ >= replay_->replay.size()) return std::nullopt;
  return replay_->replay[segment_].angle;
}

DirectorView::Step DirectorView::update(double live_seq, double dt, const std::vector<proto::DirectorCue>& cues,
                                        bool enabled, const FrameHistory& history, double rate) {
  Step step;
  if (replay_) {
    if (!enabled) {
      replay_.reset();
      step.cut = true;
    } else {
      const proto::ReplaySegment& seg = replay_->replay[segment_];
      replay_pos_ += std::max(0.0, dt) * (1000.0 / kFrameIntervalMs) * seg.speed * std::max(0.25, rate);
      if (replay_pos_ >= static_cast<double>(replay_->seq) + seg.to) {
        if (++segment_ < replay_->replay.size()) {
          replay_pos_ = static_cast<double>(replay_->seq) + replay_->replay[segment_].from;
          ++cuts_;
          step.cut = true;
        } else {
          replay_.reset();  // back to live, below
          step.cut = true;
        }
      }
      if (replay_) {
        step.replaying = true;
        step.replay_seq = replay_pos_;
        last_pos_ = live_seq;
        return step;
      }
    }
  }
  const double prev = last_pos_.value_or(live_seq);
  last_pos_ = live_seq;
  const bool jumped = std::fabs(live_seq - prev) > 60 || step.cut;
  if (enabled && !jumped) {
    for (const proto::DirectorCue& c : cues) {
      if (c.shot != proto::Shot::Replay || c.seq <= prev || c.seq > live_seq || done_.count(c.seq)) continue;
      done_.insert(c.seq);
      if (c.replay.empty()) continue;
      const double from = static_cast<double>(c.seq) + c.replay.front().from, to = static_cast<double>(c.seq) + c.replay.back().to;
      if (!history.covers(from, to)) continue;  // joined too late to have it
      replay_ = c;
      segment_ = 0;
      replay_pos_ = from;
      current_ = c;
      has_current_ = true;
      ++replays_;
      ++cuts_;
      step.cut = true;
      step.replaying = true;
      step.replay_seq = replay_pos_;
      return step;
    }
  }
  // The last shot at or before the live picture.
  const proto::DirectorCue* cue = nullptr;
  for (auto it = cues.rbegin(); it != cues.rend(); ++it)
    if (it->seq <= live_seq && it->shot != proto::Shot::Replay) {
      cue = &*it;
      break;
    }
  if (cue && show(*cue, jumped)) step.cut = true;
  return step;
}

}  // namespace mc::viewer

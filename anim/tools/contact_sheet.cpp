#include "anim/tools/contact_sheet.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

#include "anim/body_frame.hpp"
#include "anim/tools/metrics.hpp"
#include "anim/tools/png.hpp"
#include "anim/tools/strip_plot.hpp"

namespace mc::anim::tools {
namespace {

constexpr int kCells = 20;  // one second at 20 Hz

bool active(const PlayerPose& p) { return (p.state & state_bits::kStand) != 0; }

double speed(const PoseFrame& a, const PoseFrame& b, std::size_t slot) {
  return std::hypot(b.players[slot].x - a.players[slot].x, b.players[slot].y - a.players[slot].y) /
         (0.001 * kFrameIntervalMs);
}

std::string where(const PoseFrame& f, std::size_t slot) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "seq %u, %s %d", f.seq, f.players[slot].side == Side::Left ? "left" : "right",
                f.players[slot].unum);
  return buf;
}

// Marks under each sole on the grass (lowest corner below 3 cm).
void mark_soles(Image& img, int row, const SkeletonDef& skel, const std::vector<const PoseFrame*>& frames, int slot,
                float view_heading) {
  const int ground = row * kRowPx + kRowPx - 15;
  const float fc = std::cos(view_heading * kDeg), fs = std::sin(view_heading * kDeg);
  for (std::size_t c = 0; c < frames.size(); ++c) {
    const PlayerPose& pose = frames[c]->players[static_cast<std::size_t>(slot)];
    for (const char* name : {"r_foot", "l_foot"}) {
      const int j = skel.find(name);
      if (j < 0) continue;
      const Segment& seg = skel.joints[static_cast<std::size_t>(j)].segment;
      float low = 1e9f, lx = 0, ly = 0;
      for (float sx : {-0.5f, 0.5f})
        for (float sz : {-0.5f, 0.5f}) {
          const glm::vec3 local(seg.center[0] + sx * seg.size[0], seg.center[1] - 0.5f * seg.size[1],
                                seg.center[2] + sz * seg.size[2]);
          const glm::vec3 p = joint_point_field(skel, pose, j, local);
          if (p.z < low) { low = p.z; lx = p.x; ly = p.y; }
        }
      if (low >= 0.03f) continue;
      const int cx = static_cast<int>(c) * kCellPx + kCellPx / 2;
      const int px = cx + static_cast<int>(std::lround(((lx - pose.x) * fc + (ly - pose.y) * fs) * kPxPerM));
      const bool right = name[0] == 'r';
      for (int dx = -4; dx <= 4; ++dx)
        for (int dy = 2; dy <= 6; ++dy)
          img.set(px + dx, ground + dy, right ? 200 : 30, right ? 30 : 60, right ? 30 : 200);
    }
  }
}

}  // namespace

bool write_contact_sheet(const StreamView& view, const std::string& path, ContactSheetRows& rows, std::string& error) {
  const std::vector<PoseFrame>& f = view.frames;
  rows = ContactSheetRows{};
  if (f.size() < 2 * kCells + 200) {
    error = "the game is too short for a contact sheet";
    return false;
  }
  struct Pick { std::size_t first = 0; int slot = -1; };
  Pick sprint, kick, turn;
  // Sprint: the fastest second of running without a teleport (after the kick-off).
  double best = 7.0;
  for (std::size_t i = 100; i + kCells + 1 < f.size(); i += 5)
    for (std::size_t p = 0; p < kMaxPlayers; ++p) {
      double lo = 1e9, sum = 0;
      bool ok = true;
      for (std::size_t k = 0; k < kCells && ok; ++k) {
        ok = active(f[i + k].players[p]) && active(f[i + k + 1].players[p]);
        const double v = speed(f[i + k], f[i + k + 1], p);
        lo = std::min(lo, v);
        sum += v;
      }
      if (ok && lo > 6.0 && sum / kCells > best && sum / kCells < 11.0) {
        best = sum / kCells;
        sprint = {i, static_cast<int>(p)};
      }
    }
  // Kick: the first kick told to spectators that a player ran into (over 3 m/s), contact in cell 10.
  for (const proto::KickEvent& e : view.kicks) {
    const std::uint64_t seq = e.contact_time_ms / kFrameIntervalMs;
    if (seq < f[0].seq + 20) continue;
    const std::size_t c = seq - f[0].seq;
    if (c + kCells >= f.size()) continue;
    const int slot = player_index(e.side, e.unum);
    if (slot < 0) continue;
    if (speed(f[c - 10], f[c - 9], static_cast<std::size_t>(slot)) < 3.0) continue;
    kick = {c - kCells / 2 + 1, slot};
    break;
  }
  // Turn: a second in which a player turns at least 90 degrees and moves less than 0.4 m.
  for (std::size_t i = 100; i + kCells < f.size() && turn.slot < 0; i += 3)
    for (std::size_t p = 0; p < kMaxPlayers && turn.slot < 0; ++p) {
      bool ok = true;
      double turned = 0;
      for (std::size_t k = 0; k + 1 < kCells && ok; ++k) {
        ok = active(f[i + k].players[p]) && active(f[i + k + 1].players[p]);
        turned += delta_deg(f[i + k + 1].players[p].heading, f[i + k].players[p].heading);
      }
      const PlayerPose& a = f[i].players[p];
      const PlayerPose& b = f[i + kCells - 1].players[p];
      if (ok && std::fabs(turned) >= 90.0 && std::hypot(b.x - a.x, b.y - a.y) < 0.4) turn = {i, static_cast<int>(p)};
    }
  Image img(kCells * kCellPx, 3 * kRowPx);
  int drawn = 0;
  const Pick picks[3] = {sprint, kick, turn};
  std::string* names[3] = {&rows.sprint, &rows.kick, &rows.turn};
  for (int r = 0; r < 3; ++r) {
    const Pick& pk = picks[r];
    if (pk.slot < 0) continue;
    std::vector<const PoseFrame*> row;
    for (int c = 0; c < kCells; ++c) row.push_back(&f[pk.first + static_cast<std::size_t>(c)]);
    const float side = row[0]->players[static_cast<std::size_t>(pk.slot)].heading;
    draw_pose_row(img, r, view.skeleton, row, pk.slot, side);
    mark_soles(img, r, view.skeleton, row, pk.slot, side);
    *names[r] = where(*row[0], static_cast<std::size_t>(pk.slot));
    ++drawn;
  }
  if (drawn == 0) {
    error = "no sprint, kick or turn found";
    return false;
  }
  return write_png(path, img, error);
}

}  // namespace mc::anim::tools

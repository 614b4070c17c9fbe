#include "viewer/source.hpp"

#include "proto/control_messages.hpp"
#include "viewer/frame_buffer.hpp"

namespace mc::viewer {

void apply_control_message(std::string_view text, FrameBuffer& buffer) {
  proto::ControlMessage message;
  std::string error;
  if (!proto::control_from_json(text, message, error)) return;
  if (auto* teams = std::get_if<proto::TeamsUpdate>(&message)) {
    buffer.set_teams(teams->left, teams->right);
  } else if (auto* score = std::get_if<proto::ScoreUpdate>(&message)) {
    buffer.set_penalties(score->pen_left, score->pen_right);
  } else if (auto* feed = std::get_if<proto::FeedStatus>(&message)) {
    buffer.set_status(feed->lost ? "feed lost: " + feed->detail : "");
  } else if (auto* stamina = std::get_if<proto::StaminaUpdate>(&message)) {
    buffer.track().set_stamina(*stamina);
  } else if (auto* cue = std::get_if<proto::DirectorCue>(&message)) {
    buffer.track().add_cue(*cue);
  }
}

}  // namespace mc::viewer

#include "anim/mocap/reach_map_publisher.hpp"

#include <algorithm>

namespace mc::anim::mocap {

ReachMapPublisher::ReachMapPublisher(std::shared_ptr<const ReachModel> model, int every_states, MapGrid field)
    : model_(std::move(model)), every_(std::max(1, every_states)), field_(field),
      owner_(static_cast<std::size_t>(field.cells())) {}

bool ReachMapPublisher::push(const WorldState& state, const GameParams& params, proto::ReachMapUpdate& out) {
  if (count_++ % every_ != 0 || !model_) return false;
  reach_players(state, params, players_);
  int ball = -1;
  float ball_t = 0;
  ReachOverlayJob job;
  job.model = model_.get();
  job.players = players_;
  job.field = field_;
  job.ball_x = static_cast<float>(state.ball.x);
  job.ball_y = static_cast<float>(state.ball.y);
  job.ball_vx = static_cast<float>(state.ball.vx);
  job.ball_vy = static_cast<float>(state.ball.vy);
  job.ball_decay = static_cast<float>(params.server.number("ball_decay", 0.94));
  job.cycle = static_cast<float>(params.simulator_step_ms() / 1000.0);
  job.owner = owner_;
  job.ball_player = &ball;
  job.ball_time = &ball_t;
  if (!job.Run()) return false;
  out = proto::ReachMapUpdate();
  out.time = state.time;
  out.width = field_.width;
  out.height = field_.height;
  out.cell = field_.cell;
  out.x0 = field_.origin_x;
  out.y0 = field_.origin_y;
  out.cells.resize(owner_.size());
  static constexpr char kLetter[4] = {'n', 'l', 'r', 'c'};
  for (std::size_t i = 0; i < owner_.size(); ++i) out.cells[i] = kLetter[owner_[i] & 3];
  if (ball >= 0) {
    const PlayerState& p = state.players[static_cast<std::size_t>(ball)];
    out.ball_side = p.side;
    out.ball_unum = p.unum;
    out.ball_time = ball_t;
  }
  return true;
}

}  // namespace mc::anim::mocap

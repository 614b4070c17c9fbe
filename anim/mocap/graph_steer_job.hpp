// Runtime graph stepping for the mocap animation mode: at each frame, pick the
// successor of the current node whose motion over the next `lookahead` frames
// (following each clip onwards) best matches a wanted ground speed and turn
// rate. Read-only graph, no allocation, deterministic (ties go to the
// clip's own next frame, then to the lower node index).
#pragma once

#include "anim/mocap/motion_graph.hpp"

namespace mc::anim::mocap {

struct GraphSteerJob {
  const MotionGraph* graph = nullptr;  // in
  int node = 0;                        // in: current node
  float want_speed = 1.0f;             // in: m/s along the body's facing
  float want_turn = 0;                 // in: rad/s, + to the right
  float turn_weight = 1.0f;            // in: (m/s)^2 per (rad/s)^2 in the match cost
  int lookahead = 15;                  // in: frames compared (0.5 s at 30 Hz)

  int* next = nullptr;                 // out: the chosen successor
  bool* transition = nullptr;          // out, optional: whether it is a transition (blend it)

  // False when the graph or `next` is missing, `node` is out of range or has
  // no successor, or lookahead < 1.
  bool Validate() const;
  bool Run() const;
};

}  // namespace mc::anim::mocap

// Compact binary form of a built motion graph, so that tests and the server
// load it instead of rebuilding it from the clips (the tool writes the file,
// this only turns bytes into objects and back). Little-endian, versioned,
// every count and index checked on the way in: garbage gives an error, never
// a crash.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "anim/mocap/motion_graph.hpp"

namespace mc::anim::mocap {

// FNV-1a 64-bit, chained through `seed`; the cache key of inputs + parameters.
std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t seed = 0xcbf29ce484222325ull);

std::string serialize_graph(const MotionGraph& graph);
// False with `error` set when `bytes` is not a valid graph blob.
bool deserialize_graph(std::string_view bytes, MotionGraph& graph, std::string& error);

}  // namespace mc::anim::mocap

namespace mc::anim::mocap {
struct CapabilityMap;
// The cost grid of a map (no convergence history).
std::string serialize_map(const CapabilityMap& map);
bool deserialize_map(std::string_view bytes, CapabilityMap& map, std::string& error);
}  // namespace mc::anim::mocap

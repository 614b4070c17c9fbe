// Prometheus text exposition of the relay's counters and channels (/metrics).
#pragma once

#include <string>

#include "server/relay/channel_registry.hpp"
#include "server/relay/relay_stats.hpp"

namespace mc::relay {

std::string render_metrics(const RelayStats& stats, const ChannelRegistry& channels);

// The channel list as JSON (/channels): name, spectators, frames, feed state.
std::string render_channels(const ChannelRegistry& channels);

}  // namespace mc::relay

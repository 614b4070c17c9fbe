#include "server/relay/channel_registry.hpp"

namespace mc::relay {

std::shared_ptr<Channel> ChannelRegistry::open(const std::string& name) {
  std::lock_guard lock(mutex_);
  auto& slot = channels_[name];
  if (!slot) slot = std::make_shared<Channel>(name);
  if (first_.empty()) first_ = name;
  return slot;
}

std::shared_ptr<Channel> ChannelRegistry::find(const std::string& name) const {
  std::lock_guard lock(mutex_);
  auto it = channels_.find(name);
  return it == channels_.end() ? nullptr : it->second;
}

std::shared_ptr<Channel> ChannelRegistry::default_channel() const {
  std::lock_guard lock(mutex_);
  auto it = channels_.find(first_);
  if (it != channels_.end()) return it->second;
  return channels_.empty() ? nullptr : channels_.begin()->second;
}

void ChannelRegistry::remove(const std::string& name) {
  std::lock_guard lock(mutex_);
  channels_.erase(name);
  if (first_ == name) first_ = channels_.empty() ? std::string{} : channels_.begin()->first;
}

std::shared_ptr<Channel> ChannelRegistry::find_or_request(const std::string& name) {
  if (auto ch = find(name)) return ch;
  std::lock_guard lock(provider_mutex_);
  return provider_ ? provider_->request(name) : nullptr;
}

void ChannelRegistry::set_provider(ChannelProvider* provider) {
  std::lock_guard lock(provider_mutex_);
  provider_ = provider;
}

std::string ChannelRegistry::provider_metrics() const {
  std::lock_guard lock(provider_mutex_);
  return provider_ ? provider_->metrics() : std::string{};
}

std::vector<std::shared_ptr<Channel>> ChannelRegistry::all() const {
  std::lock_guard lock(mutex_);
  std::vector<std::shared_ptr<Channel>> out;
  for (const auto& [name, ch] : channels_) out.push_back(ch);
  return out;
}

}  // namespace mc::relay

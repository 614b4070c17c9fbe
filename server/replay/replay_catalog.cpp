#include "server/replay/replay_catalog.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "server/relay/log.hpp"

namespace fs = std::filesystem;

namespace mc::replay {
namespace {

// The reader's errors name the file on this machine: they go to the log,
// the spectator (who asked for a time shift) learns only that it failed.
std::nullptr_t unreadable(const std::string& channel, std::string& error) {
  relay::log_event("timeshift_failed", channel + ": " + error);
  error = "the recording of '" + channel + "' cannot be read";
  return nullptr;
}

}  // namespace

bool valid_recording_name(const std::string& name) {
  if (name.empty() || name.size() > 200 || name.front() == '.') return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) return false;
  const std::string suffix = kRecordingSuffix;
  return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::shared_ptr<relay::ReplaySource> ReplayCatalog::open(const std::string& name,
                                                         boost::asio::any_io_executor executor,
                                                         std::string& error) {
  if (dir_.empty() || !valid_recording_name(name)) {
    error = "no such recording";
    return nullptr;
  }
  const std::string path = (fs::path(dir_) / name).string();
  std::shared_ptr<const record::RecordingHello> hello;
  {
    std::lock_guard lock(mutex_);
    auto it = summaries_.find(name);
    if (it != summaries_.end()) hello = it->second.hello;
  }
  auto reader = std::make_unique<record::RecordingReader>();
  if (!reader->open(path, error, std::move(hello))) return nullptr;
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  RecordingSummary summary;
  {
    std::lock_guard lock(mutex_);
    auto it = summaries_.find(name);
    if (it != summaries_.end() && it->second.size == size) summary = it->second.summary;
  }
  if (summary.last_time == 0 && summary.goals.empty()) {
    if (!summarize(*reader, summary, error)) return nullptr;
    std::lock_guard lock(mutex_);
    summaries_[name] = Cached{size, summary, reader->shared_hello()};
  }
  auto player = std::make_shared<ReplayPlayer>(executor, name, std::move(reader), std::move(summary));
  player->start();
  return player;
}

void ReplayCatalog::set_live_recording(const std::string& channel, const std::string& name) {
  std::lock_guard lock(mutex_);
  live_[channel] = Live{name, nullptr, {}};
}

void ReplayCatalog::forget(const std::string& name) {
  std::lock_guard lock(mutex_);
  summaries_.erase(name);
}

std::shared_ptr<relay::ReplaySource> ReplayCatalog::open_timeshift(const std::string& channel,
                                                                   boost::asio::any_io_executor executor,
                                                                   std::string& error) {
  std::string name;
  RecordingSummary summary;
  std::shared_ptr<const record::RecordingHello> hello;
  {
    std::lock_guard lock(mutex_);
    auto it = live_.find(channel);
    if (dir_.empty() || it == live_.end()) {
      error = "channel '" + channel + "' is not recorded: no time shift";
      return nullptr;
    }
    Live& live = it->second;
    const std::string path = (fs::path(dir_) / live.name).string();
    if (!live.reader) {
      live.reader = std::make_unique<record::RecordingReader>();
      if (!live.reader->open(path, error)) {
        live.reader.reset();
        return unreadable(channel, error);
      }
    }
    PoseFrame f;
    if (!live.reader->refresh(error)) return unreadable(channel, error);
    while (live.reader->next(f, error)) live.summary.note(f);
    if (!error.empty()) return unreadable(channel, error);
    if (live.summary.empty) {
      error = "the recording of '" + channel + "' holds no frames yet";
      return nullptr;
    }
    name = live.name;
    summary = live.summary;
    hello = live.reader->shared_hello();
  }
  auto reader = std::make_unique<record::RecordingReader>();
  if (!reader->open((fs::path(dir_) / name).string(), error, std::move(hello))) return unreadable(channel, error);
  auto player = std::make_shared<ReplayPlayer>(executor, name, std::move(reader), std::move(summary),
                                               /*follow=*/true);
  player->start();
  return player;
}

std::string ReplayCatalog::list_json() {
  nlohmann::json list = nlohmann::json::array();
  std::error_code ec;
  if (!dir_.empty())
    for (const auto& entry : fs::directory_iterator(dir_, ec)) {
      const std::string name = entry.path().filename().string();
      if (!entry.is_regular_file(ec) || !valid_recording_name(name)) continue;
      list.push_back({{"name", name}, {"bytes", entry.file_size(ec)}});
    }
  std::sort(list.begin(), list.end(),
            [](const auto& a, const auto& b) { return a["name"].template get<std::string>() < b["name"].template get<std::string>(); });
  return nlohmann::json{{"recordings", list}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace mc::replay

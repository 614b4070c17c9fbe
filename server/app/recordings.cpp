#include "server/app/recordings.hpp"

#include <algorithm>
#include <cctype>
#include <ctime>

#include "server/relay/log.hpp"

namespace fs = std::filesystem;

namespace mc::app {
namespace {

// Digits, then at most one unit letter from `units` (multiplier each).
bool parse_with_unit(const std::string& text, const std::map<char, std::uint64_t>& units, std::uint64_t& out) {
  std::size_t digits = 0;
  while (digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits]))) ++digits;
  if (digits == 0 || digits > 15 || text.size() > digits + 1) return false;
  std::uint64_t value = std::stoull(text.substr(0, digits));
  if (text.size() == digits + 1) {
    auto it = units.find(static_cast<char>(std::tolower(static_cast<unsigned char>(text.back()))));
    if (it == units.end()) return false;
    value *= it->second;
  }
  out = value;
  return true;
}

std::string utc_stamp() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
  return stamp;
}

}  // namespace

bool parse_byte_size(const std::string& text, std::uint64_t& out) {
  return parse_with_unit(text, {{'k', 1ull << 10}, {'m', 1ull << 20}, {'g', 1ull << 30}, {'t', 1ull << 40}}, out);
}

bool parse_duration(const std::string& text, std::chrono::seconds& out) {
  std::uint64_t s = 0;
  if (!parse_with_unit(text, {{'s', 1}, {'m', 60}, {'h', 3600}, {'d', 86400}}, s)) return false;
  out = std::chrono::seconds(static_cast<std::int64_t>(s));
  return true;
}

std::vector<std::string> apply_retention(const std::string& dir, const RetentionPolicy& policy,
                                         const std::set<std::string>& keep, fs::file_time_type now) {
  std::vector<std::string> deleted;
  if (dir.empty() || (policy.max_bytes == 0 && policy.max_age.count() == 0)) return deleted;
  struct Entry {
    std::string name;
    std::uint64_t size;
    fs::file_time_type written;
  };
  std::vector<Entry> files;
  std::uint64_t total = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    std::error_code fec;
    if (!replay::valid_recording_name(name) || !e.is_regular_file(fec)) continue;
    const auto size = e.file_size(fec);
    const auto written = e.last_write_time(fec);
    if (fec) continue;
    files.push_back({name, size, written});
    total += size;
  }
  std::sort(files.begin(), files.end(), [](const Entry& a, const Entry& b) {
    return a.written != b.written ? a.written < b.written : a.name < b.name;
  });
  for (const auto& f : files) {
    if (keep.count(f.name)) continue;
    const auto age = std::chrono::duration_cast<std::chrono::seconds>(now - f.written);
    const bool too_old = policy.max_age.count() > 0 && age > policy.max_age;
    const bool too_big = policy.max_bytes > 0 && total > policy.max_bytes;
    if (!too_old && !too_big) continue;
    std::error_code rec;
    if (!fs::remove(fs::path(dir) / f.name, rec)) {
      relay::log_event("recording_delete_failed", (fs::path(dir) / f.name).string() + ": " + rec.message());
      continue;
    }
    const std::uint64_t before = total;
    total -= f.size;
    deleted.push_back(f.name);
    relay::log_event("recording_deleted",
                     (fs::path(dir) / f.name).string() + ": " + std::to_string(f.size) + " bytes, last written " +
                         std::to_string(age.count()) + " s ago; " +
                         (too_old ? "older than --record-max-age (" + std::to_string(policy.max_age.count()) + " s)"
                                  : "recordings took " + std::to_string(before) + " bytes, over --record-max-bytes (" +
                                        std::to_string(policy.max_bytes) + ")"));
  }
  return deleted;
}

Recordings::Recordings(std::string dir, RetentionPolicy policy, replay::ReplayCatalog* catalog)
    : dir_(std::move(dir)), policy_(policy), catalog_(catalog) {
  std::error_code ec;
  if (!dir_.empty()) fs::create_directories(dir_, ec);
}

Recordings::~Recordings() { stop_all(); }

std::string Recordings::next_path(const std::string& channel) {
  // <channel>-<UTC date-time>.mcrec, sorted by time; "-2"... when two games
  // start within one second.
  const std::string base = channel + "-" + utc_stamp();
  std::string name = base + replay::kRecordingSuffix;
  std::error_code ec;
  for (int n = 2; fs::exists(fs::path(dir_) / name, ec); ++n)
    name = base + "-" + std::to_string(n) + replay::kRecordingSuffix;
  return (fs::path(dir_) / name).string();
}

void Recordings::opened(const std::string& channel, const std::string& path) {
  const std::string name = fs::path(path).filename().string();
  {
    std::lock_guard lock(mutex_);
    current_[channel] = name;
  }
  if (catalog_) catalog_->set_live_recording(channel, name);
  prune();
}

bool Recordings::record(const std::shared_ptr<relay::Channel>& channel) {
  if (dir_.empty() || !channel) return false;
  RecorderOptions options;
  const std::string name = channel->name();
  options.next_path = [this, name] { return next_path(name); };
  options.on_opened = [this, name](const std::string& path) { opened(name, path); };
  std::string error;
  auto rec = Recorder::start(channel, std::move(options), error);
  if (!rec) {
    relay::log_event("recording_failed", error);
    return false;
  }
  std::lock_guard lock(mutex_);
  recorders_.push_back(std::move(rec));
  return true;
}

void Recordings::prune() {
  std::lock_guard prune_lock(prune_mutex_);
  std::set<std::string> keep;
  {
    std::lock_guard lock(mutex_);
    for (const auto& [channel, name] : current_) keep.insert(name);
  }
  for (const auto& name : apply_retention(dir_, policy_, keep))
    if (catalog_) catalog_->forget(name);
}

void Recordings::stop_all() {
  std::vector<std::shared_ptr<Recorder>> recorders;
  {
    std::lock_guard lock(mutex_);
    recorders.swap(recorders_);
  }
  for (auto& rec : recorders) rec->stop();
}

std::map<std::string, std::string> Recordings::current() const {
  std::lock_guard lock(mutex_);
  return current_;
}

}  // namespace mc::app

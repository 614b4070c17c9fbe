#include "server/app/recorder.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "proto/frame_header.hpp"
#include "server/relay/log.hpp"

namespace mc::app {
namespace {

bool is_hello(const std::string& json) {
  return json.find("\"hello\"") != std::string::npos &&
         nlohmann::json::parse(json, nullptr, false).value("type", "") == "hello";
}

}  // namespace

std::shared_ptr<Recorder> Recorder::start(const std::shared_ptr<relay::Channel>& channel, const std::string& path,
                                          std::string& error) {
  RecorderOptions options;
  options.next_path = [path, n = 0]() mutable {
    if (++n == 1) return path;
    const std::filesystem::path p(path);
    return (p.parent_path() / (p.stem().string() + "-" + std::to_string(n) + p.extension().string())).string();
  };
  return start(channel, std::move(options), error);
}

std::shared_ptr<Recorder> Recorder::start(const std::shared_ptr<relay::Channel>& channel, RecorderOptions options,
                                          std::string& error) {
  auto rec = std::shared_ptr<Recorder>(new Recorder(channel, std::move(options)));
  std::lock_guard lock(rec->mutex_);
  // Join first: the catch-up (hello + current keyframe group) and everything
  // after it then reach deliver() in order, with nothing missed.
  auto first = channel->join(rec);
  if (first.empty() || first.front().binary()) {
    channel->leave(rec.get());
    error = "channel '" + channel->name() + "' has no hello to record";
    return nullptr;
  }
  rec->hello_ = *first.front().bytes;
  if (!rec->open_next(error)) {
    channel->leave(rec.get());
    return nullptr;
  }
  for (std::size_t i = 1; i < first.size(); ++i) rec->write(first[i]);
  return rec;
}

Recorder::~Recorder() { stop(); }

std::string Recorder::path() const {
  std::lock_guard lock(mutex_);
  return writer_.is_open() ? path_ : std::string();
}

std::uint64_t Recorder::files() const {
  std::lock_guard lock(mutex_);
  return files_;
}

void Recorder::deliver(const relay::Message& m) {
  std::lock_guard lock(mutex_);
  if (!stopped_) write(m);
}

bool Recorder::open_next(std::string& error) {
  close_current();
  path_ = options_.next_path();
  failed_ = false;
  have_time_ = false;
  if (!writer_.open(path_, hello_, error, options_.writer)) {
    writer_.abandon();  // a hello that could not be written whole
    return false;
  }
  ++files_;
  relay::log_event("recording_started", path_);
  if (options_.on_opened) options_.on_opened(path_);
  return true;
}

void Recorder::close_current() {
  if (!writer_.is_open()) return;
  std::string error;
  if (!writer_.close(error)) relay::log_event("recording_close_failed", path_ + ": " + error);
  else relay::log_event("recording_closed", path_);
}

void Recorder::fail(const std::string& error) {
  // A full disk must not take the broadcast down: stop this file, keep
  // what it holds (whole records only), try again with the next game.
  failed_ = true;
  writer_.abandon();
  relay::log_event("recording_failed",
                   path_ + ": " + error +
                       "; recording of '" + channel_->name() +
                       "' stopped, the broadcast goes on; the file is readable up to the last chunk written");
}

void Recorder::write(const relay::Message& m) {
  if (!m.binary()) {
    // A different hello is a different game: it starts the next file.
    if (is_hello(*m.bytes)) {
      if (*m.bytes != hello_) {
        hello_ = *m.bytes;
        new_game_ = true;
        held_.clear();  // the old game's last words belong to neither file
      }
      return;
    }
    held_.push_back(m);
    return;
  }
  proto::FrameHeader h;
  std::string error;
  const bool has_header = proto::peek_header(*m.bytes, h, error);
  // The game clock going back is the next game (a looping log's next pass).
  const bool clock_back = has_header && have_time_ && h.time < last_time_;
  if (new_game_ || clock_back) {
    new_game_ = false;
    if (!open_next(error)) fail(error);
  }
  if (has_header) {
    have_time_ = true;
    last_time_ = h.time;
  }
  if (failed_ || !writer_.is_open()) {
    held_.clear();
    return;
  }
  for (const auto& c : held_)
    if (!writer_.add_control(*c.bytes, error)) return fail(error);
  held_.clear();
  if (!writer_.add_frame(*m.bytes, error)) fail(error);
}

void Recorder::stop() {
  channel_->leave(this);
  std::lock_guard lock(mutex_);
  if (stopped_) return;
  stopped_ = true;
  if (!writer_.is_open()) return;
  std::string error;
  for (const auto& c : held_) writer_.add_control(*c.bytes, error);
  held_.clear();
  close_current();
}

}  // namespace mc::app

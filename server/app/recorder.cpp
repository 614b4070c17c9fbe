#include "server/app/recorder.hpp"

#include "server/relay/log.hpp"

namespace mc::app {

std::shared_ptr<Recorder> Recorder::start(const std::shared_ptr<relay::Channel>& channel,
                                          const std::string& path, std::string& error) {
  auto rec = std::shared_ptr<Recorder>(new Recorder(channel, path));
  std::lock_guard lock(rec->mutex_);
  // Join first: the catch-up (hello + current keyframe group) and everything
  // after it then reach deliver() in order, with nothing missed.
  auto first = channel->join(rec);
  if (first.empty() || first.front().binary()) {
    channel->leave(rec.get());
    error = "channel '" + channel->name() + "' has no hello to record";
    return nullptr;
  }
  // No fdatasync per chunk: a chunk reaches the page cache with one write(),
  // which survives SIGKILL; syncing would stall the feed thread.
  if (!rec->writer_.open(path, *first.front().bytes, error, record::WriterOptions{20, false})) {
    channel->leave(rec.get());
    return nullptr;
  }
  for (std::size_t i = 1; i < first.size(); ++i) rec->write(first[i]);
  relay::log_event("recording_started", path);
  return rec;
}

Recorder::~Recorder() { stop(); }

void Recorder::deliver(const relay::Message& m) {
  std::lock_guard lock(mutex_);
  write(m);
}

void Recorder::write(const relay::Message& m) {
  if (failed_ || !writer_.is_open()) return;
  std::string error;
  const bool ok = m.binary() ? writer_.add_frame(*m.bytes, error) : writer_.add_control(*m.bytes, error);
  if (!ok) {
    // A full disk must not take the broadcast down: stop recording, say so.
    failed_ = true;
    relay::log_event("recording_failed", path_ + ": " + error);
  }
}

void Recorder::stop() {
  channel_->leave(this);
  std::lock_guard lock(mutex_);
  if (!writer_.is_open()) return;
  std::string error;
  if (!writer_.close(error)) relay::log_event("recording_close_failed", path_ + ": " + error);
  else relay::log_event("recording_closed", path_);
}

}  // namespace mc::app

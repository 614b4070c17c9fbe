#include "server/relay/channel.hpp"

#include <algorithm>
#include <boost/asio/post.hpp>
#include <nlohmann/json.hpp>

namespace mc::relay {
namespace {

// The slot of kKeptControlTypes that `json` goes to, or -1. A kept type
// can only be named by its quoted text or through an escape, so a message
// with neither (a replay's status, once a second per spectator, or any
// other type) is not parsed at all.
int kept_slot(std::string_view json) {
  // The quoted names, made once, not per type per message (an allocation
  // each: every control message of every channel comes through here).
  static const auto quoted = [] {
    std::array<std::string, std::size(Channel::kKeptControlTypes)> q;
    for (std::size_t i = 0; i < q.size(); ++i) q[i] = std::string("\"") + Channel::kKeptControlTypes[i] + '"';
    return q;
  }();
  bool named = json.find('\\') != std::string_view::npos;
  for (const std::string& type : quoted) named = named || json.find(type) != std::string_view::npos;
  if (!named) return -1;
  const auto j = nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object()) return -1;
  const auto it = j.find("type");
  if (it == j.end() || !it->is_string()) return -1;
  const auto& type = it->get_ref<const std::string&>();
  for (std::size_t i = 0; i < std::size(Channel::kKeptControlTypes); ++i)
    if (type == Channel::kKeptControlTypes[i]) return static_cast<int>(i);
  return -1;
}

}  // namespace

// The catch-up and the audience change together under the lock: a joiner
// gets a message either in its catch-up or from the broadcast, never both.
void Channel::set_hello(std::string json) {
  Message m = Message::control(std::move(json));
  Audience a;
  {
    std::lock_guard lock(mutex_);
    m.serial = ++published_;
    hello_ = m;
    // Frames coded against the old hello's skeleton are meaningless under the
    // new one: joiners wait for the next keyframe. The kept metadata was the
    // old game's: the publisher sends the new game's after the hello.
    gop_.clear();
    kept_ = {};
    a = audience_locked();
  }
  send(a, m);
}

void Channel::publish_frame(std::string bytes, bool keyframe) {
  Message m = Message::frame(std::move(bytes), keyframe);
  Audience a;
  {
    std::lock_guard lock(mutex_);
    m.serial = ++published_;
    if (keyframe) gop_.clear();
    // Deltas with no keyframe before them cannot be decoded by a joiner.
    if (keyframe || !gop_.empty()) gop_.push_back(m);
    a = audience_locked();
  }
  ++frames_published_;
  send(a, m);
}

void Channel::publish_control(std::string json) {
  const int slot = kept_slot(json);
  Message m = Message::control(std::move(json));
  Audience a;
  {
    std::lock_guard lock(mutex_);
    m.serial = ++published_;
    if (slot >= 0) kept_[static_cast<std::size_t>(slot)] = m;
    a = audience_locked();
  }
  send(a, m);
}

std::vector<Message> Channel::join(const std::shared_ptr<Subscriber>& s) {
  std::shared_ptr<Group> group;
  std::uint64_t after = 0;
  std::vector<Message> first;
  {
    std::lock_guard lock(mutex_);
    first.reserve(gop_.size() + 1 + kept_.size());
    if (hello_.bytes) first.push_back(hello_);
    for (const Message& k : kept_)
      if (k.bytes) first.push_back(k);
    first.insert(first.end(), gop_.begin(), gop_.end());
    auto* home = s->home();
    // A group's list is its thread's alone: a subscriber joining from
    // elsewhere is served by posts instead.
    if (home && home->get_executor().running_in_this_thread()) {
      auto it = std::find_if(groups_.begin(), groups_.end(), [home](const auto& g) { return g->home == home; });
      if (it == groups_.end()) it = groups_.insert(groups_.end(), std::make_shared<Group>(home));
      group = *it;
      after = published_;
    } else {
      subscribers_.push_back(s);
    }
  }
  if (group) {
    // On the group's thread, so no fan-out task is walking the list now. The
    // Tap stays alive while listed: its session leaves before dropping it.
    group->list.push_back({s, after});
    ++group->count;
  }
  return first;
}

void Channel::leave(const Subscriber* s) {
  std::vector<std::shared_ptr<Group>> groups;
  {
    std::lock_guard lock(mutex_);
    std::erase_if(subscribers_, [s](const std::weak_ptr<Subscriber>& w) {
      auto p = w.lock();
      return !p || p.get() == s;
    });
    groups = groups_;
  }
  for (auto& g : groups) {
    if (!g->home->get_executor().running_in_this_thread()) continue;
    auto it = std::find_if(g->list.begin(), g->list.end(),
                           [s](const Entry& e) { return !e.gone && e.subscriber.get() == s; });
    if (it == g->list.end()) continue;
    --g->count;
    if (g->walking) {
      // A fan-out task is walking this list (the session left from inside
      // a delivery): mark it, removed when the walk ends.
      it->gone = true;
      g->holes = true;
    } else {
      *it = std::move(g->list.back());
      g->list.pop_back();
    }
    break;
  }
}

std::size_t Channel::subscribers() const {
  std::lock_guard lock(mutex_);
  std::size_t n = subscribers_.size();
  for (const auto& g : groups_) n += g->count.load();
  return n;
}

const char* feed_state_name(FeedState s) {
  switch (s) {
    case FeedState::Starting: return "starting";
    case FeedState::Live: return "live";
    case FeedState::Lost: return "lost";
    case FeedState::Ended: return "ended";
  }
  return "unknown";
}

template <class F>
void Channel::for_each_at_home(const std::shared_ptr<Group>& g, F f) {
  boost::asio::post(*g->home, [g, f] {
    // Copied first: each call may end a session, which leaves the list.
    std::vector<std::shared_ptr<Subscriber>> targets;
    for (const Entry& e : g->list)
      if (!e.gone) targets.push_back(e.subscriber);
    for (const auto& t : targets) f(*t);
  });
}

void Channel::shutdown_subscribers() {
  std::vector<std::shared_ptr<Subscriber>> targets;
  std::vector<std::shared_ptr<Group>> groups;
  {
    std::lock_guard lock(mutex_);
    for (auto& w : subscribers_)
      if (auto p = w.lock()) targets.push_back(std::move(p));
    groups = groups_;
  }
  for (auto& t : targets) t->shutdown();
  for (auto& g : groups) for_each_at_home(g, [](Subscriber& t) { t.shutdown(); });
}

void Channel::close_subscribers(std::uint16_t code, const std::string& reason) {
  Audience a;
  {
    std::lock_guard lock(mutex_);
    a = audience_locked();
  }
  for (auto& t : a.targets) t->close(code, reason);
  for (auto& g : a.groups) for_each_at_home(g, [code, reason](Subscriber& t) { t.close(code, reason); });
}

Channel::Audience Channel::audience_locked() {
  Audience a;
  a.targets.reserve(subscribers_.size());
  for (auto& w : subscribers_)
    if (auto p = w.lock()) a.targets.push_back(std::move(p));
  a.groups = groups_;
  return a;
}

void Channel::send(Audience& a, const Message& m) {
  // Home threads get one task per message for all their subscribers.
  for (auto& g : a.groups) {
    if (g->count.load() == 0) continue;
    // The home first: the lambda's move of `g` may be evaluated before
    // post()'s first argument (unspecified order; GCC does), leaving `g` null.
    auto& home = *g->home;
    boost::asio::post(home, [g = std::move(g), m] {
      g->walking = true;
      // By index, re-reading the size: a delivery may add to the list.
      for (std::size_t i = 0; i < g->list.size(); ++i) {
        const Entry& e = g->list[i];
        if (e.gone || m.serial <= e.after) continue;
        Subscriber* target = e.subscriber.get();  // `e` may move if the list grows meanwhile
        target->deliver_here(m);
      }
      g->walking = false;
      if (g->holes) {
        std::erase_if(g->list, [](const Entry& e) { return e.gone; });
        g->holes = false;
      }
    });
  }
  for (auto& t : a.targets) t->deliver(m);
}

}  // namespace mc::relay

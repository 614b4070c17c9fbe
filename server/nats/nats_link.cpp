#include "server/nats/nats_link.hpp"

#include <nats/nats.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>

namespace mc::nats {
namespace {

std::string status_text(natsStatus s) {
  std::string text = natsStatus_GetText(s);
  natsStatus last = NATS_OK;
  const char* detail = nats_GetLastError(&last);
  if (detail && *detail) text += std::string(": ") + detail;
  return text;
}

constexpr auto kCloseWait = std::chrono::seconds(3);
// Both requests of a snapshot read together (last_message).
constexpr auto kFetchBudget = std::chrono::milliseconds(500);

}  // namespace

struct NatsLink::Sub {
  std::string subject;
  Handler handler;
  natsSubscription* sub = nullptr;
  std::mutex mutex;
  std::condition_variable cv;
  bool complete = false;

  static void on_message(natsConnection*, natsSubscription*, natsMsg* msg, void* closure) {
    auto* self = static_cast<Sub*>(closure);
    self->handler(natsMsg_GetSubject(msg),
                  std::string_view(natsMsg_GetData(msg), static_cast<std::size_t>(natsMsg_GetDataLength(msg))));
    natsMsg_Destroy(msg);
  }
  static void on_complete(void* closure) {
    auto* self = static_cast<Sub*>(closure);
    std::lock_guard lock(self->mutex);
    self->complete = true;
    self->cv.notify_all();
  }
};

NatsLink::NatsLink(Events events) : events_(std::move(events)) {}

std::unique_ptr<NatsLink> NatsLink::open(const NatsConfig& config, const std::string& name, Events events,
                                         bool buffer_while_reconnecting, std::string& error) {
  std::unique_ptr<NatsLink> link(new NatsLink(std::move(events)));
  natsOptions* opts = nullptr;
  natsStatus s = natsOptions_Create(&opts);
  // One URL per server: libnats 3.4 mis-reads credentials in a
  // comma-separated URL list, an array of URLs it reads right.
  std::vector<std::string> urls;
  for (std::size_t pos = 0; pos <= config.url.size();) {
    auto comma = config.url.find(',', pos);
    if (comma == std::string::npos) comma = config.url.size();
    std::string one = config.url.substr(pos, comma - pos);
    one.erase(0, one.find_first_not_of(' '));
    one.erase(one.find_last_not_of(' ') + 1);
    if (!one.empty()) urls.push_back(one);
    pos = comma + 1;
  }
  std::vector<const char*> url_ptrs;
  for (const auto& u : urls) url_ptrs.push_back(u.c_str());
  if (urls.empty()) s = NATS_INVALID_ARG;
  if (s == NATS_OK) s = natsOptions_SetServers(opts, url_ptrs.data(), static_cast<int>(url_ptrs.size()));
  // The name /connz shows for this connection: which process on which host.
  char host[256] = "";
  ::gethostname(host, sizeof host - 1);
  const std::string full_name = name + " on " + host + ", pid " + std::to_string(::getpid());
  if (s == NATS_OK) s = natsOptions_SetName(opts, full_name.c_str());
  // The servers in the order given when asked (an edge pinned to its
  // nearest node); by default at random, which spreads edges over nodes.
  if (s == NATS_OK && !config.randomize_servers) s = natsOptions_SetNoRandomize(opts, true);
  // Forever, at a steady pace: a NATS node that comes back is found again.
  if (s == NATS_OK) s = natsOptions_SetMaxReconnect(opts, -1);
  if (s == NATS_OK) s = natsOptions_SetReconnectWait(opts, config.reconnect_wait.count());
  if (s == NATS_OK) s = natsOptions_SetRetryOnFailedConnect(opts, true, &NatsLink::on_connected, link.get());
  if (s == NATS_OK) s = natsOptions_SetReconnectedCB(opts, &NatsLink::on_connected, link.get());
  if (s == NATS_OK) s = natsOptions_SetDisconnectedCB(opts, &NatsLink::on_disconnected, link.get());
  if (s == NATS_OK) s = natsOptions_SetClosedCB(opts, &NatsLink::on_closed, link.get());
  // A node that hangs, or a machine that vanishes without closing its
  // sockets, is noticed when two pings a second apart go unanswered: in 2
  // to 3 s (the client's defaults, 2 min x 2, would leave spectators
  // without a picture for minutes). Measured in cluster_failover_test.
  if (s == NATS_OK) s = natsOptions_SetPingInterval(opts, 1000);
  if (s == NATS_OK) s = natsOptions_SetMaxPingsOut(opts, 2);
  if (s == NATS_OK && !buffer_while_reconnecting) s = natsOptions_SetReconnectBufSize(opts, 1);
  if (s != NATS_OK) {
    error = "NATS options: " + status_text(s);
    natsOptions_Destroy(opts);
    return nullptr;
  }
  s = natsConnection_Connect(&link->conn_, opts);
  natsOptions_Destroy(opts);
  if (s != NATS_OK && s != NATS_NOT_YET_CONNECTED) {
    error = "NATS connect to " + config.url + ": " + status_text(s);
    return nullptr;
  }
  s = natsConnection_JetStream(&link->js_, link->conn_, nullptr);
  if (s != NATS_OK) {
    error = "NATS JetStream context: " + status_text(s);
    return nullptr;
  }
  if (natsConnection_Status(link->conn_) == NATS_CONN_STATUS_CONNECTED) on_connected(link->conn_, link.get());
  return link;
}

NatsLink::~NatsLink() {
  for (auto& sub : subs_) {
    natsSubscription_Unsubscribe(sub->sub);
    std::unique_lock lock(sub->mutex);
    sub->cv.wait_for(lock, kCloseWait, [&] { return sub->complete; });
  }
  if (js_) jsCtx_Destroy(js_);
  if (conn_) {
    natsConnection_Close(conn_);
    {
      std::unique_lock lock(mutex_);
      closed_cv_.wait_for(lock, kCloseWait, [&] { return closed_; });
    }
    natsConnection_Destroy(conn_);
  }
  for (auto& sub : subs_) natsSubscription_Destroy(sub->sub);
}

void NatsLink::on_connected(natsConnection*, void* self) {
  auto* link = static_cast<NatsLink*>(self);
  link->connected_ = true;
  if (link->events_.connected) link->events_.connected();
}

void NatsLink::on_disconnected(natsConnection*, void* self) {
  auto* link = static_cast<NatsLink*>(self);
  link->connected_ = false;
  if (link->events_.disconnected) link->events_.disconnected();
}

void NatsLink::on_closed(natsConnection*, void* self) {
  auto* link = static_cast<NatsLink*>(self);
  link->connected_ = false;
  std::lock_guard lock(link->mutex_);
  link->closed_ = true;
  link->closed_cv_.notify_all();
}

bool NatsLink::publish(const std::string& subject, std::string_view data) {
  if (!connected_) return false;
  return natsConnection_Publish(conn_, subject.c_str(), data.data(), static_cast<int>(data.size())) == NATS_OK;
}

bool NatsLink::subscribe(const std::string& subject, Handler handler, std::string& error) {
  auto sub = std::make_unique<Sub>();
  sub->subject = subject;
  sub->handler = std::move(handler);
  natsStatus s = natsConnection_Subscribe(&sub->sub, conn_, subject.c_str(), &Sub::on_message, sub.get());
  if (s == NATS_OK) s = natsSubscription_SetOnCompleteCB(sub->sub, &Sub::on_complete, sub.get());
  if (s != NATS_OK) {
    error = "NATS subscribe " + subject + ": " + status_text(s);
    if (sub->sub) natsSubscription_Destroy(sub->sub);
    return false;
  }
  std::lock_guard lock(mutex_);
  subs_.push_back(std::move(sub));
  return true;
}

bool NatsLink::unsubscribe(const std::string& subject) {
  std::unique_ptr<Sub> sub;
  {
    std::lock_guard lock(mutex_);
    auto it = std::find_if(subs_.begin(), subs_.end(), [&](const auto& s) { return s->subject == subject; });
    if (it == subs_.end()) return false;
    sub = std::move(*it);
    subs_.erase(it);
  }
  natsSubscription_Unsubscribe(sub->sub);
  {
    std::unique_lock lock(sub->mutex);
    sub->cv.wait_for(lock, kCloseWait, [&] { return sub->complete; });
  }
  natsSubscription_Destroy(sub->sub);
  return true;
}

NatsLink::Counters NatsLink::counters() const {
  Counters c;
  natsStatistics* stats = nullptr;
  if (natsStatistics_Create(&stats) != NATS_OK) return c;
  if (natsConnection_GetStats(conn_, stats) == NATS_OK) {
    uint64_t in_msgs = 0, in_bytes = 0, out_msgs = 0, out_bytes = 0, reconnects = 0;
    natsStatistics_GetCounts(stats, &in_msgs, &in_bytes, &out_msgs, &out_bytes, &reconnects);
    c = {in_msgs, in_bytes, reconnects};
  }
  natsStatistics_Destroy(stats);
  return c;
}

bool NatsLink::ensure_last_per_subject_stream(const std::string& stream, const std::string& subjects, int replicas,
                                              std::string& error) {
  jsStreamConfig cfg;
  jsStreamConfig_Init(&cfg);
  const char* subject_list[] = {subjects.c_str()};
  cfg.Name = stream.c_str();
  cfg.Subjects = subject_list;
  cfg.SubjectsLen = 1;
  cfg.MaxMsgsPerSubject = 1;  // the latest keyframe of each game, nothing older
  cfg.Storage = js_FileStorage;
  cfg.Replicas = replicas;
  // Edges read the snapshots by direct get (last_message).
  cfg.AllowDirect = true;
  jsOptions o;
  jsOptions_Init(&o);
  o.Wait = 3000;
  jsErrCode jerr = static_cast<jsErrCode>(0);
  natsStatus s = js_AddStream(nullptr, js_, &cfg, &o, &jerr);
  if (s != NATS_OK && jerr == JSStreamNameExistErr) s = js_UpdateStream(nullptr, js_, &cfg, &o, &jerr);
  if (s != NATS_OK) {
    error = "JetStream stream " + stream + ": " + status_text(s) +
            (jerr ? " (JetStream error " + std::to_string(static_cast<int>(jerr)) + ")" : "");
    return false;
  }
  return true;
}

NatsLink::Fetch NatsLink::last_message(const std::string& stream, const std::string& subject, std::string& out,
                                       std::string& error) {
  // Live messages wait while the snapshot is read: give up soon. A healthy
  // cluster answers in milliseconds; one electing a leader may not answer
  // at all, and the next live keyframe (at most 1 s away) serves instead.
  const auto deadline = std::chrono::steady_clock::now() + kFetchBudget;
  jsOptions o;
  jsOptions_Init(&o);
  o.Wait = kFetchBudget.count();
  // STREAM.INFO first. nats-server 2.9 lists a stream under creation
  // before its store exists, and a STREAM.MSG.GET that reaches it then
  // dereferences the missing store and kills the server (jsMsgGetRequest,
  // jetstream_api.go:3028 in 2.9.10). STREAM.INFO is safe in that window
  // and reports no message: a stream that reports one has its store.
  jsErrCode jerr = static_cast<jsErrCode>(0);
  jsStreamInfo* info = nullptr;
  natsStatus s = js_GetStreamInfo(&info, js_, stream.c_str(), &o, &jerr);
  if (s != NATS_OK) {
    if (s == NATS_NOT_FOUND || jerr == JSStreamNotFoundErr) return Fetch::NotFound;
    error = "JetStream stream info " + stream + ": " + status_text(s);
    return Fetch::Failed;
  }
  const bool stored = info->State.LastSeq > 0;
  const bool direct = info->Config && info->Config->AllowDirect;
  jsStreamInfo_Destroy(info);
  if (!stored) return Fetch::NotFound;
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
  o.Wait = std::max<std::int64_t>(100, left.count());
  // A direct get is answered by the stream itself, which subscribes only
  // once its store exists (on a cluster: on whichever replica is current),
  // so it cannot reach a half-made stream at all. Streams made before
  // allow_direct get the message-get, which the check above makes safe.
  natsMsg* msg = nullptr;
  jerr = static_cast<jsErrCode>(0);
  if (direct) {
    jsDirectGetMsgOptions d;
    jsDirectGetMsgOptions_Init(&d);
    d.LastBySubject = subject.c_str();
    s = js_DirectGetMsg(&msg, js_, stream.c_str(), &o, &d);
  } else {
    s = js_GetLastMsg(&msg, js_, stream.c_str(), subject.c_str(), &o, &jerr);
  }
  if (s == NATS_OK) {
    out.assign(natsMsg_GetData(msg), static_cast<std::size_t>(natsMsg_GetDataLength(msg)));
    natsMsg_Destroy(msg);
    return Fetch::Found;
  }
  if (s == NATS_NOT_FOUND || jerr == JSNoMessageFoundErr || jerr == JSStreamNotFoundErr) return Fetch::NotFound;
  error = "JetStream get " + subject + ": " + status_text(s);
  return Fetch::Failed;
}

}  // namespace mc::nats

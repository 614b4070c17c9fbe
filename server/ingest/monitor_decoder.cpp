#include "server/ingest/monitor_decoder.hpp"

#include "server/ingest/binary_records.hpp"
#include "server/ingest/text_show.hpp"

namespace mc::ingest {
namespace {
bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }
}  // namespace

MonitorDecoder::Kind MonitorDecoder::decode(std::string_view d, WorldState& out, MessageRecord& msg,
                                            std::string& error) {
  if (d.size() > kMaxDatagram) {
    error = "oversized datagram (" + std::to_string(d.size()) + " bytes)";
    return Kind::Error;
  }
  // Text and JSON datagrams end in NUL; binary ones are fixed-size.
  std::string_view t = d;
  while (!t.empty() && (t.back() == '\0' || t.back() == '\n')) t.remove_suffix(1);
  if (!t.empty() && t.front() == '(') return decode_text(t, out, msg, error);
  if (!t.empty() && t.front() == '{') {
    RecordKind kind{};
    if (!decode_json_record(t, ctx_, out, msg, kind, error)) return Kind::Error;
    switch (kind) {
      case RecordKind::Show: return Kind::Show;
      case RecordKind::Msg: return Kind::Message;
      case RecordKind::ServerParam:
      case RecordKind::PlayerParam:
      case RecordKind::PlayerType: return Kind::Params;
      default: return Kind::Ignored;
    }
  }
  return decode_binary(d, out, msg, error);
}

MonitorDecoder::Kind MonitorDecoder::decode_text(std::string_view t, WorldState& out,
                                                 MessageRecord& msg, std::string& error) {
  if (starts_with(t, "(show ")) {
    ShowExtras extras;
    if (!parse_text_show(t, out, extras, error)) return Kind::Error;
    if (extras.has_play_mode) ctx_.play_mode = out.play_mode;
    if (extras.has_team) {
      ctx_.left = out.left;
      ctx_.right = out.right;
    }
    out.play_mode = ctx_.play_mode;
    out.left = ctx_.left;
    out.right = ctx_.right;
    return Kind::Show;
  }
  if (starts_with(t, "(msg ")) return parse_msg_record(t, msg, error) ? Kind::Message : Kind::Error;
  if (starts_with(t, "(server_param "))
    return parse_param_record(t, "server_param", ctx_.params.server, error) ? Kind::Params : Kind::Error;
  if (starts_with(t, "(player_param "))
    return parse_param_record(t, "player_param", ctx_.params.player, error) ? Kind::Params : Kind::Error;
  if (starts_with(t, "(player_type "))
    return parse_player_type_record(t, ctx_.params, error) ? Kind::Params : Kind::Error;
  // Older servers also sent these to monitors.
  if (starts_with(t, "(playmode ")) {
    int time = 0;
    PlayMode pm{};
    if (!parse_playmode_record(t, time, pm, error)) return Kind::Error;
    ctx_.play_mode = pm;
    return Kind::Ignored;
  }
  if (starts_with(t, "(team ")) {
    int time = 0;
    return parse_team_record(t, time, ctx_.left, ctx_.right, error) ? Kind::Ignored : Kind::Error;
  }
  if (starts_with(t, "(ok ") || starts_with(t, "(error ") || starts_with(t, "(warning ")) {
    msg = MessageRecord{};
    msg.text.assign(t);
    return Kind::Reply;
  }
  error = "unknown text datagram";
  return Kind::Error;
}

MonitorDecoder::Kind MonitorDecoder::decode_binary(std::string_view d, WorldState& out,
                                                   MessageRecord& msg, std::string& error) {
  using namespace binary;
  if (d.size() != kDispInfoSize && d.size() != kDispInfo2Size) {
    error.assign("unrecognised datagram of ").append(std::to_string(d.size())).append(" bytes");
    return Kind::Error;
  }
  const bool v2 = d.size() == kDispInfo2Size;
  const std::int16_t mode = be16(d.data());
  // dispinfo_t: union at 2; dispinfo_t2: 2 bytes of padding, union at 4.
  const std::string_view body = d.substr(v2 ? 4 : 2);
  switch (mode) {
    case kShow: {
      const bool ok = v2 ? decode_showinfo2(body, out) : decode_showinfo_v1(body, out);
      if (!ok) break;
      if (!v2)
        for (int i = 0; i < kMaxPlayers; ++i)
          out.players[static_cast<std::size_t>(i)].type = v1_types_[static_cast<std::size_t>(i)];
      ctx_.play_mode = out.play_mode;
      ctx_.left = out.left;
      ctx_.right = out.right;
      return Kind::Show;
    }
    case kMsg:
      msg = MessageRecord{};
      if (!decode_msginfo(body, msg.board, msg.text)) break;
      msg.time = -1;  // binary messages carry no time
      if (!v2) apply_change_player_type(msg.text, v1_types_);
      return Kind::Message;
    case kPlayerType: {
      PlayerType t;
      if (v2 && decode_player_type(body, t) && store_player_type(ctx_.params, t)) return Kind::Params;
      break;
    }
    case kParam:
      if (v2 && decode_server_params(body, ctx_.params.server)) return Kind::Params;
      break;
    case kPlayerParam:
      if (v2) return Kind::Params;  // nothing a viewer needs
      break;
    case kDraw:
    case kBlank:
    case kNoInfo:
      return Kind::Ignored;
    default:
      break;
  }
  error.assign("bad binary record (mode ").append(std::to_string(mode)).append(")");
  return Kind::Error;
}

}  // namespace mc::ingest

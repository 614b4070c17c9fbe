#include "server/nats/subjects.hpp"

#include <cctype>

namespace mc::nats {

bool valid_game(std::string_view game) {
  if (game.empty() || game.size() > 64) return false;
  for (char c : game)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') return false;
  return true;
}

bool valid_prefix(std::string_view prefix) {
  if (prefix.empty() || prefix.size() > 128) return false;
  std::size_t pos = 0;
  for (;;) {
    const auto dot = prefix.find('.', pos);
    if (!valid_game(prefix.substr(pos, dot == std::string_view::npos ? dot : dot - pos))) return false;
    if (dot == std::string_view::npos) return true;
    pos = dot + 1;
  }
}

std::string live_subject(std::string_view prefix, std::string_view game) {
  return std::string(prefix) + "." + std::string(game) + ".live";
}
std::string key_subject(std::string_view prefix, std::string_view game) {
  return std::string(prefix) + "." + std::string(game) + ".key";
}
std::string live_wildcard(std::string_view prefix) { return std::string(prefix) + ".*.live"; }
std::string key_wildcard(std::string_view prefix) { return std::string(prefix) + ".*.key"; }

std::string stream_name(std::string_view prefix) {
  std::string s;
  for (char c : prefix)
    s.push_back(c == '.' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  return s + "_KEY";
}

std::string game_of_live_subject(std::string_view prefix, std::string_view subject) {
  constexpr std::string_view suffix = ".live";
  if (subject.size() <= prefix.size() + 1 + suffix.size()) return {};
  if (subject.substr(0, prefix.size()) != prefix || subject[prefix.size()] != '.') return {};
  if (subject.substr(subject.size() - suffix.size()) != suffix) return {};
  const auto game = subject.substr(prefix.size() + 1, subject.size() - prefix.size() - 1 - suffix.size());
  return valid_game(game) ? std::string(game) : std::string();
}

}  // namespace mc::nats

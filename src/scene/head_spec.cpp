#include "scene/head_spec.hpp"

#include <array>
#include <charconv>

#include "scene/number_text.hpp"

namespace conescan::scene {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

struct key {
  const char* name;
  double head_config::*field;
};

constexpr std::array<key, 7> keys{{{"alpha", &head_config::alpha_deg},
                                   {"beta", &head_config::beta_deg},
                                   {"gamma", &head_config::gamma_deg},
                                   {"sigma", &head_config::sigma_deg},
                                   {"phase", &head_config::phase_deg},
                                   {"noise", &head_config::noise_deg},
                                   {"lsb", &head_config::lsb_deg}}};

constexpr const char* allowed_keys = "alpha, beta, gamma, sigma, phase, noise, lsb (degrees)";

// Appends the pieces. (Also sidesteps g++ 12's false -Wrestrict on "literal" + std::string.)
template <class... Pieces>
std::string concat(const Pieces&... pieces) {
  std::string out;
  (out.append(pieces), ...);
  return out;
}

}  // namespace

bool is_head_key(std::string_view name) {
  for (const key& k : keys)
    if (name == k.name) return true;
  return false;
}

const char* head_keys_text() {
  return allowed_keys;
}

std::variant<head_config, std::string> parse_head_spec(std::string_view spec) {
  head_config head;
  std::array<bool, keys.size()> seen{};
  if (trim(spec).empty()) return concat("empty head: give key=value pairs among ", allowed_keys);
  while (true) {
    const std::size_t comma = spec.find(',');
    const std::string_view item = trim(spec.substr(0, comma));
    const std::size_t equals = item.find('=');
    if (equals == std::string_view::npos)
      return concat("'", item, "' is not key=value; keys: ", allowed_keys);
    const std::string_view name = trim(item.substr(0, equals));
    const std::string_view text = trim(item.substr(equals + 1));
    std::size_t k = 0;
    while (k < keys.size() && name != keys[k].name) ++k;
    if (k == keys.size()) return concat("unknown head key '", name, "'; keys: ", allowed_keys);
    if (seen[k]) return concat("head key '", name, "' given twice");
    seen[k] = true;
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size())
      return concat("head key '", name, "' has '", text, "', not a number in degrees");
    head.*keys[k].field = value;
    if (comma == std::string_view::npos) break;
    spec.remove_prefix(comma + 1);
  }
  return head;
}

std::string format_head_spec(const head_config& head) {
  std::string out;
  for (const key& k : keys) {
    if (!out.empty()) out += ',';
    out += k.name;
    out += '=';
    out += shortest_text(head.*k.field);
  }
  return out;
}

}  // namespace conescan::scene

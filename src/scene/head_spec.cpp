#include "scene/head_spec.hpp"

#include <array>

#include "text/number_text.hpp"

namespace conescan::scene {

namespace {

struct key {
  const char* name;
  double head_config::*field;
};

constexpr std::array<key, 10> keys{{{"alpha", &head_config::alpha_deg},
                                    {"beta", &head_config::beta_deg},
                                    {"gamma", &head_config::gamma_deg},
                                    {"sigma", &head_config::sigma_deg},
                                    {"phase", &head_config::phase_deg},
                                    {"noise", &head_config::noise_deg},
                                    {"lsb", &head_config::lsb_deg},
                                    {"dgamma", &head_config::dgamma_deg},
                                    {"bias-in", &head_config::bias_in_deg},
                                    {"bias-out", &head_config::bias_out_deg}}};
constexpr std::size_t gamma_key = 2, sigma_key = 3;

constexpr const char* allowed_keys =
    "alpha, beta, gamma, sigma, phase, noise, lsb, dgamma, bias-in, bias-out (degrees)";

// Appends the pieces. (Also sidesteps g++ 12's false -Wrestrict on "literal" + std::string.)
template <class... Pieces>
std::string concat(const Pieces&... pieces) {
  std::string out;
  (out.append(pieces), ...);
  return out;
}

std::size_t key_index(std::string_view name) {
  std::size_t k = 0;
  while (k < keys.size() && name != keys[k].name) ++k;
  return k;
}

}  // namespace

bool is_head_key(std::string_view name) {
  return key_index(name) < keys.size();
}

double* head_key_field(head_config& head, std::string_view key) {
  const std::size_t k = key_index(key);
  return k < keys.size() ? &(head.*keys[k].field) : nullptr;
}

const char* head_keys_text() {
  return allowed_keys;
}

checked<head_config> parse_head_spec(std::string_view spec) {
  head_config head;
  std::array<bool, keys.size()> seen{};
  if (text::trim_blanks(spec).empty())
    return diagnostic::saying(concat("empty head: give key=value pairs among ", allowed_keys));
  while (true) {
    const std::size_t comma = spec.find(',');
    const std::string_view item = text::trim_blanks(spec.substr(0, comma));
    const std::size_t equals = item.find('=');
    if (equals == std::string_view::npos)
      return diagnostic::saying(concat(quote(item), " is not key=value; keys: ", allowed_keys));
    const std::string_view name = text::trim_blanks(item.substr(0, equals));
    const std::size_t k = key_index(name);
    if (k == keys.size())
      return diagnostic::saying(concat("unknown head key ", quote(name), "; keys: ", allowed_keys));
    if (seen[k]) return diagnostic::saying(concat("head key '", name, "' given twice"));
    seen[k] = true;
    const checked<double> value = text::parse_real(text::trim_blanks(item.substr(equals + 1)));
    if (!value.ok())
      return diagnostic::saying(concat("head key '", name, "': ", value.error().message));
    head.*keys[k].field = value.value();
    if (comma == std::string_view::npos) break;
    spec.remove_prefix(comma + 1);
  }
  // validate() would blame sigma, which the user did not type: name gamma.
  if (seen[gamma_key] && !seen[sigma_key] && !(head.sigma_deg < head.gamma_deg))
    return diagnostic::saying(concat(
        "gamma = ", text::shortest_text(head.gamma_deg),
        " is not above the default misalignment sigma = ", text::shortest_text(head.sigma_deg),
        " deg: give sigma= below gamma"));
  return head;
}

std::string format_head_spec(const head_config& head) {
  std::string out;
  for (const key& k : keys) {
    if (!out.empty()) out += ',';
    out += k.name;
    out += '=';
    out += text::shortest_text(head.*k.field);
  }
  return out;
}

}  // namespace conescan::scene

#include "scene/head_spec.hpp"

#include <array>
#include <span>

#include "text/number_text.hpp"

namespace conescan::scene {

namespace {

// A head key: a number (`field`), or one of `words` (set and get by the word's index). The
// keys after the first ten (MODEL §12's physics) are written only when they differ from the
// default head's, so scenes without them print as before.
struct key {
  const char* name;
  double head_config::*field = nullptr;
  std::span<const std::string_view> words = {};
  void (*set_word)(head_config&, std::size_t) = nullptr;
  std::size_t (*get_word)(const head_config&) = nullptr;
  bool always_printed = false;
};

constexpr std::array<std::string_view, 2> shape_words{"square", "circle"};
constexpr std::array<std::string_view, 3> locator_words{"normalised", "fixed", "slope"};

constexpr std::array<key, 16> keys{{
    {.name = "alpha", .field = &head_config::alpha_deg, .always_printed = true},
    {.name = "beta", .field = &head_config::beta_deg, .always_printed = true},
    {.name = "gamma", .field = &head_config::gamma_deg, .always_printed = true},
    {.name = "sigma", .field = &head_config::sigma_deg, .always_printed = true},
    {.name = "phase", .field = &head_config::phase_deg, .always_printed = true},
    {.name = "noise", .field = &head_config::noise_deg, .always_printed = true},
    {.name = "lsb", .field = &head_config::lsb_deg, .always_printed = true},
    {.name = "dgamma", .field = &head_config::dgamma_deg, .always_printed = true},
    {.name = "bias-in", .field = &head_config::bias_in_deg, .always_printed = true},
    {.name = "bias-out", .field = &head_config::bias_out_deg, .always_printed = true},
    {.name = "fov", .field = &head_config::fov_deg},
    {.name = "fov-shape",
     .words = shape_words,
     .set_word = [](head_config& h, std::size_t k) { h.shape = fov_shape(k); },
     .get_word = [](const head_config& h) { return static_cast<std::size_t>(h.shape); }},
    {.name = "spin-hz", .field = &head_config::spin_hz},
    {.name = "tau-ms", .field = &head_config::tau_ms},
    {.name = "locator",
     .words = locator_words,
     .set_word = [](head_config& h, std::size_t k) { h.locator = horizon_locator_choice(k); },
     .get_word = [](const head_config& h) { return static_cast<std::size_t>(h.locator); }},
    {.name = "threshold", .field = &head_config::threshold},
}};
constexpr std::size_t gamma_key = 2, sigma_key = 3;

constexpr const char* allowed_keys =
    "alpha, beta, gamma, sigma, phase, noise, lsb, dgamma, bias-in, bias-out (degrees), fov "
    "(degrees), fov-shape (square | circle), spin-hz (rev/s), tau-ms (ms), locator (normalised | "
    "fixed | slope), threshold";

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

std::string words_text(const key& k) {
  std::string words;
  for (std::string_view w : k.words) words += (words.empty() ? "" : ", ") + std::string(w);
  return words;
}

// Reads `text` into key k of `head`; the error holds the message after the key's name.
checked<void> read_key(const key& k, std::string_view text, head_config& head) {
  if (k.field) {
    const checked<double> value = text::parse_real(text);
    if (!value.ok()) return value.error();
    head.*k.field = value.value();
    return success();
  }
  for (std::size_t w = 0; w < k.words.size(); ++w)
    if (text == k.words[w]) {
      k.set_word(head, w);
      return success();
    }
  return diagnostic::saying(concat(quote(text), " is not one of: ", words_text(k)));
}

}  // namespace

bool is_head_key(std::string_view name) {
  return key_index(name) < keys.size();
}

bool is_head_word_key(std::string_view name) {
  const std::size_t k = key_index(name);
  return k < keys.size() && !keys[k].field;
}

double* head_key_field(head_config& head, std::string_view key) {
  const std::size_t k = key_index(key);
  return k < keys.size() && keys[k].field ? &(head.*keys[k].field) : nullptr;
}

std::vector<std::string_view> head_number_keys() {
  std::vector<std::string_view> names;
  for (const key& k : keys)
    if (k.field) names.emplace_back(k.name);
  return names;
}

const char* head_keys_text() {
  return allowed_keys;
}

checked<void> check_head_value(std::string_view name, std::string_view text) {
  const std::size_t k = key_index(name);
  if (k == keys.size())
    return diagnostic::saying(concat("unknown head key ", quote(name), "; keys: ", allowed_keys));
  head_config scratch;
  return read_key(keys[k], text, scratch);
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
    const checked<void> value = read_key(keys[k], text::trim_blanks(item.substr(equals + 1)), head);
    if (!value.ok())
      return diagnostic::saying(concat("head key '", name, "': ", value.error().message));
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
  static const head_config defaults;
  std::string out;
  for (const key& k : keys) {
    const bool number = k.field != nullptr;
    const bool at_default =
        number ? head.*k.field == defaults.*k.field : k.get_word(head) == k.get_word(defaults);
    if (!k.always_printed && at_default) continue;
    if (!out.empty()) out += ',';
    out += k.name;
    out += '=';
    out += number ? text::shortest_text(head.*k.field) : std::string(k.words[k.get_word(head)]);
  }
  return out;
}

}  // namespace conescan::scene

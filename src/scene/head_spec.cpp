#include "scene/head_spec.hpp"

#include <array>
#include <span>
#include <vector>

#include "conescan/enum_names.hpp"
#include "text/number_text.hpp"

namespace conescan::scene {

namespace {

// The core's enums a word key sets (MODEL §12), with their words.
constexpr enum_names<field_shape, 2> field_shape_names{
    {{field_shape::square, "square"}, {field_shape::circle, "circle"}}};
constexpr enum_names<locator_kind, 3> locator_kind_names{{{locator_kind::normalised, "normalised"},
                                                          {locator_kind::fixed, "fixed"},
                                                          {locator_kind::slope, "slope"}}};
static_assert(in_enum_order(field_shape_names) && in_enum_order(locator_kind_names));

// A word key's reading and writing, from the head's field and its enum's name table.
template <auto Field, const auto& Names>
constexpr head_key_words words_of() {
  return {[](head_config& head, std::string_view word) {
            const auto* value = value_named(Names, word);
            if (value) head.*Field = *value;
            return value != nullptr;
          },
          [](const head_config& head) { return name_of(Names, head.*Field, "?"); },
          [](std::string_view separator) {
            std::string out;
            for (const auto& n : Names) out.append(out.empty() ? "" : separator).append(n.name);
            return out;
          }};
}

using G = head_key_group;
using S = physics_step;

// A key whose value is a number in `unit`, and one whose value is a word of a core enum (a
// physics key: MODEL §12's enums); `help` is what --head's help says of it beyond its name.
constexpr head_key number(const char* name, G group, const char* unit, double head_config::*field,
                          const char* help = nullptr, S step = S::none) {
  return {name, group, step, unit, field, {}, help};
}
constexpr head_key word(const char* name, S step, head_key_words words) {
  return {name, G::physics, step, "", nullptr, words, nullptr};
}

// The keys after the first ten (MODEL §12's physics) are written only when they differ from the
// default head's, so scenes without them print as before.
constexpr std::array<head_key, 16> keys{{
    number("alpha", G::mounting, "deg", &head_config::alpha_deg),
    number("beta", G::mounting, "deg", &head_config::beta_deg),
    number("gamma", G::mounting, "deg", &head_config::gamma_deg),
    number("sigma", G::mounting, "deg", &head_config::sigma_deg),
    number("phase", G::mounting, "deg", &head_config::phase_deg),
    number("noise", G::errors, "deg", &head_config::noise_deg, "1 sigma per crossing, [0, 10]"),
    number("lsb", G::errors, "deg", &head_config::lsb_deg,
           "telemetry step of chord and phase: 0, or [1e-9, 10]"),
    number("dgamma", G::biases, "deg", &head_config::dgamma_deg, "true cone gamma + dgamma"),
    number("bias-in", G::biases, "deg", &head_config::bias_in_deg),
    number("bias-out", G::biases, "deg", &head_config::bias_out_deg,
           "added to each crossing, [-10, 10]"),
    number("fov", G::physics, "deg", &head_config::fov_deg,
           "full width, deg, default 0: a pencil beam", S::field),
    word("fov-shape", S::field, words_of<&head_config::shape, field_shape_names>()),
    number("spin-hz", G::physics, "rev/s", &head_config::spin_hz, "rev/s", S::detector),
    number("tau-ms", G::physics, "ms", &head_config::tau_ms,
           "detector time constant, needs spin-hz", S::detector),
    word("locator", S::locator, words_of<&head_config::locator, locator_kind_names>()),
    // The default locator and threshold (head_config's; a test holds them to it).
    number("threshold", G::physics, "", &head_config::threshold, "default normalised 0.5",
           S::locator),
}};

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

// "alpha, beta, ... bias-out (degrees), fov (degrees), fov-shape (square | circle), ...": outside
// the physics, a run of keys of one unit says it once; each physics key says its own.
std::string allowed_keys_text() {
  std::string out;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const head_key& key = keys[k];
    out.append(k == 0 ? "" : ", ").append(key.name);
    const bool run_ends = key.group == G::physics || k + 1 == keys.size() ||
                          std::string_view(keys[k + 1].unit) != key.unit ||
                          keys[k + 1].group == G::physics;
    const std::string_view unit = key.unit;
    if (!key.field)
      out.append(concat(" (", key.words.list(" | "), ")"));
    else if (run_ends && !unit.empty())
      out.append(concat(" (", unit == "deg" ? "degrees" : unit, ")"));
  }
  return out;
}

const std::string& allowed_keys() {
  static const std::string text = allowed_keys_text();
  return text;
}

// Reads `text` into key k of `head`; the error holds the message after the key's name.
checked<void> read_key(const head_key& k, std::string_view text, head_config& head) {
  if (k.field) {
    const checked<double> value = text::parse_real(text);
    if (!value.ok()) return value.error();
    head.*k.field = value.value();
    return success();
  }
  if (k.words.set(head, text)) return success();
  return diagnostic::saying(concat(quote(text), " is not one of: ", k.words.list(", ")));
}

// The mounting keys as --head's help shows them: "alpha=..,beta=..,...", or with the default
// head's values, "alpha=0,beta=90,...".
std::string mounting_text(bool values) {
  static const head_config defaults;
  std::string out;
  for (const head_key& k : keys)
    if (k.group == G::mounting)
      out.append(concat(out.empty() ? "" : ",", k.name, "=", values ? k.text(defaults) : ".."));
  return out;
}

// A group's keys as --head's help shows them: "noise=.. (help) and lsb=.. (help)", a word key
// with its words ("fov-shape=square|circle"), the last joined by "and".
std::string group_text(G group) {
  std::vector<std::string> items;
  for (const head_key& k : keys)
    if (k.group == group)
      items.push_back(concat(k.name, "=", k.field ? ".." : k.words.list("|"),
                             k.help ? concat(" (", k.help, ")") : ""));
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i)
    out.append(concat(i == 0 ? "" : i + 1 == items.size() ? " and " : ", ", items[i]));
  return out;
}

std::string head_help_text(bool fit) {
  const std::string lead = concat(
      fit ? "a sensor head of the telemetry, degrees: " : "a sensor head, degrees: ",
      mounting_text(false), " (repeatable, at most ", std::to_string(max_heads),
      "; replaces the default head ", mounting_text(true), "; keys left out keep those values)");
  if (fit)
    return concat(lead,
                  ", noise=.. (1 sigma per crossing, [0, 10]: the fit's weights) and lsb=.. "
                  "(telemetry step), dgamma=.., bias-in=.., bias-out=.. (the biases --free "
                  "estimates: their starting values); the sensor physics of the telemetry's "
                  "heads (MODEL §12, model scan): fov=.., fov-shape=.., spin-hz=.., locator=.. as "
                  "simulated, tau-ms=.. and threshold=.. (the starting values of hK.tau-ms and a "
                  "fixed locator's hK.threshold)");
  return concat(lead, ", and ", group_text(G::errors),
                ", default 0; fixed biases that conescan-fit estimates: ", group_text(G::biases),
                ", default 0; sensor physics (MODEL §12, model scan): ", group_text(G::physics));
}

}  // namespace

bool head_key::same(const head_config& head, const head_config& other) const {
  return field ? head.*field == other.*field
               : std::string_view(words.get(head)) == words.get(other);
}

void head_key::copy(head_config& head, const head_config& from) const {
  if (field)
    head.*field = from.*field;
  else
    words.set(head, words.get(from));
}

std::string head_key::text(const head_config& head) const {
  return field ? text::shortest_text(head.*field) : std::string(words.get(head));
}

std::span<const head_key> head_keys() {
  return keys;
}

const head_key* find_head_key(std::string_view name) {
  const std::size_t k = key_index(name);
  return k < keys.size() ? &keys[k] : nullptr;
}

void copy_physics_step(head_config& head, const head_config& from, physics_step step) {
  for (const head_key& k : keys)
    if (k.step == step) k.copy(head, from);
}

std::string_view head_help(bool fit) {
  static const std::string sim_help = head_help_text(false), fit_help = head_help_text(true);
  return fit ? fit_help : sim_help;
}

std::string physics_keys_text() {
  std::string out;
  for (const head_key& k : keys)
    if (k.group == G::physics) out.append(concat(out.empty() ? "" : ", ", k.name, "="));
  return out;
}

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
  for (const head_key& k : keys)
    if (k.field) names.emplace_back(k.name);
  return names;
}

const char* head_keys_text() {
  return allowed_keys().c_str();
}

checked<void> check_head_value(std::string_view name, std::string_view text) {
  const std::size_t k = key_index(name);
  if (k == keys.size())
    return diagnostic::saying(concat("unknown head key ", quote(name), "; keys: ", allowed_keys()));
  head_config scratch;
  return read_key(keys[k], text, scratch);
}

namespace {

// One comma-separated item of a head spec, blanks trimmed: its text, the key before '=' and the
// value after it (equals false where there is no '=').
struct head_item {
  std::string_view text, name, value;
  bool equals;
};

// The items of a spec in order: the one place a head spec is split.
std::vector<head_item> head_items(std::string_view spec) {
  std::vector<head_item> items;
  while (true) {
    const std::size_t comma = spec.find(',');
    const std::string_view item = text::trim_blanks(spec.substr(0, comma));
    const std::size_t equals = item.find('=');
    items.push_back({item, text::trim_blanks(item.substr(0, equals)),
                     equals == std::string_view::npos ? std::string_view()
                                                      : text::trim_blanks(item.substr(equals + 1)),
                     equals != std::string_view::npos});
    if (comma == std::string_view::npos) return items;
    spec.remove_prefix(comma + 1);
  }
}

}  // namespace

std::set<std::string> head_spec_keys(std::string_view spec) {
  std::set<std::string> names;
  for (const head_item& item : head_items(spec))
    if (!item.name.empty()) names.insert(std::string(item.name));
  return names;
}

checked<head_config> parse_head_spec(std::string_view spec) {
  head_config head;
  std::array<bool, keys.size()> seen{};
  if (text::trim_blanks(spec).empty())
    return diagnostic::saying(concat("empty head: give key=value pairs among ", allowed_keys()));
  for (const head_item& item : head_items(spec)) {
    if (!item.equals)
      return diagnostic::saying(
          concat(quote(item.text), " is not key=value; keys: ", allowed_keys()));
    const std::size_t k = key_index(item.name);
    if (k == keys.size())
      return diagnostic::saying(
          concat("unknown head key ", quote(item.name), "; keys: ", allowed_keys()));
    if (seen[k]) return diagnostic::saying(concat("head key '", item.name, "' given twice"));
    seen[k] = true;
    const checked<void> value = read_key(keys[k], item.value, head);
    if (!value.ok())
      return diagnostic::saying(concat("head key '", item.name, "': ", value.error().message));
  }
  // validate() would blame sigma, which the user did not type: name gamma.
  if (seen[key_index("gamma")] && !seen[key_index("sigma")] && !(head.sigma_deg < head.gamma_deg))
    return diagnostic::saying(concat(
        "gamma = ", text::shortest_text(head.gamma_deg),
        " is not above the default misalignment sigma = ", text::shortest_text(head.sigma_deg),
        " deg: give sigma= below gamma"));
  return head;
}

std::string format_head_spec(const head_config& head) {
  static const head_config defaults;
  std::string out;
  for (const head_key& k : keys) {
    if (k.group == G::physics && k.same(head, defaults)) continue;
    out.append(concat(out.empty() ? "" : ",", k.name, "=", k.text(head)));
  }
  return out;
}

}  // namespace conescan::scene

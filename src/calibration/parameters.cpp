#include "calibration/parameters.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "text/number_text.hpp"

namespace conescan::calibration {

std::string parameter_name(std::size_t index, std::size_t head_count) {
  if (index < head_parameter_count * head_count)
    return "h" + std::to_string(index / head_parameter_count + 1) + "." +
           std::string(head_parameter_specs[index % head_parameter_count].key);
  return std::string(earth_parameter_specs[index - head_parameter_count * head_count].key);
}

std::string_view parameter_unit(std::size_t index, std::size_t head_count) {
  if (index < head_parameter_count * head_count)
    return head_parameter_specs[index % head_parameter_count].unit;
  return earth_parameter_specs[index - head_parameter_count * head_count].unit;
}

bool is_physics_parameter(std::size_t index, std::size_t head_count) {
  if (index < head_parameter_count * head_count) {
    const auto p = static_cast<head_parameter>(index % head_parameter_count);
    return p == head_parameter::tau_ms || p == head_parameter::threshold;
  }
  const auto p = static_cast<earth_parameter>(index - head_parameter_count * head_count);
  return p == earth_parameter::radiance_offset || p == earth_parameter::radiance_scale;
}

bool physics_absent(std::size_t index, std::size_t head_count, double value) {
  return std::isnan(value) && is_physics_parameter(index, head_count);
}

parameter_set parameter_set::nominal(std::size_t head_count) {
  const std::size_t n = parameter_count(head_count);
  return {head_count, std::vector<double>(n, 0.0), std::vector<bool>(n, false),
          std::vector<double>(n, 0.0)};
}

bool parameter_set::any_free() const {
  return std::find(free.begin(), free.end(), true) != free.end();
}

std::string allowed_parameter_names(std::size_t head_count) {
  std::string out;
  for (const parameter_spec& spec : head_parameter_specs)
    out += "hK." + std::string(spec.key) + ", ";
  out += head_count == 0 ? std::string("(K a head number)")
                         : "(K = 1.." + std::to_string(head_count) + ")";
  for (const parameter_spec& spec : earth_parameter_specs) out += ", " + std::string(spec.key);
  return out;
}

namespace {

diagnostic unknown_name(std::string_view name) {
  return {"", "unknown parameter " + quote(name) + "; allowed: " + allowed_parameter_names(0)};
}

/// The head number of "hK." (1-based), or 0 when the digits are not a head number.
std::size_t head_number(std::string_view digits) {
  if (digits.empty() || digits.front() == '0') return 0;
  std::size_t number = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), number);
  return ec == std::errc() && end == digits.data() + digits.size() ? number : 0;
}

}  // namespace

checked<parsed_name> parse_parameter_name(std::string_view name) {
  for (std::size_t k = 0; k < earth_parameter_count; ++k)
    if (name == earth_parameter_specs[k].key)
      return parsed_name{false, 0, head_parameter::sigma, static_cast<earth_parameter>(k)};
  const std::size_t dot = name.find('.');
  if (name.size() < 2 || name.front() != 'h' || dot == std::string_view::npos)
    return unknown_name(name);
  const std::string_view key = name.substr(dot + 1);
  const auto spec = std::find_if(head_parameter_specs.begin(), head_parameter_specs.end(),
                                 [&](const parameter_spec& s) { return s.key == key; });
  if (spec == head_parameter_specs.end()) return unknown_name(name);
  const std::string_view digits = name.substr(1, dot - 1);
  if (digits == "0")
    return diagnostic{"", "heads are numbered from 1: " + quote(name) + " names head 0"};
  const std::size_t number = head_number(digits);
  if (number == 0) return unknown_name(name);
  return parsed_name{true, number - 1,
                     static_cast<head_parameter>(spec - head_parameter_specs.begin()),
                     earth_parameter::horizon};
}

namespace {

constexpr double max_segment_s = 1e12;

/// The segment length of "@SECONDS" (the text after '@').
checked<double> segment_length(std::string_view token, std::string_view seconds) {
  const checked<double> value = text::parse_real(seconds);
  if (!value.ok() || !(value.value() > 0 && value.value() <= max_segment_s))
    return diagnostic{"free", quote(token) +
                                  ": a drifting parameter is NAME@SECONDS, the segment length a "
                                  "number of seconds in (0, 1e12]"};
  return value.value();
}

/// A head whose sigma and phase are both free but drift differently.
checked<void> check_pairs(const std::vector<free_parameter>& free, std::size_t head_count) {
  for (std::size_t k = 0; k < head_count; ++k) {
    const free_parameter* sigma = nullptr;
    const free_parameter* phase = nullptr;
    for (const free_parameter& f : free) {
      if (f.index == parameter_index(k, head_parameter::sigma)) sigma = &f;
      if (f.index == parameter_index(k, head_parameter::phase)) phase = &f;
    }
    if (sigma != nullptr && phase != nullptr && sigma->segment_s != phase->segment_s) {
      const std::string head = "h" + std::to_string(k + 1);
      return diagnostic{"free", head + ".sigma and " + head +
                                    ".phase are estimated together (as the misalignment's "
                                    "components): give both the same @SECONDS, or neither"};
    }
  }
  return success();
}

}  // namespace

checked<std::vector<free_parameter>> parse_free_selection(std::string_view list,
                                                          std::size_t head_count) {
  auto error = [](std::string message) { return diagnostic{"free", std::move(message)}; };
  if (list.empty())
    return error("no free parameter: give a comma-separated list of " +
                 allowed_parameter_names(head_count));
  std::vector<free_parameter> selected;
  std::size_t item = 1;
  for (std::size_t start = 0;; ++item) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string_view token = list.substr(start, comma - start);
    if (token.empty())
      return error("item " + std::to_string(item) + " of " + quote(list) + " is empty");
    const std::size_t at = token.find('@');
    const std::string_view name = token.substr(0, at);
    free_parameter f;
    if (at != std::string_view::npos) {
      checked<double> length = segment_length(token, token.substr(at + 1));
      if (!length.ok()) return length.error();
      f.segment_s = length.value();
    }
    checked<parsed_name> parsed = parse_parameter_name(name);
    if (!parsed.ok()) return error(parsed.error().message);
    const parsed_name& p = parsed.value();
    if (p.is_head && p.head >= head_count)
      return error(quote(token) + " names head " + std::to_string(p.head + 1) +
                   " but the scene has " + std::to_string(head_count) +
                   (head_count == 1 ? " head" : " heads"));
    f.index =
        p.is_head ? parameter_index(p.head, p.head_key) : parameter_index(head_count, p.earth_key);
    for (const free_parameter& g : selected)
      if (g.index == f.index) return error(quote(name) + " is named twice");
    selected.push_back(f);
    if (comma == list.size()) break;
    start = comma + 1;
  }
  if (checked<void> pairs = check_pairs(selected, head_count); !pairs.ok()) return pairs.error();
  return selected;
}

checked<std::vector<std::size_t>> parse_free_list(std::string_view list, std::size_t head_count) {
  checked<std::vector<free_parameter>> selected = parse_free_selection(list, head_count);
  if (!selected.ok()) return selected.error();
  std::vector<std::size_t> indices;
  for (const free_parameter& f : selected.value()) {
    if (f.segment_s > 0)
      return diagnostic{"free",
                        "drifting parameters (NAME@SECONDS) are conescan-fit's: " + quote(list)};
    indices.push_back(f.index);
  }
  return indices;
}

void free_parameters(parameter_set& parameters, const std::vector<free_parameter>& free) {
  for (const free_parameter& f : free) {
    parameters.free[f.index] = true;
    parameters.segment_s[f.index] = f.segment_s;
  }
}

}  // namespace conescan::calibration

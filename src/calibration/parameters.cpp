#include "calibration/parameters.hpp"

#include <algorithm>
#include <charconv>

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

parameter_set parameter_set::nominal(std::size_t head_count) {
  const std::size_t n = parameter_count(head_count);
  return {head_count, std::vector<double>(n, 0.0), std::vector<bool>(n, false)};
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

checked<std::vector<std::size_t>> parse_free_list(std::string_view list, std::size_t head_count) {
  auto error = [](std::string message) { return diagnostic{"free", std::move(message)}; };
  if (list.empty())
    return error("no free parameter: give a comma-separated list of " +
                 allowed_parameter_names(head_count));
  std::vector<std::size_t> indices;
  std::size_t item = 1;
  for (std::size_t start = 0;; ++item) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string_view token = list.substr(start, comma - start);
    if (token.empty())
      return error("item " + std::to_string(item) + " of " + quote(list) + " is empty");
    checked<parsed_name> parsed = parse_parameter_name(token);
    if (!parsed.ok()) return error(parsed.error().message);
    const parsed_name& p = parsed.value();
    if (p.is_head && p.head >= head_count)
      return error(quote(token) + " names head " + std::to_string(p.head + 1) +
                   " but the scene has " + std::to_string(head_count) +
                   (head_count == 1 ? " head" : " heads"));
    const std::size_t index =
        p.is_head ? parameter_index(p.head, p.head_key) : parameter_index(head_count, p.earth_key);
    if (std::find(indices.begin(), indices.end(), index) != indices.end())
      return error(quote(token) + " is named twice");
    indices.push_back(index);
    if (comma == list.size()) break;
    start = comma + 1;
  }
  return indices;
}

}  // namespace conescan::calibration

#include "text/kvn_line.hpp"

#include <algorithm>

#include "text/number_text.hpp"

namespace conescan::text {

namespace {

bool is_upper_word(std::string_view w) noexcept {
  return !w.empty() && std::all_of(w.begin(), w.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  });
}

}  // namespace

kvn_line classify_kvn_line(std::string_view line) noexcept {
  const std::string_view t = trim_blanks(line);
  if (t.empty()) return {kvn_kind::blank, {}, {}};
  if (t.substr(0, 7) == "COMMENT" && (t.size() == 7 || t[7] == ' ' || t[7] == '\t')) {
    return {kvn_kind::comment, "COMMENT", trim_blanks(t.substr(7))};
  }
  const std::size_t equals = t.find('=');
  if (equals != std::string_view::npos) {
    return {kvn_kind::keyword_value, trim_blanks(t.substr(0, equals)),
            trim_blanks(t.substr(equals + 1))};
  }
  const char c = t.front();
  if ((c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.') return {kvn_kind::data, {}, {}};
  if (is_upper_word(t)) return {kvn_kind::marker, t, {}};
  return {kvn_kind::malformed, {}, {}};
}

}  // namespace conescan::text

#include "sources/kvn.hpp"

#include <algorithm>
#include <charconv>

#include "text/number_text.hpp"
#include "text/text_lines.hpp"

namespace conescan::sources {

checked<void> kvn_block::add(const kvn_line& l, std::size_t line) {
  if (std::find(vocabulary_.begin(), vocabulary_.end(), l.keyword) == vocabulary_.end()) {
    return diagnostic::in_file(
        {}, line, "unknown keyword " + quote(l.keyword) + " in the " + std::string(name_));
  }
  if (const kvn_entry* previous = find(l.keyword)) {
    return diagnostic::in_file({}, line,
                               "keyword " + std::string(l.keyword) + " given twice in the " +
                                   std::string(name_) + " (first at line " +
                                   std::to_string(previous->line) + ")");
  }
  entries_.push_back({std::string(l.keyword), std::string(l.value), line});
  return success();
}

const kvn_entry* kvn_block::find(std::string_view keyword) const noexcept {
  for (const kvn_entry& e : entries_) {
    if (e.keyword == keyword) return &e;
  }
  return nullptr;
}

checked<void> kvn_block::require(std::span<const std::string_view> keywords, std::size_t at) const {
  for (std::string_view k : keywords) {
    if (find(k) == nullptr) {
      return diagnostic::in_file({}, at,
                                 "missing mandatory keyword " + std::string(k) + " in the " +
                                     std::string(name_) + " starting at line " +
                                     std::to_string(first_line_));
    }
  }
  return success();
}

frame_kind classify_frame(std::string_view value) {
  const std::string v = text::to_upper(value);
  if (v == "EME2000" || v == "GCRF" || v == "ICRF" || v == "TEME" || v == "TOD")
    return frame_kind::inertial;
  if (v.rfind("ITRF", 0) == 0) return frame_kind::earth_fixed;
  if (v.rfind("SC_BODY_", 0) == 0 && v.size() > 8) return frame_kind::spacecraft_body;
  return frame_kind::unsupported;
}

std::optional<time_scale> parse_time_system(std::string_view value) {
  const std::string v = text::to_upper(value);
  for (time_scale s : {time_scale::utc, time_scale::tai, time_scale::tt, time_scale::gps}) {
    if (v == to_string(s)) return s;
  }
  return std::nullopt;
}

std::string_view to_string(interpolation_method m) noexcept {
  switch (m) {
    case interpolation_method::lagrange:
      return "LAGRANGE";
    case interpolation_method::hermite:
      return "HERMITE";
    case interpolation_method::linear:
      return "LINEAR";
  }
  return "?";
}

std::optional<interpolation_method> parse_interpolation_method(std::string_view value) {
  const std::string v = text::to_upper(value);
  for (interpolation_method m : {interpolation_method::lagrange, interpolation_method::hermite,
                                 interpolation_method::linear}) {
    if (v == to_string(m)) return m;
  }
  return std::nullopt;
}

checked<time_span> declared_span(const kvn_block& meta, time_scale scale) {
  time_span span;
  const char* keys[2][2] = {{"USEABLE_START_TIME", "START_TIME"},
                            {"USEABLE_STOP_TIME", "STOP_TIME"}};
  for (int end = 0; end < 2; ++end) {
    const kvn_entry* e = meta.find(keys[end][0]);
    if (!e) e = meta.find(keys[end][1]);
    checked<instant> t = entry_epoch(*e, scale);
    if (!t.ok()) return t.error();
    (end == 0 ? span.start : span.stop) = t.value();
  }
  for (const char* key : {"START_TIME", "STOP_TIME"}) {
    const checked<instant> t = entry_epoch(*meta.find(key), scale);
    if (!t.ok()) return t.error();
  }
  if (span.stop < span.start) {
    return diagnostic::in_file({}, meta.find("STOP_TIME")->line,
                               "the segment's stop time is before its start time");
  }
  return span;
}

checked<interpolation_choice> interpolation_from(const kvn_block& meta,
                                                 std::string_view method_keyword,
                                                 interpolation_choice defaults) {
  interpolation_choice c = defaults;
  if (const kvn_entry* method = meta.find(method_keyword)) {
    const std::optional<interpolation_method> parsed = parse_interpolation_method(method->value);
    if (!parsed) return unsupported_value(*method, "LAGRANGE, HERMITE or LINEAR");
    c.method = *parsed;
  }
  if (const kvn_entry* degree = meta.find("INTERPOLATION_DEGREE")) {
    checked<int> d = entry_integer(*degree, max_interpolation_degree);
    if (!d.ok()) return d.error();
    c.degree = d.value();
  }
  if (c.method == interpolation_method::linear) c.degree = 1;
  return c;
}

diagnostic unexpected_line(const kvn_line& l, std::size_t line, const std::string& where,
                           std::span<const std::string_view> metadata_vocabulary) {
  switch (l.kind) {
    case kvn_kind::keyword_value:
      if (std::find(metadata_vocabulary.begin(), metadata_vocabulary.end(), l.keyword) !=
          metadata_vocabulary.end()) {
        return diagnostic::in_file(
            {}, line,
            "keyword " + std::string(l.keyword) + " " + where + " (it belongs in a META block)");
      }
      return diagnostic::in_file({}, line, "unknown keyword " + quote(l.keyword) + " " + where);
    case kvn_kind::marker:
      return diagnostic::in_file({}, line, "unexpected " + std::string(l.keyword) + " " + where);
    case kvn_kind::data:
      return diagnostic::in_file({}, line, "data line " + where);
    default:
      return diagnostic::in_file({}, line, "malformed line " + where);
  }
}

diagnostic unsupported_value(const kvn_entry& e, std::string_view accepted) {
  return diagnostic::in_file({}, e.line,
                             "unsupported " + e.keyword + " " + quote(e.value) +
                                 " (conescan takes " + std::string(accepted) + ")");
}

checked<instant> entry_epoch(const kvn_entry& e, time_scale scale) {
  checked<instant> t = parse_epoch(e.value, scale);
  if (!t.ok()) {
    t.error().message = e.keyword + ": " + t.error().message;
    t.error().where.line = e.line;
  }
  return t;
}

checked<int> entry_integer(const kvn_entry& e, int max) {
  int v = 0;
  const char* end = e.value.data() + e.value.size();
  const auto [ptr, ec] = std::from_chars(e.value.data(), end, v);
  if (ec != std::errc() || ptr != end || v < 1 || v > max) {
    return diagnostic::in_file(
        {}, e.line,
        e.keyword + " " + quote(e.value) + " is not an integer in 1.." + std::to_string(max));
  }
  return v;
}

checked<double> check_version_line(const kvn_line& l, std::string_view keyword, double max_version,
                                   std::string_view other_keyword) {
  // "CCSDS_OEM_VERS" -> "OEM": the message type the keyword names.
  const auto type = [](std::string_view k) { return std::string(k.substr(6, 3)); };
  if (l.kind == kvn_kind::keyword_value && l.keyword == other_keyword) {
    return diagnostic::in_file({}, 0,
                               "this is an " + type(other_keyword) + " (" +
                                   std::string(other_keyword) + "), not an " + type(keyword));
  }
  if (l.kind != kvn_kind::keyword_value || l.keyword != keyword) {
    return diagnostic::in_file({}, 0,
                               "expected " + std::string(keyword) + " = version first: not an " +
                                   type(keyword) + " in KVN");
  }
  const std::optional<double> v = text::parse_number(l.value);
  if (!v || *v < 1.0 || *v > max_version) {
    return diagnostic::in_file({}, 0,
                               "unsupported " + std::string(keyword) + " " + quote(l.value) +
                                   " (conescan reads versions 1 to " +
                                   text::shortest_text(max_version) + ")");
  }
  return *v;
}

}  // namespace conescan::sources

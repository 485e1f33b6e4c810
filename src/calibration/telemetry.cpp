#include "calibration/telemetry.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <string_view>

#include "text/number_text.hpp"
#include "text/text_lines.hpp"

namespace conescan::calibration {

namespace {

/// Lines of a stream, at most max_telemetry_line_bytes each, without the line end (and a CR
/// before it). Reads blocks of 64 KiB: a file without line ends costs 1 MiB, not its size.
class line_source {
 public:
  explicit line_source(std::istream& in) : in_(in), buffer_(std::size_t{1} << 16) {}

  enum class result { line, end, too_long };

  result next(std::string& line) {
    line.clear();
    bool any = false;
    for (;;) {
      if (at_ == filled_ && !refill()) break;
      any = true;
      const char* begin = buffer_.data() + at_;
      const auto* newline = static_cast<const char*>(std::memchr(begin, '\n', filled_ - at_));
      const std::size_t length =
          newline ? static_cast<std::size_t>(newline - begin) : filled_ - at_;
      if (line.size() + length > max_telemetry_line_bytes) return result::too_long;
      line.append(begin, length);
      at_ += length;
      if (newline) {
        ++at_;
        break;
      }
    }
    if (!any) return result::end;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    ++number_;
    return result::line;
  }
  std::uint64_t number() const noexcept { return number_; }

 private:
  bool refill() {
    if (!in_) return false;
    in_.read(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    filled_ = static_cast<std::size_t>(in_.gcount());
    at_ = 0;
    return filled_ > 0;
  }

  std::istream& in_;
  std::vector<char> buffer_;
  std::size_t at_ = 0;
  std::size_t filled_ = 0;
  std::uint64_t number_ = 0;
};

/// A field of a line and its 1-based byte column.
struct field {
  std::string_view text;
  std::uint64_t column;
};

std::vector<field> split(std::string_view line) {
  std::vector<field> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    const std::size_t end = comma == std::string_view::npos ? line.size() : comma;
    fields.push_back({line.substr(start, end - start), start + 1});
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

/// Where a head's columns are in the header.
struct head_columns {
  std::optional<std::size_t> chord;
  std::optional<std::size_t> phase;
};

/// Which column gives each row's time (top of telemetry.hpp).
enum class time_kind { t_s, utc, gps };

struct header_layout {
  std::size_t field_count = 0;
  time_kind time = time_kind::t_s;
  std::size_t t_column = 0;        ///< t_s or utc; gps_week for GPS times
  std::size_t seconds_column = 0;  ///< gps_s for GPS times
  std::vector<head_columns> heads;
};

/// The time columns a header may have.
struct time_columns {
  std::optional<std::size_t> t_s, utc, gps_week, gps_s;

  std::optional<std::size_t>* slot(std::string_view name) {
    return name == "t_s"        ? &t_s
           : name == "utc"      ? &utc
           : name == "gps_week" ? &gps_week
           : name == "gps_s"    ? &gps_s
                                : nullptr;
  }
};

/// K of "hK_chord_deg" or "hK_phase_deg" (and which), or 0.
std::size_t head_of_column(std::string_view name, bool& is_chord) {
  for (std::string_view suffix : {std::string_view("_chord_deg"), std::string_view("_phase_deg")}) {
    if (name.size() <= suffix.size() + 1 || name.front() != 'h' ||
        name.substr(name.size() - suffix.size()) != suffix)
      continue;
    const std::string_view digits = name.substr(1, name.size() - 1 - suffix.size());
    std::size_t k = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), k);
    if (ec != std::errc() || end != digits.data() + digits.size() || digits.front() == '0')
      continue;
    is_chord = suffix == "_chord_deg";
    return k;
  }
  return 0;
}

class telemetry_parser {
 public:
  telemetry_parser(const std::string& file, std::size_t head_count,
                   const telemetry_time_stamps& stamps)
      : file_(file), head_count_(head_count), stamps_(stamps) {}

  diagnostic beyond_heads(std::uint64_t line, std::uint64_t column, std::size_t head) const {
    return error(line, column,
                 "the telemetry has columns of head " + std::to_string(head) +
                     " but the scene has " + std::to_string(head_count_) +
                     (head_count_ == 1 ? " head" : " heads"));
  }

  diagnostic error(std::uint64_t line, std::uint64_t column, std::string message) const {
    return {"telemetry", std::move(message), origin::file_line(file_, line, column)};
  }

  /// The header's fields (the line split, its byte-order mark removed).
  checked<header_layout> header(const std::vector<field>& fields, std::uint64_t line_number) const {
    header_layout h;
    h.field_count = fields.size();
    time_columns times;
    std::vector<head_columns> found;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      const field& f = fields[i];
      bool is_chord = false;
      std::optional<std::size_t>* slot = times.slot(f.text);
      if (const std::size_t k = slot ? 0 : head_of_column(f.text, is_chord); k != 0) {
        // A head beyond the scene's is refused here, before a slot per head is made (a column
        // "h14444444444_chord_deg" asked for 600 GB: a fuzzing finding).
        if (k > head_count_) return beyond_heads(line_number, f.column, k);
        if (k > found.size()) found.resize(k);
        slot = is_chord ? &found[k - 1].chord : &found[k - 1].phase;
      }
      if (slot == nullptr) continue;
      if (slot->has_value())
        return error(line_number, f.column, "column " + quote(f.text) + " appears twice");
      *slot = i;
    }
    if (checked<void> t = time_layout(times, line_number, h); !t.ok()) return t.error();
    found.resize(head_count_);
    for (std::size_t k = 0; k < head_count_; ++k) {
      const std::string prefix = "h" + std::to_string(k + 1);
      if (!found[k].chord)
        return error(line_number, 0,
                     "missing column '" + prefix + "_chord_deg' (the scene has " +
                         std::to_string(head_count_) + " heads)");
      if (!found[k].phase)
        return error(line_number, 0,
                     "missing column '" + prefix + "_phase_deg' (the scene has " +
                         std::to_string(head_count_) + " heads)");
    }
    h.heads = std::move(found);
    return h;
  }

  /// One kind of time column (t_s, utc, or gps_week and gps_s), and a way to read it.
  checked<void> time_layout(const time_columns& c, std::uint64_t line, header_layout& h) const {
    const int kinds = int{c.t_s.has_value()} + int{c.utc.has_value()} +
                      int{c.gps_week.has_value() || c.gps_s.has_value()};
    if (kinds > 1)
      return error(line, 0, "mixed time columns: give one time (t_s, utc, or gps_week and gps_s)");
    if (kinds == 0)
      return error(line, 0,
                   "missing column 't_s' in the header (or a time as utc, or gps_week and gps_s)");
    if (c.gps_week.has_value() != c.gps_s.has_value())
      return error(line, 0,
                   c.gps_week ? "gps_week without gps_s (the seconds of the week)"
                              : "gps_s without gps_week");
    h.time = c.t_s ? time_kind::t_s : c.utc ? time_kind::utc : time_kind::gps;
    h.t_column = c.t_s ? *c.t_s : c.utc ? *c.utc : *c.gps_week;
    if (c.gps_s) h.seconds_column = *c.gps_s;
    if ((h.time == time_kind::utc && !stamps_.from_utc) ||
        (h.time == time_kind::gps && !stamps_.from_gps))
      return error(line, 0, "absolute times (utc, GPS) need the scene's epoch");
    return success();
  }

  /// The row's time as seconds from the scene's epoch.
  checked<double> time_of(const std::vector<field>& fields, std::uint64_t line,
                          const header_layout& h) const {
    const field& f = fields[h.t_column];
    if (h.time == time_kind::t_s) {
      checked<std::optional<double>> t = number(f, line, "t_s", false);
      if (!t.ok()) return t.error();
      return *t.value();
    }
    checked<double> t = 0.0;
    if (h.time == time_kind::utc) {
      t = stamps_.from_utc(f.text);
    } else {
      checked<std::optional<double>> week = number(f, line, "gps_week", false);
      if (!week.ok()) return week.error();
      checked<std::optional<double>> s = number(fields[h.seconds_column], line, "gps_s", false);
      if (!s.ok()) return s.error();
      t = stamps_.from_gps(*week.value(), *s.value());
    }
    if (!t.ok())
      return error(line, f.column,
                   "column " + std::string(h.time == time_kind::utc ? "utc" : "gps_week") + ": " +
                       t.error().message);
    return t.value();
  }

  /// A row's time within the scene's span (when given); the message names the column and the
  /// time as written, and the span.
  checked<void> within_span(double t_s, const std::vector<field>& fields, std::uint64_t line,
                            const header_layout& h) const {
    if (!stamps_.span || (t_s >= stamps_.span->first_s && t_s <= stamps_.span->last_s))
      return success();
    const field& f = fields[h.t_column];
    const std::string written = h.time == time_kind::t_s ? "t_s = " + std::string(f.text)
                                : h.time == time_kind::utc
                                    ? "utc " + quote(f.text)
                                    : "gps_week " + std::string(f.text) + ", gps_s " +
                                          std::string(fields[h.seconds_column].text);
    const std::string after =
        h.time == time_kind::t_s
            ? ""
            : " (t_s = " + text::shortest_text(t_s) + " from the scene's epoch" +
                  (h.time == time_kind::gps
                       ? "; GPS weeks are counted on from 1980, not modulo 1024"
                       : "") +
                  ")";
    return error(line, f.column,
                 written + after + " is outside the scene's span, t_s " +
                     text::shortest_text(stamps_.span->first_s) + " to " +
                     text::shortest_text(stamps_.span->last_s) + " s (" + stamps_.span->set_by +
                     "): telemetry of another time is not this scene's");
  }

  /// A finite number, or nullopt for conescan-sim's `nan` when allowed; errors otherwise.
  checked<std::optional<double>> number(const field& f, std::uint64_t line, std::string_view column,
                                        bool nan_allowed) const {
    if (nan_allowed && f.text == "nan") return std::optional<double>();
    double value = 0;
    const auto [end, ec] = std::from_chars(f.text.data(), f.text.data() + f.text.size(), value);
    if (f.text.empty()) return error(line, f.column, "column " + std::string(column) + " is empty");
    if (ec == std::errc::result_out_of_range)
      return error(line, f.column,
                   "column " + std::string(column) + ": " + quote(f.text) +
                       " is beyond the range of a double");
    if (ec != std::errc() || end != f.text.data() + f.text.size() || !std::isfinite(value))
      return error(line, f.column,
                   "column " + std::string(column) + ": " + quote(f.text) +
                       " is not a finite number" +
                       (nan_allowed ? " (nan marks a head that did not measure)" : ""));
    return std::optional<double>(value);
  }

  /// One row's measurements (its fields: a line split), appended to `out`.
  checked<bool> row(const std::vector<field>& fields, std::uint64_t line_number,
                    const header_layout& h, telemetry& out) {
    if (fields.size() != h.field_count)
      return error(line_number, 0,
                   std::to_string(fields.size()) + " fields, the header has " +
                       std::to_string(h.field_count));
    checked<double> t = time_of(fields, line_number, h);
    if (!t.ok()) return t.error();
    const double t_s = t.value();
    if (previous_t_ && !(t_s > *previous_t_))
      return error(line_number, fields[h.t_column].column,
                   (h.time == time_kind::t_s ? "t_s = " + std::string(fields[h.t_column].text)
                                             : "t_s = " + text::shortest_text(t_s)) +
                       " does not follow the previous row's " + text::shortest_text(*previous_t_) +
                       ": rows must be in increasing time");
    previous_t_ = t_s;
    if (checked<void> in_span = within_span(t_s, fields, line_number, h); !in_span.ok())
      return in_span.error();
    if (out.observations.size() + out.unmeasured.size() + head_count_ > max_telemetry_measurements)
      return error(line_number, 0,
                   "more than " + std::to_string(max_telemetry_measurements) +
                       " measurements (rows times heads): the limit of a fit");
    for (std::size_t k = 0; k < head_count_; ++k) {
      const std::string prefix = "h" + std::to_string(k + 1);
      const field& chord_field = fields[*h.heads[k].chord];
      checked<std::optional<double>> chord =
          number(chord_field, line_number, prefix + "_chord_deg", true);
      if (!chord.ok()) return chord.error();
      checked<std::optional<double>> phase =
          number(fields[*h.heads[k].phase], line_number, prefix + "_phase_deg", true);
      if (!phase.ok()) return phase.error();
      if (!chord.value() || !phase.value()) {
        ++out.skipped_per_head[k];
        out.unmeasured.push_back({out.row_count, t_s, k});
        continue;
      }
      const double c = *chord.value();
      if (!(c > 0 && c < 360))
        return error(line_number, chord_field.column,
                     "column " + prefix + "_chord_deg: " + quote(chord_field.text) +
                         " is outside (0, 360) deg");
      out.observations.push_back({{out.row_count, t_s, k}, c, *phase.value()});
    }
    ++out.row_count;
    return true;
  }

  telemetry empty_telemetry() const {
    telemetry out;
    out.file = file_;
    out.skipped_per_head.assign(head_count_, 0);
    return out;
  }

  /// The telemetry once every row is read: at least one row.
  checked<telemetry> finished(telemetry out) const {
    if (out.row_count == 0) return error(1, 0, "no telemetry row after the header");
    return out;
  }

 private:
  const std::string& file_;
  std::size_t head_count_;
  const telemetry_time_stamps& stamps_;
  std::optional<double> previous_t_;
};

}  // namespace

checked<telemetry> read_telemetry(std::istream& in, const std::string& file_name,
                                  std::size_t head_count, const telemetry_time_stamps& stamps) {
  telemetry_parser parser(file_name, head_count, stamps);
  line_source lines(in);
  std::string line;
  auto too_long = [&] {
    return parser.error(lines.number() + 1, 0, "a line longer than 1 MiB: not telemetry");
  };
  line_source::result got = lines.next(line);
  if (got == line_source::result::too_long) return too_long();
  if (got == line_source::result::end)
    return diagnostic{"telemetry", "the file is empty: expected a header line",
                      origin::file_line(file_name, 0)};
  std::string_view header_line = line;
  if (header_line.substr(0, 3) == "\xEF\xBB\xBF") header_line.remove_prefix(3);
  checked<header_layout> header = parser.header(split(header_line), lines.number());
  if (!header.ok()) return header.error();
  telemetry out = parser.empty_telemetry();
  while ((got = lines.next(line)) == line_source::result::line) {
    if (line.empty()) return parser.error(lines.number(), 1, "an empty line");
    checked<bool> r = parser.row(split(line), lines.number(), header.value(), out);
    if (!r.ok()) return r.error();
  }
  if (got == line_source::result::too_long) return too_long();
  if (in.bad())
    return diagnostic{"telemetry", "cannot read: " + std::string(std::strerror(EIO)),
                      origin::file_line(file_name, 0)};
  return parser.finished(std::move(out));
}

checked<telemetry> read_telemetry_file(const std::string& path, std::size_t head_count,
                                       const telemetry_time_stamps& stamps) {
  std::ifstream in;
  if (checked<void> opened = text::open_for_reading(path, in); !opened.ok()) {
    diagnostic e = std::move(opened).error();
    e.option = "telemetry";
    return e;
  }
  return read_telemetry(in, path, head_count, stamps);
}

std::size_t telemetry_columns::row_count() const noexcept {
  if (!texts.empty()) return texts.front().second.size();
  return numbers.empty() ? 0 : numbers.front().second.size();
}

namespace {

/// A row of columns as the fields of its CSV line: each value's text (a number's shortest
/// round-trip text, NaN as nan) in `buffer`, its column where that line would have it.
void row_fields(const telemetry_columns& columns, std::size_t k, std::string& buffer,
                std::vector<field>& fields) {
  buffer.clear();
  std::vector<std::size_t> ends;
  for (const auto& [name, values] : columns.texts) {
    buffer += values[k];
    ends.push_back(buffer.size());
  }
  char number[32];
  for (const auto& [name, values] : columns.numbers) {
    const double v = values[k];
    if (std::isnan(v)) {
      buffer += "nan";
    } else {
      const auto end = std::to_chars(number, number + sizeof number, v).ptr;
      buffer.append(number, end);
    }
    ends.push_back(buffer.size());
  }
  fields.clear();
  std::size_t start = 0;
  for (std::size_t c = 0; c < ends.size(); ++c) {
    // Column c's text starts after c commas in the line.
    fields.push_back({std::string_view(buffer).substr(start, ends[c] - start), start + c + 1});
    start = ends[c];
  }
}

}  // namespace

checked<telemetry> read_telemetry_columns(const telemetry_columns& columns, const std::string& name,
                                          std::size_t head_count,
                                          const telemetry_time_stamps& stamps) {
  telemetry_parser parser(name, head_count, stamps);
  std::string names;
  for (const auto& column : columns.texts) names += (names.empty() ? "" : ",") + column.first;
  for (const auto& column : columns.numbers)
    names += (names.empty() && columns.texts.empty() ? "" : ",") + column.first;
  checked<header_layout> header = parser.header(split(names), 1);
  if (!header.ok()) return header.error();
  telemetry out = parser.empty_telemetry();
  std::size_t rows = columns.row_count();
  for (const auto& column : columns.texts) rows = std::min(rows, column.second.size());
  for (const auto& column : columns.numbers) rows = std::min(rows, column.second.size());
  std::string buffer;
  std::vector<field> fields;
  for (std::size_t k = 0; k < rows; ++k) {
    row_fields(columns, k, buffer, fields);
    checked<bool> r = parser.row(fields, k + 2, header.value(), out);
    if (!r.ok()) return r.error();
  }
  return parser.finished(std::move(out));
}

}  // namespace conescan::calibration

// OMM element sets: the format detected, the fields checked and turned into SGP4's (omm.hpp).
#include "orbit/omm.hpp"

#include <charconv>
#include <cmath>
#include <functional>

#include "conescan/enum_names.hpp"
#include "orbit/catalogue.hpp"
#include "orbit/omm_record.hpp"
#include "text/calendar_text.hpp"
#include "text/number_text.hpp"
#include "text/text_lines.hpp"

namespace conescan::orbit {

using omm_detail::field_error;
using omm_detail::field_value;
using omm_detail::record;
using omm_detail::record_error;

namespace {

constexpr double jd_1950 = 2433281.5;  // 1949-12-31T00:00 UTC, SGP4's day 0

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

/// The digits of `text` as a number, exactly `count` of them; nullopt otherwise.
std::optional<int> digits(std::string_view text, std::size_t count) {
  if (text.size() != count) return std::nullopt;
  int value = 0;
  for (char c : text) {
    if (!is_digit(c)) return std::nullopt;
    value = 10 * value + (c - '0');
  }
  return value;
}

/// An OMM epoch: the calendar's syntax (text/calendar_text.hpp: YYYY-MM-DDThh:mm:ss[.f] or
/// YYYY-DDDThh:mm:ss[.f] with an optional Z), in 1900-2099 and without a leap second (SGP4's
/// days have 86400 s); nullopt for any other text.
std::optional<tle_epoch> parse_epoch(std::string_view written) {
  const std::optional<text::calendar_time> c = text::parse_calendar(written);
  if (!c || c->year < 1900 || c->year > 2099 || !(c->second < 60)) return std::nullopt;
  const double seconds = 3600.0 * c->hour + 60.0 * c->minute + c->second;
  return tle_epoch{c->year, text::day_of_year(c->year, c->month, c->day), seconds / 86400.0};
}

/// OBJECT_ID in the TLE's form: "1998-067A" -> "98067A"; any other form as written.
std::string tle_designator(const std::string& object_id) {
  if (object_id.size() >= 9 && object_id.size() <= 11 && object_id[4] == '-' &&
      digits(object_id.substr(0, 4), 4) && digits(object_id.substr(5, 3), 3))
    return object_id.substr(2, 2) + object_id.substr(5);
  return object_id;
}

/// Reads a set's fields, keeping the first failure (later reads return their fallbacks), so
/// that a caller reads every field and asks for the error once.
class set_reader {
 public:
  set_reader(const record& set, const std::string& source) : set_(set), source_(source) {}

  const std::optional<diagnostic>& error() const { return error_; }
  void fail(diagnostic d) {
    if (!error_) error_ = std::move(d);
  }
  void fail(const field_value& f, std::string message) {
    fail(field_error(source_, f, std::move(message)));
  }

  const field_value* find(std::string_view key) const {
    const auto it = set_.fields.find(key);
    return it == set_.fields.end() || it->second.text.empty() ? nullptr : &it->second;
  }

  /// The field's text, upper case ("" when absent).
  std::string word(std::string_view key) const {
    const field_value* f = find(key);
    return f ? text::to_upper(f->text) : std::string();
  }

  /// A field SGP4 needs is absent (or empty).
  void missing(std::string_view key) {
    fail(record_error(source_, set_,
                      "missing " + std::string(key) +
                          ": SGP4 needs EPOCH, MEAN_MOTION, ECCENTRICITY, INCLINATION, "
                          "RA_OF_ASC_NODE, ARG_OF_PERICENTER, MEAN_ANOMALY and BSTAR"));
  }

  /// A number SGP4 needs, within [low, high] (or [low, high) when high_open).
  double required(std::string_view key, double low, double high, bool high_open = false) {
    const field_value* f = find(key);
    if (!f) {
      missing(key);
      return 0;
    }
    return in_range(*f, low, high, high_open);
  }

  /// An optional number (fallback when absent), any finite value.
  double optional(std::string_view key, double fallback) {
    const field_value* f = find(key);
    return f ? in_range(*f, -HUGE_VAL, HUGE_VAL, false) : fallback;
  }

  /// An optional whole number in [0, high] (fallback when absent).
  long whole(std::string_view key, long fallback, long high) {
    const field_value* f = find(key);
    if (!f) return fallback;
    long value = 0;
    const auto [end, ec] = std::from_chars(f->text.data(), f->text.data() + f->text.size(), value);
    if (ec != std::errc() || end != f->text.data() + f->text.size() || value < 0 || value > high) {
      fail(*f, quote(f->text) + " is not a whole number in [0, " + std::to_string(high) + "]");
      return fallback;
    }
    return value;
  }

 private:
  double in_range(const field_value& f, double low, double high, bool high_open) {
    const std::optional<double> value = text::parse_number(f.text);
    if (!value) {
      fail(f, quote(f.text) + " is not a number");
      return 0;
    }
    if (!(*value >= low && (high_open ? *value < high : *value <= high))) {
      fail(f, quote(f.text) + " is outside [" + text::shortest_text(low) + ", " +
                  text::shortest_text(high) + (high_open ? ")" : "]"));
      return 0;
    }
    return *value;
  }

  const record& set_;
  const std::string& source_;
  std::optional<diagnostic> error_;
};

/// CENTER_NAME, REF_FRAME, TIME_SYSTEM and the theory: what SGP4's elements are (mandatory in
/// KVN and XML), and the marks of elements that are not SGP4's.
void check_theory(set_reader& r, const record& set, const std::string& source) {
  const std::pair<const char*, const char*> fixed[] = {
      {"CENTER_NAME", "EARTH"}, {"REF_FRAME", "TEME"}, {"TIME_SYSTEM", "UTC"}};
  for (const auto& [key, value] : fixed) {
    const field_value* f = r.find(key);
    if (!f && set.ccsds)
      r.fail(record_error(source, set, std::string("missing ") + key + " (" + value + ")"));
    else if (f && text::to_upper(f->text) != value)
      r.fail(*f, quote(f->text) + ": SGP4's elements are " + value);
  }
  const std::string theory = r.word("MEAN_ELEMENT_THEORY");
  const field_value* f = r.find("MEAN_ELEMENT_THEORY");
  if (!f && set.ccsds)
    r.fail(record_error(source, set, "missing MEAN_ELEMENT_THEORY (SGP4)"));
  else if (theory == "SGP4-XP" || theory == "SGP4XP")
    r.fail(*f, quote(f->text) +
                   ": SGP4-XP elements are fitted to the SGP4-XP propagator, which conescan "
                   "does not have; give SGP4 elements (CelesTrak's GP data)");
  else if (f && theory != "SGP4" && theory != "SGP/SGP4" && theory != "SDP4" &&
           theory != "SGP4/SDP4")
    r.fail(*f, quote(f->text) + " is not SGP4's theory (SGP4, SGP/SGP4, SDP4 or SGP4/SDP4)");
  for (const char* xp : {"BTERM", "AGOM"})
    if (const field_value* g = r.find(xp))
      r.fail(*g,
             "a parameter of SGP4-XP's force model: these are SGP4-XP elements, which "
             "SGP4 cannot propagate");
  if (const field_value* a = r.find("SEMI_MAJOR_AXIS"))
    r.fail(*a, "SGP4 takes MEAN_MOTION (rev/day), not SEMI_MAJOR_AXIS");
}

/// TLE_LINE1 and TLE_LINE2 (Space-Track) must carry NORAD_CAT_ID's catalogue number.
void check_catalogue_numbers(set_reader& r, const tle& set) {
  const field_value* id = r.find("NORAD_CAT_ID");
  for (const char* key : {"TLE_LINE1", "TLE_LINE2"}) {
    const field_value* line = r.find(key);
    if (!line) continue;
    const std::optional<long> number =
        line->text.size() >= 7 ? catalog_number_value(line->text.substr(2, 5)) : std::nullopt;
    if (!number)
      r.fail(*line,
             "columns 3-7 " + quote(line->text.substr(2, 5)) + " are not a catalogue number");
    else if (id && *number != set.satellite_number)
      r.fail(*line, "catalogue number " + std::to_string(*number) +
                        " (columns 3-7) disagrees "
                        "with NORAD_CAT_ID " +
                        id->text);
  }
}

/// The tleParameters that identify the set (SGP4 does not read them): NORAD_CAT_ID,
/// CLASSIFICATION_TYPE, EPHEMERIS_TYPE, ELEMENT_SET_NO, REV_AT_EPOCH.
void read_tle_parameters(set_reader& r, tle& t) {
  if (const field_value* id = r.find("NORAD_CAT_ID")) {
    bool all_digits = id->text.size() <= 9;
    for (char c : id->text) all_digits = all_digits && is_digit(c);
    if (!all_digits) r.fail(*id, quote(id->text) + " is not a catalogue number (1 to 9 digits)");
    t.catalog_number = id->text;
    t.satellite_number = all_digits ? std::stol(id->text) : 0;
  }
  t.classification = 'U';
  if (const field_value* c = r.find("CLASSIFICATION_TYPE")) {
    const std::string word = text::to_upper(c->text);
    if (word != "U" && word != "C" && word != "S")
      r.fail(*c, quote(c->text) + " is not U, C or S");
    else
      t.classification = word[0];
  }
  t.ephemeris_type = static_cast<int>(r.whole("EPHEMERIS_TYPE", 0, 9));
  if (const field_value* e = r.find("EPHEMERIS_TYPE"); e && !r.error()) {
    if (t.ephemeris_type == 4)
      r.fail(*e, "4: SGP4-XP elements, which SGP4 cannot propagate (give SGP4 elements, type 0)");
    else if (t.ephemeris_type != 0 && t.ephemeris_type != 2 && t.ephemeris_type != 3)
      r.fail(*e, quote(e->text) +
                     " is not an SGP4 element set (0; 2 and 3, Spacetrack Report "
                     "#3's SGP4 and SDP4)");
  }
  t.element_set_number = static_cast<int>(r.whole("ELEMENT_SET_NO", 0, 9999));
  t.revolution_number = r.whole("REV_AT_EPOCH", 0, 999999999);
}

/// The message's version, when the format carries it (KVN's first line, XML's version
/// attribute, a CSV column or JSON member when given): a number in 1 to 3, as the OEM's.
void check_version(set_reader& r, const record& set) {
  constexpr double max_omm_version = 3.0;  // CCSDS 502.0-B-3
  const auto it = set.fields.find("CCSDS_OMM_VERS");
  if (it == set.fields.end()) return;
  const std::optional<double> v = text::parse_number(it->second.text);
  if (!v || *v < 1.0 || *v > max_omm_version)
    r.fail(it->second, "unsupported version " + quote(it->second.text) +
                           " (conescan reads versions 1 to " +
                           text::shortest_text(max_omm_version) + ")");
}

/// The set's TLE fields, every one checked.
checked<omm_element_set> element_set_of(const record& set, const std::string& source,
                                        omm_format format) {
  set_reader r(set, source);
  check_version(r, set);
  check_theory(r, set, source);
  omm_element_set out;
  out.format = format;
  out.place = set.place;
  tle& t = out.elements;
  t.line_number = set.line;
  if (const field_value* name = r.find("OBJECT_NAME")) t.name = name->text;
  if (const field_value* id = r.find("OBJECT_ID"))
    t.international_designator = tle_designator(id->text);
  if (const field_value* epoch = r.find("EPOCH")) {
    const std::optional<tle_epoch> e = parse_epoch(epoch->text);
    if (!e)
      r.fail(*epoch, quote(epoch->text) +
                         " is not a UTC epoch YYYY-MM-DDThh:mm:ss[.f] or YYYY-DDDThh:mm:ss[.f] in "
                         "1900-2099 (no leap second: SGP4's days have 86400 s)");
    else
      t.epoch = *e;
  } else {
    r.missing("EPOCH");
  }
  t.mean_motion_rev_day = r.required("MEAN_MOTION", 0, HUGE_VAL);
  if (const field_value* n = r.find("MEAN_MOTION"); n && !(t.mean_motion_rev_day > 0) && !r.error())
    r.fail(*n, quote(n->text) + " is not positive");
  t.eccentricity = r.required("ECCENTRICITY", 0, 1, true);
  t.inclination_deg = r.required("INCLINATION", 0, 180);
  t.raan_deg = r.required("RA_OF_ASC_NODE", 0, 360);
  t.argument_of_perigee_deg = r.required("ARG_OF_PERICENTER", 0, 360);
  t.mean_anomaly_deg = r.required("MEAN_ANOMALY", 0, 360);
  t.bstar_per_earth_radius = r.required("BSTAR", -HUGE_VAL, HUGE_VAL);
  t.mean_motion_dot_rev_day2 = r.optional("MEAN_MOTION_DOT", 0);
  t.mean_motion_ddot_rev_day3 = r.optional("MEAN_MOTION_DDOT", 0);
  read_tle_parameters(r, t);
  check_catalogue_numbers(r, t);
  if (r.error()) return *r.error();
  out.epoch_days_since_1950 = (jd_day_start(t.epoch) - jd_1950) + t.epoch.fraction_of_day;
  return out;
}

}  // namespace

std::string_view to_string(omm_format format) noexcept {
  static constexpr enum_names<omm_format, 4> names{{{omm_format::kvn, "KVN"},
                                                    {omm_format::xml, "XML"},
                                                    {omm_format::csv, "CSV"},
                                                    {omm_format::json, "JSON"}}};
  return name_of(names, format, "");
}

std::optional<omm_format> detect_omm_format(std::string_view text) noexcept {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  const std::size_t start = text.find_first_not_of(" \t\r\n");
  if (start == std::string_view::npos) return std::nullopt;
  text.remove_prefix(start);
  if (text.front() == '<') return omm_format::xml;
  if (text.front() == '[' || text.front() == '{') return omm_format::json;
  if (text.rfind("CCSDS_OMM_VERS", 0) == 0) return omm_format::kvn;
  const std::string_view first_line = text.substr(0, text.find('\n'));
  if (first_line.find(',') != std::string_view::npos &&
      first_line.find("EPOCH") != std::string_view::npos)
    return omm_format::csv;
  return std::nullopt;
}

sgp4_elements mean_elements(const omm_element_set& set) noexcept {
  sgp4_elements elements = mean_elements(set.elements);
  elements.epoch_days_since_1950 = set.epoch_days_since_1950;
  return elements;
}

namespace {

/// Why a text is no OMM: its start is none of the four formats.
diagnostic not_an_omm(std::string_view text, const std::string& source) {
  const bool tle_like = text.rfind("1 ", 0) == 0 || text.find("\n1 ") != std::string_view::npos;
  const bool oem = text.find("CCSDS_OEM_VERS") != std::string_view::npos;
  return diagnostic::in_file(
      source, 1,
      std::string("not an OMM: expected CCSDS KVN (CCSDS_OMM_VERS = ...), XML (<ndm> or "
                  "<omm>), CelesTrak's CSV (a header naming EPOCH) or JSON ([{...}])") +
          (tle_like ? "; a two-line element set is read with --tle"
           : oem    ? "; an OEM is read with --oem"
                    : ""));
}

/// What is done with each set's record (element_set_of checks it) in the text's format: true to
/// read on, false to stop.
using set_handler = std::function<checked<bool>(const record&, omm_format)>;

/// Reads the sets of `text` in its format one at a time and hands each to `take`; a text of no
/// set is refused. Holds one set's record at a time.
checked<void> for_each_set(std::string_view text, const std::string& source,
                           const set_handler& take) {
  const std::optional<omm_format> format = detect_omm_format(text);
  if (!format) return not_an_omm(text, source);
  using reader =
      checked<void> (*)(std::string_view, const std::string&, const omm_detail::record_handler&);
  const reader read = *format == omm_format::kvn   ? omm_detail::kvn_records
                      : *format == omm_format::xml ? omm_detail::xml_records
                      : *format == omm_format::csv ? omm_detail::csv_records
                                                   : omm_detail::json_records;
  std::size_t count = 0;
  checked<void> sets = read(text, source, [&](record&& set) -> checked<bool> {
    ++count;
    return take(set, *format);
  });
  if (!sets.ok()) return sets;
  if (count == 0)
    return diagnostic::in_file(
        source, 0, "holds no element set (read as " + std::string(to_string(*format)) + ")");
  return success();
}

}  // namespace

checked<std::vector<omm_element_set>> read_omm_sets(std::string_view text,
                                                    const std::string& source) {
  std::vector<omm_element_set> out;
  checked<void> read =
      for_each_set(text, source, [&](const record& set, omm_format format) -> checked<bool> {
        checked<omm_element_set> one = element_set_of(set, source, format);
        if (!one.ok()) return std::move(one).error();
        out.push_back(std::move(one).value());
        return true;
      });
  if (!read.ok()) return std::move(read).error();
  return out;
}

namespace {

/// The file's text, its start checked before more is read: /dev/zero or a binary is refused at
/// once.
checked<std::string> omm_text(const std::string& path) {
  return text::read_bounded_file(path, omm_max_bytes, "an OMM",
                                 [&](std::string_view start) -> checked<void> {
                                   if (detect_omm_format(start)) return success();
                                   return not_an_omm(start, path);
                                 });
}

}  // namespace

checked<omm_element_set> read_omm(const std::string& path, tle_selection selection) {
  if (selection == tle_selection::only_one) return read_omm_object(path, "");
  checked<std::string> text = omm_text(path);
  if (!text.ok()) return text.error();
  std::optional<omm_element_set> taken;
  checked<void> read =
      for_each_set(text.value(), path, [&](const record& set, omm_format format) -> checked<bool> {
        checked<omm_element_set> one = element_set_of(set, path, format);
        if (!one.ok()) return std::move(one).error();
        taken = std::move(one).value();
        return false;
      });
  if (!read.ok()) return std::move(read).error();
  return std::move(*taken);
}

checked<omm_element_set> read_omm_object(const std::string& path, std::string_view object) {
  checked<std::string> text = omm_text(path);
  if (!text.ok()) return text.error();
  catalogue_chooser chooser(object);
  std::optional<omm_element_set> taken;
  checked<void> read =
      for_each_set(text.value(), path, [&](const record& set, omm_format format) -> checked<bool> {
        checked<omm_element_set> one = element_set_of(set, path, format);
        if (!one.ok()) return std::move(one).error();
        const catalogue_chooser::step step =
            chooser.offer(one.value().elements, one.value().place, record_error(path, set, ""));
        if (step == catalogue_chooser::step::keep) taken = std::move(one).value();
        return step != catalogue_chooser::step::stop;
      });
  if (!read.ok()) return std::move(read).error();
  if (checked<void> verdict = chooser.verdict(path); !verdict.ok()) return verdict.error();
  return std::move(*taken);
}

}  // namespace conescan::orbit

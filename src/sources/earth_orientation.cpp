#include "sources/earth_orientation.hpp"

#include <erfa.h>

#include <cmath>
#include <numbers>

#include "text/number_text.hpp"
#include "text/text_lines.hpp"

namespace conescan::sources {

namespace {

constexpr double arcsec_rad = std::numbers::pi / (180.0 * 3600.0);
// The last column read (UT1 - UTC ends at column 68).
constexpr std::size_t least_line_chars = 68;

// Columns first..last (1-based, inclusive) of a line, blanks trimmed.
std::string_view columns(std::string_view line, std::size_t first, std::size_t last) {
  std::string_view field = line.substr(first - 1, last - first + 1);
  while (!field.empty() && field.front() == ' ') field.remove_prefix(1);
  while (!field.empty() && field.back() == ' ') field.remove_suffix(1);
  return field;
}

// A line's day: its MJD and the three values, or why not; `blank` when a value is missing (the
// end of the predictions).
struct parsed_line {
  double mjd = 0, xp_arcsec = 0, yp_arcsec = 0, ut1_minus_utc_s = 0;
  bool blank = false;
};

checked<parsed_line> parse_line(std::string_view line) {
  if (line.size() < least_line_chars)
    return diagnostic::saying("a line of " + std::to_string(line.size()) +
                              " characters: finals2000A's lines reach UT1 - UTC at columns 59-68");
  parsed_line p;
  const std::string_view mjd = columns(line, 8, 15), xp = columns(line, 19, 27),
                         yp = columns(line, 38, 46), ut1 = columns(line, 59, 68);
  const std::optional<double> mjd_value = text::parse_number(mjd);
  if (!mjd_value || *mjd_value != std::floor(*mjd_value) || *mjd_value < 36934 ||
      *mjd_value > 124000)
    return diagnostic::saying("columns 8-15 hold " + quote(mjd) +
                              ", not the MJD of a day within 1960-2199");
  p.mjd = *mjd_value;
  if (xp.empty() || yp.empty() || ut1.empty()) {
    p.blank = true;
    return p;
  }
  for (const auto& [text, where, out] :
       {std::tuple{xp, "19-27 (x_p)", &p.xp_arcsec}, std::tuple{yp, "38-46 (y_p)", &p.yp_arcsec},
        std::tuple{ut1, "59-68 (UT1 - UTC)", &p.ut1_minus_utc_s}}) {
    const std::optional<double> v = text::parse_number(text);
    if (!v)
      return diagnostic::saying("columns " + std::string(where) + " hold " + quote(text) +
                                ", not a number");
    *out = *v;
  }
  for (const std::size_t flag : {std::size_t{17}, std::size_t{58}})
    if (line[flag - 1] != 'I' && line[flag - 1] != 'P')
      return diagnostic::saying("column " + std::to_string(flag) + " holds " +
                                quote(line.substr(flag - 1, 1)) +
                                ", not I (IERS) or P (prediction)");
  if (std::abs(p.ut1_minus_utc_s) > 1 || std::abs(p.xp_arcsec) > 2 || std::abs(p.yp_arcsec) > 2)
    return diagnostic::saying(
        "UT1 - UTC " + text::shortest_text(p.ut1_minus_utc_s) + " s, x_p " +
        text::shortest_text(p.xp_arcsec) + "\", y_p " + text::shortest_text(p.yp_arcsec) +
        "\": beyond what the Earth does (|UT1 - UTC| < 1 s, |x_p|, |y_p| < 2\")");
  return p;
}

// 0h UTC of an MJD.
checked<instant> day_start(double mjd) {
  int year = 0, month = 0, day = 0;
  double fraction = 0;
  if (eraJd2cal(2400000.5, mjd, &year, &month, &day, &fraction) != 0)
    return diagnostic::saying("MJD " + text::shortest_text(mjd) + " is outside ERFA's calendar");
  return from_calendar({year, month, day, 0, 0, 0.0}, time_scale::utc);
}

}  // namespace

checked<earth_orientation> earth_orientation::read_finals2000a(const std::string& path) {
  earth_orientation eop;
  eop.path_ = path;
  bool ended = false;  // past the last day with values
  double last_mjd = 0;
  const checked<void> read = text::for_each_line(path, [&](std::string_view line) -> checked<void> {
    if (ended) return success();
    const checked<parsed_line> parsed = parse_line(line);
    if (!parsed.ok()) return parsed.error();
    const parsed_line& p = parsed.value();
    if (!eop.days_.empty() && p.mjd != last_mjd + 1)
      return diagnostic::saying("MJD " + text::shortest_text(p.mjd) + " after " +
                                text::shortest_text(last_mjd) +
                                ": the days must follow each other");
    last_mjd = p.mjd;
    if (p.blank) {
      ended = true;
      return success();
    }
    if (eop.days_.size() >= max_days)
      return diagnostic::saying("more than " + std::to_string(max_days) + " days");
    const checked<instant> t = day_start(p.mjd);
    if (!t.ok()) return t.error();
    eop.days_.push_back({t.value(), p.ut1_minus_utc_s - tai_minus_utc_s(t.value()),
                         p.xp_arcsec * arcsec_rad, p.yp_arcsec * arcsec_rad});
    return success();
  });
  if (!read.ok()) return read.error();
  if (eop.days_.empty())
    return diagnostic::in_file(path, 0,
                               "no day with UT1 - UTC and the pole: not a finals2000A file");
  return eop;
}

std::optional<earth_orientation_values> earth_orientation::at(const instant& t) const noexcept {
  if (t < days_.front().t || days_.back().t < t) return std::nullopt;
  const double from_first = seconds_between(days_.front().t, t);
  // Days are 86400 s of TAI but for one with a leap second: find the day, then its next.
  auto k = static_cast<std::size_t>(std::floor(from_first / seconds_per_day));
  if (k >= days_.size()) k = days_.size() - 1;
  while (k > 0 && t < days_[k].t) --k;
  while (k + 1 < days_.size() && !(t < days_[k + 1].t)) ++k;
  const day& a = days_[k];
  if (k + 1 == days_.size())
    return earth_orientation_values{a.ut1_minus_tai_s + tai_minus_utc_s(t), a.xp_rad, a.yp_rad};
  const day& b = days_[k + 1];
  const double w = seconds_between(a.t, t) / seconds_between(a.t, b.t);
  return earth_orientation_values{
      a.ut1_minus_tai_s + w * (b.ut1_minus_tai_s - a.ut1_minus_tai_s) + tai_minus_utc_s(t),
      a.xp_rad + w * (b.xp_rad - a.xp_rad), a.yp_rad + w * (b.yp_rad - a.yp_rad)};
}

std::string earth_orientation::coverage() const {
  return path_ + " covers " + format_utc(first(), 0).substr(0, 10) + " to " +
         format_utc(last(), 0).substr(0, 10) + " (UTC)";
}

}  // namespace conescan::sources

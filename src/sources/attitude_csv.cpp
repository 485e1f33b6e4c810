#include "sources/attitude_csv.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "text/number_text.hpp"
#include "text/text_lines.hpp"

namespace conescan::sources {

namespace {

constexpr std::array<std::string_view, 4> columns = {"t_s", "roll_deg", "pitch_deg", "yaw_deg"};
constexpr double deg = std::numbers::pi / 180;

/// The comma-separated fields of a line, trimmed: up to 5 (a fifth means too many).
std::size_t split_commas(std::string_view line, std::array<std::string_view, 5>& out) {
  std::size_t n = 0;
  for (;;) {
    const std::size_t comma = line.find(',');
    if (n < out.size()) out[n] = text::trim_blanks(line.substr(0, comma));
    ++n;
    if (comma == std::string_view::npos) return n;
    line.remove_prefix(comma + 1);
  }
}

std::string header_text() {
  return std::string(columns[0]) + "," + std::string(columns[1]) + "," + std::string(columns[2]) +
         "," + std::string(columns[3]);
}

/// `to` moved by a whole number of turns to within half a turn of `from`: the short way round.
double nearest_turn(double from, double to) noexcept {
  return from + std::remainder(to - from, 2 * std::numbers::pi);
}

}  // namespace

checked<attitude_table> read_attitude_csv(const std::string& path, std::size_t max_rows) {
  attitude_table table;
  table.path_ = path;
  bool header_seen = false;
  checked<void> e = text::for_each_line(path, [&](std::string_view line) -> checked<void> {
    if (text::trim_blanks(line).empty()) return success();
    std::array<std::string_view, 5> f;
    const std::size_t n = split_commas(line, f);
    if (!header_seen) {
      if (n != 4 || !std::equal(columns.begin(), columns.end(), f.begin())) {
        return diagnostic::in_file({}, 0,
                                   "expected the header " + header_text() + ", not " + quote(line));
      }
      header_seen = true;
      return success();
    }
    if (n != 4) {
      return diagnostic::in_file(
          {}, 0, "row with " + std::to_string(n) + " fields (expected " + header_text() + ")");
    }
    std::array<double, 4> v{};
    for (std::size_t i = 0; i < 4; ++i) {
      const std::optional<double> x = text::parse_number(f[i]);
      if (!x) {
        return diagnostic::in_file(
            {}, 0, "malformed number " + quote(f[i]) + " (" + std::string(columns[i]) + ")");
      }
      v[i] = *x;
    }
    if (!table.t_s_.empty() && !(table.t_s_.back() < v[0])) {
      return diagnostic::in_file(
          {}, 0,
          "t_s " + text::shortest_text(v[0]) + " is not after the previous row's " +
              text::shortest_text(table.t_s_.back()) + " (times must increase)");
    }
    if (table.t_s_.size() >= max_rows) {
      return diagnostic::in_file(
          {}, 0, "more than " + std::to_string(max_rows) + " rows (the limit that bounds memory)");
    }
    table.t_s_.push_back(v[0]);
    table.angles_.push_back({v[1] * deg, v[2] * deg, v[3] * deg});
    return success();
  });
  if (!e.ok()) return e.error();
  if (table.t_s_.empty()) {
    return diagnostic::in_file(
        path, 0,
        header_seen ? "no rows after the header" : "empty: expected the header " + header_text());
  }
  return table;
}

checked<void> attitude_table::check_coverage(double t0_s, double t1_s) const {
  if (!(t0_s >= t_s_.front() && t1_s <= t_s_.back() && t0_s <= t1_s)) {
    return diagnostic::in_file(path_, 0,
                               "the attitude covers t_s " + text::shortest_text(t_s_.front()) +
                                   " to " + text::shortest_text(t_s_.back()) +
                                   " s, not the scene's " + text::shortest_text(t0_s) + " to " +
                                   text::shortest_text(t1_s) + " s");
  }
  return success();
}

checked<attitude_angles> attitude_table::angles_at(double t_s) const {
  if (!(t_s >= t_s_.front() && t_s <= t_s_.back())) {
    return diagnostic::in_file(path_, 0,
                               "t_s " + text::shortest_text(t_s) + " is outside the attitude's " +
                                   text::shortest_text(t_s_.front()) + " to " +
                                   text::shortest_text(t_s_.back()) + " s");
  }
  const auto above = std::upper_bound(t_s_.begin(), t_s_.end(), t_s);
  if (above == t_s_.end()) return angles_.back();
  const auto k = static_cast<std::size_t>(above - t_s_.begin()) - 1;
  const double u = (t_s - t_s_[k]) / (t_s_[k + 1] - t_s_[k]);
  const attitude_angles& a = angles_[k];
  const attitude_angles& b = angles_[k + 1];
  const auto lerp = [u](double x, double y) { return x + u * (nearest_turn(x, y) - x); };
  return attitude_angles{lerp(a.roll_rad, b.roll_rad), lerp(a.pitch_rad, b.pitch_rad),
                         lerp(a.yaw_rad, b.yaw_rad)};
}

}  // namespace conescan::sources

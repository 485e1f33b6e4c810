#include "sources/attitude_csv.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>

#include "text/number_text.hpp"
#include "text/text_lines.hpp"

namespace conescan::sources {

namespace {

constexpr double deg = std::numbers::pi / 180;

// The columns a table may have, in the order of the slots below.
constexpr std::array<std::string_view, 11> column_names = {
    "t_s",     "utc", "gps_week", "gps_s", "roll_deg", "pitch_deg",
    "yaw_deg", "q_w", "q_x",      "q_y",   "q_z"};
enum slot : std::size_t { t_s, utc, gps_week, gps_s, roll, pitch, yaw, q_w, q_x, q_y, q_z };

const char* const accepted_header =
    "a time (t_s, utc, or gps_week and gps_s) and an attitude (roll_deg, pitch_deg, yaw_deg, or "
    "q_w, q_x, q_y, q_z)";

/// A field of a line, trimmed, with its 1-based byte column.
struct field {
  std::string_view text;
  std::uint64_t column = 0;
};

/// The comma-separated fields of a line, at most `capacity` + 1 (one more means too many).
std::vector<field> split_commas(std::string_view line, std::size_t capacity) {
  std::vector<field> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    const std::string_view raw =
        line.substr(start, comma == std::string_view::npos ? comma : comma - start);
    const std::string_view text = text::trim_blanks(raw);
    out.push_back({text, start + static_cast<std::size_t>(text.data() - raw.data()) + 1});
    if (comma == std::string_view::npos || out.size() > capacity) return out;
    start = comma + 1;
  }
}

/// `to` moved by a whole number of turns to within half a turn of `from`: the short way round.
double nearest_turn(double from, double to) noexcept {
  return from + std::remainder(to - from, 2 * std::numbers::pi);
}

diagnostic at_column(std::uint64_t column, std::string message) {
  return diagnostic::in_file({}, 0, std::move(message), column);
}

}  // namespace

/// Reads a table line by line: the header's layout, then each row into the table.
class attitude_csv_reader {
 public:
  attitude_csv_reader(attitude_table& table, const attitude_csv_options& options)
      : table_(table), options_(options) {}

  checked<void> line(std::string_view text) {
    ++line_;
    if (text::trim_blanks(text).empty()) return success();
    if (!header_seen_) return header(text);
    return row(text);
  }
  bool header_seen() const noexcept { return header_seen_; }

 private:
  checked<void> header(std::string_view text) {
    const std::vector<field> fields = split_commas(text, column_names.size());
    if (fields.size() > column_names.size())
      return at_column(fields.back().column,
                       "more columns than a table has: expected " + std::string(accepted_header));
    for (std::size_t i = 0; i < fields.size(); ++i) {
      const auto name = std::find(column_names.begin(), column_names.end(), fields[i].text);
      if (name == column_names.end())
        return at_column(fields[i].column, "unknown column " + quote(fields[i].text) +
                                               ": expected " + accepted_header);
      const auto s = static_cast<std::size_t>(name - column_names.begin());
      if (position_[s])
        return at_column(fields[i].column, "column " + quote(fields[i].text) + " appears twice");
      position_[s] = i;
    }
    columns_ = fields.size();
    header_seen_ = true;
    if (checked<void> t = time_layout(); !t.ok()) return t;
    return attitude_layout();
  }

  checked<void> time_layout() {
    const bool by_t = position_[t_s].has_value(), by_utc = position_[utc].has_value();
    const bool by_gps = position_[gps_week] || position_[gps_s];
    if (by_t + by_utc + by_gps > 1)
      return at_column(0, "mixed time columns: give one time (t_s, utc, or gps_week and gps_s)");
    if (by_t + by_utc + by_gps == 0)
      return at_column(0, std::string("no time column: expected ") + accepted_header);
    if (by_gps && !(position_[gps_week] && position_[gps_s]))
      return at_column(0, position_[gps_week] ? "gps_week without gps_s (the seconds of the week)"
                                              : "gps_s without gps_week");
    table_.time_ = by_t     ? attitude_time_column::t_s
                   : by_utc ? attitude_time_column::utc
                            : attitude_time_column::gps;
    if (!by_t && !options_.epoch)
      return at_column(0, "absolute times (utc, GPS) need the scene's epoch");
    return success();
  }

  checked<void> attitude_layout() {
    const auto count = [&](std::initializer_list<slot> slots) {
      return std::count_if(slots.begin(), slots.end(), [&](slot s) { return position_[s]; });
    };
    const auto angles = count({roll, pitch, yaw}), quaternions = count({q_w, q_x, q_y, q_z});
    if (angles > 0 && quaternions > 0)
      return at_column(0, "mixed angle and quaternion columns: give one attitude");
    if (angles + quaternions == 0)
      return at_column(0, std::string("no attitude columns: expected ") + accepted_header);
    const bool by_angles = angles > 0;
    static constexpr slot angle_slots[] = {roll, pitch, yaw};
    static constexpr slot quaternion_slots[] = {q_w, q_x, q_y, q_z};
    for (slot s :
         by_angles ? std::span<const slot>(angle_slots) : std::span<const slot>(quaternion_slots))
      if (!position_[s])
        return at_column(
            0, "missing column " + quote(column_names[s]) + " (expected " + accepted_header + ")");
    table_.kind_ = by_angles ? attitude_table_kind::angles : attitude_table_kind::quaternions;
    table_.scalar_first_ = !by_angles && *position_[q_w] < *position_[q_x];
    return success();
  }

  /// A finite number of column `s` (message: the column's name).
  checked<double> number(const std::vector<field>& f, slot s) const {
    const field& x = f[*position_[s]];
    const std::optional<double> value = text::parse_number(x.text);
    if (!value)
      return at_column(x.column, "malformed number " + quote(x.text) + " (" +
                                     std::string(column_names[s]) + ")");
    return *value;
  }

  /// The row's time as seconds from the scene's epoch.
  checked<double> time_of(const std::vector<field>& f) const {
    if (table_.time_ == attitude_time_column::t_s) return number(f, t_s);
    checked<instant> t = instant{};
    if (table_.time_ == attitude_time_column::utc) {
      t = parse_epoch(f[*position_[utc]].text, time_scale::utc);
      if (!t.ok()) return at_column(f[*position_[utc]].column, "utc: " + t.error().message);
    } else {
      const checked<double> week = number(f, gps_week), seconds = number(f, gps_s);
      if (!week.ok()) return week.error();
      if (!seconds.ok()) return seconds.error();
      t = from_gps_week(week.value(), seconds.value());
      if (!t.ok()) return at_column(f[*position_[gps_week]].column, t.error().message);
    }
    return seconds_between(*options_.epoch, t.value());
  }

  checked<void> row(std::string_view text) {
    const std::vector<field> f = split_commas(text, columns_);
    if (f.size() != columns_)
      return at_column(0, "row with " + std::string(f.size() > columns_ ? "more than " : "") +
                              std::to_string(f.size() > columns_ ? columns_ : f.size()) +
                              " fields (the header has " + std::to_string(columns_) + ")");
    const checked<double> t = time_of(f);
    if (!t.ok()) return t.error();
    if (!table_.t_s_.empty() && !(table_.t_s_.back() < t.value()))
      return at_column(0, "t_s " + text::shortest_text(t.value()) +
                              " is not after the previous row's " +
                              text::shortest_text(table_.t_s_.back()) + " (times must increase)");
    if (table_.t_s_.size() >= options_.max_rows)
      return at_column(0, "more than " + std::to_string(options_.max_rows) +
                              " rows (the limit that bounds memory)");
    checked<void> value =
        table_.kind_ == attitude_table_kind::angles ? angle_row(f) : quaternion_row(f);
    if (!value.ok()) return value;
    table_.t_s_.push_back(t.value());
    table_.lines_.push_back(line_);
    return success();
  }

  checked<void> angle_row(const std::vector<field>& f) {
    std::array<double, 3> v{};
    for (slot s : {roll, pitch, yaw}) {
      const checked<double> x = number(f, s);
      if (!x.ok()) return x.error();
      v[s - roll] = x.value() * deg;
    }
    table_.angles_.push_back({v[0], v[1], v[2]});
    return success();
  }

  checked<void> quaternion_row(const std::vector<field>& f) {
    std::array<double, 4> v{};
    for (slot s : {q_w, q_x, q_y, q_z}) {
      const checked<double> x = number(f, s);
      if (!x.ok()) return x.error();
      v[s - q_w] = x.value();
    }
    const quaternion q{v[0], v[1], v[2], v[3]};
    const double n = norm(q);
    if (!(std::abs(n - 1) <= attitude_csv_quaternion_tolerance))
      return at_column(
          f[*position_[q_w]].column,
          "quaternion (q_w, q_x, q_y, q_z) of norm " + text::shortest_text(n) + ", not 1 within " +
              text::shortest_text(attitude_csv_quaternion_tolerance) + ": not a rotation");
    // Inertial -> body transforms coordinates: body <- inertial is R(conj q) (top of file).
    quaternion body_from_inertial = conjugate(scaled(q, 1 / n));
    if (!table_.body_from_inertial_.empty() &&
        dot(table_.body_from_inertial_.back(), body_from_inertial) < 0)
      body_from_inertial = scaled(body_from_inertial, -1);  // the same rotation, continuous
    table_.body_from_inertial_.push_back(body_from_inertial);
    return success();
  }

  attitude_table& table_;
  const attitude_csv_options& options_;
  std::uint64_t line_ = 0;
  bool header_seen_ = false;
  std::size_t columns_ = 0;
  std::array<std::optional<std::size_t>, column_names.size()> position_{};
};

namespace {

/// The attitude of 3-2-1 angles as a quaternion, the elementary rotations composed in the
/// DCM's order (any one convention serves: only angles between attitudes are taken of it).
quaternion from_angles(double roll, double pitch, double yaw) noexcept {
  return quaternion_from_rotation_vector({roll, 0, 0}) *
         quaternion_from_rotation_vector({0, pitch, 0}) *
         quaternion_from_rotation_vector({0, 0, yaw});
}

/// The value at the midpoint of [t0, t1] of the parabola through (t0, 0), (t1, y1), (t2, y2),
/// less the chord's (y1 / 2): the second-order term linear interpolation leaves out.
double curvature_at_midpoint(double t0, double t1, double t2, double y1, double y2) noexcept {
  // Newton's form: p(t) = y1 (t - t0) / (t1 - t0) + c (t - t0)(t - t1), with c the second divided
  // difference; at the midpoint (t - t0)(t - t1) = -(t1 - t0)^2 / 4.
  const double d1 = y1 / (t1 - t0), d2 = (y2 - y1) / (t2 - t1);
  const double c = (d2 - d1) / (t2 - t0);
  return -c * (t1 - t0) * (t1 - t0) / 4;
}

}  // namespace

void attitude_table::estimate_errors() {
  const std::size_t n = t_s_.size();
  errors_rad_.assign(n > 1 ? n - 1 : 0, 0.0f);
  if (n < 3) return;  // two rows: a line is all they define
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const std::size_t j = k + 2 < n ? k + 2 : k - 1;  // the third row: the next, or the one before
    const double t0 = t_s_[k], t1 = t_s_[k + 1], t2 = t_s_[j];
    double angle = 0;
    if (kind_ == attitude_table_kind::angles) {
      // Each angle relative to row k's, the short way round as angles_at takes it.
      const attitude_angles &a = angles_[k], &b = angles_[k + 1], &c = angles_[j];
      const auto mid = [&](double x, double y, double z, bool linear) {
        const double y1 = nearest_turn(x, y) - x, y2 = nearest_turn(x, z) - x;
        return x + y1 / 2 + (linear ? 0 : curvature_at_midpoint(t0, t1, t2, y1, y2));
      };
      const auto at_mid = [&](bool linear) {
        return from_angles(mid(a.roll_rad, b.roll_rad, c.roll_rad, linear),
                           mid(a.pitch_rad, b.pitch_rad, c.pitch_rad, linear),
                           mid(a.yaw_rad, b.yaw_rad, c.yaw_rad, linear));
      };
      angle = angle_between(at_mid(true), at_mid(false));
    } else {
      // Rotation vectors relative to row k: the geodesic is their chord.
      const quaternion& q = body_from_inertial_[k];
      const vec3<double> v1 = rotation_vector(body_from_inertial_[k + 1] * conjugate(q));
      const vec3<double> v2 = rotation_vector(body_from_inertial_[j] * conjugate(q));
      const vec3<double> bend{curvature_at_midpoint(t0, t1, t2, v1.x, v2.x),
                              curvature_at_midpoint(t0, t1, t2, v1.y, v2.y),
                              curvature_at_midpoint(t0, t1, t2, v1.z, v2.z)};
      angle = angle_between(quaternion_from_rotation_vector(v1 * 0.5) * q,
                            quaternion_from_rotation_vector(v1 * 0.5 + bend) * q);
    }
    errors_rad_[k] = static_cast<float>(angle);
  }
}

checked<attitude_table> read_attitude_csv(const std::string& path,
                                          const attitude_csv_options& options) {
  attitude_table table;
  table.path_ = path;
  attitude_csv_reader reader(table, options);
  checked<void> e =
      text::for_each_line(path, [&](std::string_view line) { return reader.line(line); });
  if (!e.ok()) return e.error();
  if (table.t_s_.empty()) {
    return diagnostic::in_file(path, 0,
                               reader.header_seen()
                                   ? "no rows after the header"
                                   : std::string("empty: expected a header of ") + accepted_header);
  }
  table.estimate_errors();
  return table;
}

checked<void> attitude_table::check_coverage(double t0_s, double t1_s,
                                             std::optional<double> max_angle_rad) const {
  if (!(t0_s >= t_s_.front() && t1_s <= t_s_.back() && t0_s <= t1_s)) {
    return diagnostic::in_file(path_, 0,
                               "the attitude covers t_s " + text::shortest_text(t_s_.front()) +
                                   " to " + text::shortest_text(t_s_.back()) +
                                   " s, not the scene's " + text::shortest_text(t0_s) + " to " +
                                   text::shortest_text(t1_s) + " s");
  }
  if (!max_angle_rad || errors_rad_.empty()) return success();
  // The intervals that meet [t0_s, t1_s], the worst first found.
  const auto first =
      static_cast<std::size_t>(std::upper_bound(t_s_.begin(), t_s_.end(), t0_s) - t_s_.begin());
  std::size_t worst = std::min(first == 0 ? 0 : first - 1, errors_rad_.size() - 1);
  for (std::size_t k = worst; k < errors_rad_.size() && t_s_[k] < t1_s; ++k)
    if (errors_rad_[k] > errors_rad_[worst]) worst = k;
  const double error_rad = errors_rad_[worst];
  if (!(error_rad > *max_angle_rad)) return success();
  constexpr double deg_per_rad = 180 / std::numbers::pi;
  return diagnostic::in_file(
      path_, lines_[worst],
      "attitude interpolation error estimate " + text::rounded_text(error_rad * deg_per_rad) +
          " deg between t_s " + text::shortest_text(t_s_[worst]) + " and " +
          text::shortest_text(t_s_[worst + 1]) + " (this row and the next, " +
          text::rounded_text(t_s_[worst + 1] - t_s_[worst]) + " s apart) exceeds the " +
          text::rounded_text(*max_angle_rad * deg_per_rad) +
          " deg the angles need: sample the attitude more finely (or accept a coarser one with "
          "--interpolation-tolerance-deg)");
}

checked<std::size_t> attitude_table::interval(double t_s) const {
  if (!(t_s >= t_s_.front() && t_s <= t_s_.back())) {
    return diagnostic::in_file(path_, 0,
                               "t_s " + text::shortest_text(t_s) + " is outside the attitude's " +
                                   text::shortest_text(t_s_.front()) + " to " +
                                   text::shortest_text(t_s_.back()) + " s");
  }
  const auto above = std::upper_bound(t_s_.begin(), t_s_.end(), t_s);
  if (above == t_s_.end()) return t_s_.size() - 1;  // the last row itself
  return static_cast<std::size_t>(above - t_s_.begin()) - 1;
}

checked<attitude_angles> attitude_table::angles_at(double t_s) const {
  if (kind_ != attitude_table_kind::angles)
    return diagnostic::in_file(path_, 0, "a quaternion table holds no angles");
  const checked<std::size_t> at = interval(t_s);
  if (!at.ok()) return at.error();
  const std::size_t k = at.value();
  if (k + 1 == t_s_.size()) return angles_.back();
  const double u = (t_s - t_s_[k]) / (t_s_[k + 1] - t_s_[k]);
  const attitude_angles& a = angles_[k];
  const attitude_angles& b = angles_[k + 1];
  const auto lerp = [u](double x, double y) { return x + u * (nearest_turn(x, y) - x); };
  return attitude_angles{lerp(a.roll_rad, b.roll_rad), lerp(a.pitch_rad, b.pitch_rad),
                         lerp(a.yaw_rad, b.yaw_rad)};
}

checked<quaternion> attitude_table::body_from_inertial_at(double t_s) const {
  if (kind_ != attitude_table_kind::quaternions)
    return diagnostic::in_file(path_, 0, "an angle table holds no quaternions");
  const checked<std::size_t> at = interval(t_s);
  if (!at.ok()) return at.error();
  const std::size_t k = at.value();
  const quaternion& a = body_from_inertial_[k];
  if (k + 1 == t_s_.size() || t_s == t_s_[k]) return a;
  // The geodesic: a turned by the fraction u of the rotation from a to the next row.
  const double u = (t_s - t_s_[k]) / (t_s_[k + 1] - t_s_[k]);
  const vec3<double> step = rotation_vector(body_from_inertial_[k + 1] * conjugate(a));
  return quaternion_from_rotation_vector(step * u) * a;
}

}  // namespace conescan::sources

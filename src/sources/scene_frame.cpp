#include "sources/scene_frame.hpp"

#include <erfa.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "conescan/enum_names.hpp"
#include "sources/earth_rotation.hpp"
#include "sources/uniform_nodes.hpp"

namespace conescan::sources {

namespace {

constexpr enum_names<reference_frame, 6> frame_names{{{reference_frame::tod, "TOD"},
                                                      {reference_frame::teme, "TEME"},
                                                      {reference_frame::eme2000, "EME2000"},
                                                      {reference_frame::gcrf, "GCRF"},
                                                      {reference_frame::icrf, "ICRF"},
                                                      {reference_frame::itrf, "ITRF"}}};

constexpr double two_pi = 2.0 * std::numbers::pi;

/// ERFA's row-major r[row][col] as the core's column-major matrix (m[col][row]).
mat3<double> from_erfa(const double r[3][3]) noexcept {
  mat3<double> m(0.0);
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) m[col][row] = r[row][col];
  return m;
}

/// UT1 seconds from `from` to `to` (two-part Julian dates, each part differenced alone).
double ut1_seconds_between(const julian_date& from, const julian_date& to) noexcept {
  return ((to.jd1 - from.jd1) + (to.jd2 - from.jd2)) * seconds_per_day;
}

/// A UTC step between two nodes (a leap second, or a step of 0.05 s or more in the 1960s): UT1 =
/// UTC + constant then advances by other than the TAI seconds, beyond the pre-1972 drift of
/// TAI - UTC (at most 0.0026 s a day: 6.5e-4 s between nodes 6 h apart).
constexpr double ut1_step_threshold_s = 0.01;

}  // namespace

mat3<double> about_z(double angle_rad) noexcept {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  mat3<double> m(0.0);
  m[0][0] = c;
  m[0][1] = s;
  m[1][0] = -s;
  m[1][1] = c;
  m[2][2] = 1.0;
  return m;
}

std::string_view to_string(reference_frame frame) noexcept {
  return name_of(frame_names, frame, "?");
}

std::optional<reference_frame> reference_frame_from_name(std::string_view name) noexcept {
  if (const reference_frame* frame = value_named(frame_names, name);
      frame && *frame != reference_frame::itrf)
    return *frame;
  // ITRF, ITRF93, ITRF2000, ITRF-97, ...: the letters, then digits and at most one '-'.
  if (name.substr(0, 4) != "ITRF") return std::nullopt;
  const std::string_view tail = name.substr(4);
  const bool tail_ok = std::all_of(tail.begin(), tail.end(),
                                   [](char c) { return (c >= '0' && c <= '9') || c == '-'; }) &&
                       std::count(tail.begin(), tail.end(), '-') <= 1 &&
                       (tail.empty() || tail.back() != '-');
  if (!tail_ok) return std::nullopt;
  return reference_frame::itrf;
}

cartesian_state to_tod(const rotation_to_tod& rotation, const cartesian_state& source) noexcept {
  const double w = rotation.spin_rad_s;
  const vec3<double> spin_cross_r(-w * source.r_m.y, w * source.r_m.x, 0.0);
  return cartesian_state{apply(rotation.tod_from_source, source.r_m),
                         apply(rotation.tod_from_source, source.v_m_s + spin_cross_r)};
}

rotation_to_tod scene_rotations::of(reference_frame frame) const noexcept {
  switch (frame) {
    case reference_frame::tod:
      return {};
    case reference_frame::teme:
      return {tod_from_teme, 0.0};
    case reference_frame::eme2000:
      return {tod_from_eme2000, 0.0};
    case reference_frame::gcrf:
    case reference_frame::icrf:
      return {tod_from_gcrf, 0.0};
    case reference_frame::itrf:
      return {about_z(gast_rad), earth_rotation_rate_rad_s};
  }
  return {};
}

scene_rotations scene_rotations_at(const julian_date& tt, const julian_date& ut1) noexcept {
  // eraPnm06a and eraEe06a each evaluate the nutation series (the whole cost): once here.
  double dpsi = 0, deps = 0, epsa = 0;
  eraNut06a(tt.jd1, tt.jd2, &dpsi, &deps);
  double rb[3][3], rp[3][3], rbp[3][3], rn[3][3], rbpn[3][3], np[3][3];
  eraPn06(tt.jd1, tt.jd2, dpsi, deps, &epsa, rb, rp, rbp, rn, rbpn);
  eraRxr(rn, rp, np);
  scene_rotations r;
  r.tod_from_gcrf = from_erfa(rbpn);
  r.tod_from_eme2000 = from_erfa(np);
  // eraEe06a is eraAnpm(eraEe00(tt, eraObl06(tt), dpsi)), and eraObl06 is eraPn06's epsa.
  r.equation_of_equinoxes_rad = eraAnpm(eraEe00(tt.jd1, tt.jd2, epsa, dpsi));
  r.tod_from_teme = about_z(r.equation_of_equinoxes_rad);
  // eraGst06a is eraGst06 with eraPnm06a's matrix, which is this rbpn.
  r.gast_rad = eraGst06(ut1.jd1, ut1.jd2, tt.jd1, tt.jd2, rbpn);
  return r;
}

scene_rotations scene_rotations_at(const instant& t, double ut1_minus_utc_s) noexcept {
  return scene_rotations_at(tt_julian_date(t), ut1_julian_date(t, ut1_minus_utc_s));
}

double rotation_angle_rad(const mat3<double>& m) noexcept {
  // sin(angle) |axis| from the antisymmetric part, cos(angle) from the trace.
  const vec3<double> axis_part(m[1][2] - m[2][1], m[2][0] - m[0][2], m[0][1] - m[1][0]);
  const double trace = m[0][0] + m[1][1] + m[2][2];
  return std::atan2(0.5 * norm(axis_part), 0.5 * (trace - 1.0));
}

checked<frame_track> frame_track::over(const instant& t0, const instant& t1,
                                       double ut1_minus_utc_s) {
  if (checked<void> e = check_in_utc_table(t0, t1); !e.ok()) return e.error();
  if (t1 < t0) return diagnostic{{}, "frame track: the span ends before it starts"};
  frame_track track;
  track.ut1_minus_utc_s_ = ut1_minus_utc_s;
  track.first_node_ = add_seconds(t0, -frame_track_node_spacing_s);
  const double span_s = seconds_between(t0, t1);
  const std::size_t count = nodes_covering(span_s, frame_track_node_spacing_s);
  track.nodes_.resize(count);
  const julian_date first_ut1 = ut1_julian_date(track.first_node_, ut1_minus_utc_s);
  for (std::size_t k = 0; k < count; ++k) {
    const instant at =
        add_seconds(track.first_node_, static_cast<double>(k) * frame_track_node_spacing_s);
    const julian_date ut1 = ut1_julian_date(at, ut1_minus_utc_s);
    const scene_rotations r = scene_rotations_at(tt_julian_date(at), ut1);
    node& n = track.nodes_[k];
    n.tod_from_gcrf = r.tod_from_gcrf;
    n.tod_from_eme2000 = r.tod_from_eme2000;
    n.tod_from_teme = r.tod_from_teme;
    n.ut1_s = ut1_seconds_between(first_ut1, ut1);
    // GAST - w u is -EO(TT) plus a constant (ERA is linear in UT1 at exactly w): smooth in time
    // whatever UTC does; unwrapped against the node before.
    double slow = r.gast_rad - earth_rotation_rate_rad_s * n.ut1_s;
    if (k > 0) slow -= two_pi * std::round((slow - track.nodes_[k - 1].gast_slow_rad) / two_pi);
    n.gast_slow_rad = slow;
  }
  return track;
}

rotation_to_tod frame_track::at(reference_frame frame, const instant& t) const noexcept {
  if (frame == reference_frame::tod) return {};
  const double x = seconds_between(first_node_, t) / frame_track_node_spacing_s;
  const cubic_window c = cubic_window_at(x, nodes_.size());
  const node* n = nodes_.data() + c.first;
  if (frame == reference_frame::itrf) {
    double slow = 0;
    for (int j = 0; j < 4; ++j) slow += c.weight[j] * n[j].gast_slow_rad;
    // UT1 seconds from the first node: linear within the interval that holds t (exact for the
    // drift of TAI - UTC before 1972), ERFA's own where UTC steps inside it.
    const auto first = static_cast<double>(c.first);
    const double interval = std::clamp(std::floor(x), first, first + 2.0);
    const node& left = nodes_[static_cast<std::size_t>(interval)];
    const node& right = nodes_[static_cast<std::size_t>(interval) + 1];
    const double ut1_step_s = right.ut1_s - left.ut1_s;
    double ut1_s = 0;
    if (std::abs(ut1_step_s - frame_track_node_spacing_s) > ut1_step_threshold_s) {
      const julian_date first_ut1 = ut1_julian_date(first_node_, ut1_minus_utc_s_);
      ut1_s = ut1_seconds_between(first_ut1, ut1_julian_date(t, ut1_minus_utc_s_));
    } else {
      ut1_s = left.ut1_s + (x - interval) * ut1_step_s;
    }
    return {about_z(slow + earth_rotation_rate_rad_s * ut1_s), earth_rotation_rate_rad_s};
  }
  mat3<double> m(0.0);
  for (int j = 0; j < 4; ++j) {
    const mat3<double>& node_matrix = frame == reference_frame::teme      ? n[j].tod_from_teme
                                      : frame == reference_frame::eme2000 ? n[j].tod_from_eme2000
                                                                          : n[j].tod_from_gcrf;
    m += node_matrix * c.weight[j];
  }
  return {m, 0.0};
}

}  // namespace conescan::sources

#include "sources/sun_moon.hpp"

#include <erfa.h>
#include <erfam.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "sources/scene_frame.hpp"
#include "sources/uniform_nodes.hpp"

namespace conescan::sources {

namespace {

/// ERFA's light time for one au (s) as a fraction of a day, and its au in metres.
constexpr double light_days_per_au = ERFA_AULT / ERFA_DAYSEC;
constexpr double metres_per_au = ERFA_DAU;

vec3<double> from_erfa(const double p[3]) noexcept {
  return vec3<double>(p[0], p[1], p[2]);
}

/// The geocentric Sun (au, GCRS axes), retarded and aberrated (sun_moon.hpp's method).
vec3<double> apparent_sun_au(const julian_date& tt) noexcept {
  double earth_helio[2][3], earth_bary[2][3];  // au, au/day
  eraEpv00(tt.jd1, tt.jd2, earth_helio, earth_bary);
  const double distance_au = std::sqrt(eraPdp(earth_helio[0], earth_helio[0]));
  // The Sun's barycentric velocity is the Earth's barycentric minus heliocentric velocity.
  const double light_time_days = distance_au * light_days_per_au;
  double sun[3];
  for (int k = 0; k < 3; ++k)
    sun[k] = -earth_helio[0][k] - light_time_days * (earth_bary[1][k] - earth_helio[1][k]);
  double direction[3], earth_velocity_c[3], apparent[3];
  double sun_distance_au = 0;
  eraPn(sun, &sun_distance_au, direction);
  for (int k = 0; k < 3; ++k) earth_velocity_c[k] = earth_bary[1][k] * light_days_per_au;
  const double inverse_lorentz = std::sqrt(1.0 - eraPdp(earth_velocity_c, earth_velocity_c));
  eraAb(direction, earth_velocity_c, sun_distance_au, inverse_lorentz, apparent);
  return from_erfa(apparent) * sun_distance_au;
}

/// The geocentric Moon (au, GCRS axes) at the time its light left it.
vec3<double> apparent_moon_au(const julian_date& tt) noexcept {
  double pv[2][3];  // au, au/day
  eraMoon98(tt.jd1, tt.jd2, pv);
  const double light_time_days = std::sqrt(eraPdp(pv[0], pv[0])) * light_days_per_au;
  return from_erfa(pv[0]) - from_erfa(pv[1]) * light_time_days;
}

std::string span_message() {
  return "the Sun and Moon ephemerides (eraEpv00, eraMoon98) are taken for TT "
         "1950-01-01T00:00 to 2100-01-01T12:00";
}

bool in_span(const julian_date& tt) noexcept {
  const double jd = tt.jd1 + tt.jd2;
  return jd >= sun_moon_first_jd_tt && jd < sun_moon_end_jd_tt;
}

}  // namespace

checked<sun_moon_positions> sun_moon_at(const julian_date& tt, const mat3<double>& tod_from_gcrf) {
  if (!in_span(tt)) {
    return diagnostic{{}, "epoch outside the ephemerides' span: " + span_message()};
  }
  return sun_moon_positions{apparent_sun_tod_m(tt, tod_from_gcrf),
                            apply(tod_from_gcrf, apparent_moon_au(tt) * metres_per_au)};
}

vec3<double> apparent_sun_tod_m(const julian_date& tt, const mat3<double>& tod_from_gcrf) noexcept {
  return apply(tod_from_gcrf, apparent_sun_au(tt) * metres_per_au);
}

checked<sun_moon_positions> sun_moon_at(const instant& t) {
  const julian_date tt = tt_julian_date(t);
  return sun_moon_at(tt, scene_rotations_at(tt, ut1_julian_date(t, 0.0)).tod_from_gcrf);
}

body_view view_from(const vec3<double>& body_tod_m, double radius_m,
                    const vec3<double>& satellite_tod_m) noexcept {
  const vec3<double> line = body_tod_m - satellite_tod_m;
  const double distance = norm(line);
  if (!(distance > radius_m)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {vec3<double>(nan), distance, nan};
  }
  return {line / distance, distance, std::asin(radius_m / distance)};
}

checked<void> sun_moon_track::check_span(const instant& t0, const instant& t1) {
  if (checked<void> e = check_in_utc_table(t0, t1); !e.ok()) return e.error();
  if (t1 < t0) return diagnostic{{}, "Sun and Moon track: the span ends before it starts"};
  const instant first = add_seconds(t0, -sun_moon_track_node_spacing_s);
  const std::size_t count = nodes_covering(seconds_between(t0, t1), sun_moon_track_node_spacing_s);
  const instant last =
      add_seconds(first, static_cast<double>(count - 1) * sun_moon_track_node_spacing_s);
  if (!in_span(tt_julian_date(first)) || !in_span(tt_julian_date(last)))
    return diagnostic{{},
                      "span " + format_utc(t0, 3) + " to " + format_utc(t1, 3) +
                          " UTC: its Sun and Moon track runs from " + format_utc(first, 0) +
                          " to " + format_utc(last, 0) + " UTC, and " + span_message()};
  return success();
}

checked<sun_moon_track> sun_moon_track::over(const instant& t0, const instant& t1) {
  if (checked<void> e = check_span(t0, t1); !e.ok()) return e.error();
  sun_moon_track track;
  track.first_node_ = add_seconds(t0, -sun_moon_track_node_spacing_s);
  const double span_s = seconds_between(t0, t1);
  const std::size_t count = nodes_covering(span_s, sun_moon_track_node_spacing_s);
  track.nodes_.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    const instant node =
        add_seconds(track.first_node_, static_cast<double>(k) * sun_moon_track_node_spacing_s);
    checked<sun_moon_positions> p = sun_moon_at(node);
    if (!p.ok())
      return diagnostic{
          {},
          "span " + format_utc(t0, 3) + " to " + format_utc(t1, 3) + " UTC: " + p.error().message};
    track.nodes_.push_back(p.value());
  }
  return track;
}

sun_moon_positions sun_moon_track::at(const instant& t) const noexcept {
  const double x = seconds_between(first_node_, t) / sun_moon_track_node_spacing_s;
  const cubic_window c = cubic_window_at(x, nodes_.size());
  const sun_moon_positions* n = nodes_.data() + c.first;
  sun_moon_positions p;
  for (int j = 0; j < 4; ++j) {
    p.sun_tod_m += n[j].sun_tod_m * c.weight[j];
    p.moon_tod_m += n[j].moon_tod_m * c.weight[j];
  }
  return p;
}

}  // namespace conescan::sources

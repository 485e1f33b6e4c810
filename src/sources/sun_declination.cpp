#include "sources/sun_declination.hpp"

#include <erfa.h>
#include <erfam.h>

#include <algorithm>
#include <cmath>

namespace conescan::sources {

double apparent_sun_declination_rad(const julian_date& tt) noexcept {
  double earth_helio[2][3], earth_bary[2][3];  // au, au/day
  eraEpv00(tt.jd1, tt.jd2, earth_helio, earth_bary);
  // Geocentric Sun at the time its light left it: the Sun's barycentric velocity is the Earth's
  // barycentric minus heliocentric velocity.
  const double distance_au = std::sqrt(eraPdp(earth_helio[0], earth_helio[0]));
  const double light_time_days = distance_au * ERFA_AULT / ERFA_DAYSEC;
  double sun[3];
  for (int k = 0; k < 3; ++k) {
    const double sun_velocity = earth_bary[1][k] - earth_helio[1][k];
    sun[k] = -earth_helio[0][k] - light_time_days * sun_velocity;
  }
  double direction[3], earth_velocity_c[3], apparent[3], of_date[3];
  double norm = 0;
  eraPn(sun, &norm, direction);
  for (int k = 0; k < 3; ++k) earth_velocity_c[k] = earth_bary[1][k] * ERFA_AULT / ERFA_DAYSEC;
  const double bm1 = std::sqrt(1.0 - eraPdp(earth_velocity_c, earth_velocity_c));
  eraAb(direction, earth_velocity_c, norm, bm1, apparent);
  double bias_precession_nutation[3][3];
  eraPnm06a(tt.jd1, tt.jd2, bias_precession_nutation);
  eraRxp(bias_precession_nutation, apparent, of_date);
  return std::atan2(of_date[2], std::hypot(of_date[0], of_date[1]));
}

double sun_declination_rad(const instant& t) noexcept {
  return apparent_sun_declination_rad(tt_julian_date(t));
}

checked<sun_declination_track> sun_declination_track::over(const instant& t0, const instant& t1) {
  if (checked<void> e = check_in_utc_table(t0, t1); !e.ok()) return e.error();
  sun_declination_track track;
  track.first_node_ = add_seconds(t0, -sun_track_node_spacing_s);
  const double span_s = std::max(0.0, seconds_between(t0, t1));
  // One node before t0, enough to pass t1 by one, and at least the four the cubic takes (a span
  // of length 0 would otherwise get three: found by AddressSanitizer).
  const auto nodes = std::max<std::size_t>(
      4, static_cast<std::size_t>(std::ceil(span_s / sun_track_node_spacing_s)) + 3);
  track.declination_rad_.reserve(nodes);
  for (std::size_t k = 0; k < nodes; ++k) {
    const instant node =
        add_seconds(track.first_node_, static_cast<double>(k) * sun_track_node_spacing_s);
    track.declination_rad_.push_back(sun_declination_rad(node));
  }
  return track;
}

double sun_declination_track::at(const instant& t) const noexcept {
  // Four nodes around t: k-1, k, k+1, k+2 with t in [node k, node k+1], clamped to the table.
  const double x = seconds_between(first_node_, t) / sun_track_node_spacing_s;
  const auto last_start = static_cast<double>(declination_rad_.size() - 4);
  const double start = std::clamp(std::floor(x) - 1.0, 0.0, last_start);
  const auto k = static_cast<std::size_t>(start);
  const double u = x - start;  // in node units from node k: nodes at 0, 1, 2, 3
  const double* d = declination_rad_.data() + k;
  return -d[0] * (u - 1) * (u - 2) * (u - 3) / 6 + d[1] * u * (u - 2) * (u - 3) / 2 -
         d[2] * u * (u - 1) * (u - 3) / 2 + d[3] * u * (u - 1) * (u - 2) / 6;
}

}  // namespace conescan::sources

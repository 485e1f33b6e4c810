#include "calibration/scene_geometry.hpp"

#include <cmath>

#include "conescan/attitude.hpp"
#include "orbit/kepler.hpp"
#include "orbit/wgs84.hpp"
#include "scene/degrees.hpp"

using conescan::scene::deg_to_rad_reduced;

namespace conescan::calibration {

checked<std::vector<row_truth>> scene_truth_at(const scene::scene_config& scene,
                                               std::span<const double> times_s) {
  // The orbit as simulation::simulation builds it (SPEC §3); to be replaced by the scene layer's
  // truth_at(t_s) when it lands (see the header).
  const orbit::earth_constants& w = orbit::wgs84();
  const orbit::elements elements{scene.a_km * 1000,
                                 scene.e,
                                 deg_to_rad(scene::effective_inclination_deg(scene)),
                                 deg_to_rad_reduced(scene.raan_deg),
                                 deg_to_rad_reduced(scene.argp_deg),
                                 deg_to_rad_reduced(scene.m0_deg)};
  const orbit::kepler_orbit kepler(elements,
                                   scene.j2
                                       ? orbit::j2_secular_rates(elements, w.gm_m3_s2, w.j2, w.a_m)
                                       : orbit::two_body_rates(elements, w.gm_m3_s2),
                                   w.gm_m3_s2);
  const mat3<double> body_from_orbit =
      dcm_body_from_orbit(deg_to_rad_reduced(scene.roll_deg), deg_to_rad(scene.pitch_deg),
                          deg_to_rad_reduced(scene.yaw_deg));
  const double sun_declination_rad = deg_to_rad(scene.sun_declination_deg.value_or(0));
  std::vector<row_truth> out(times_s.size());
  std::vector<orbit::orbit_state> states(times_s.size());
  kepler.states_at(times_s.data(), states.data(), times_s.size());
  for (std::size_t i = 0; i < times_s.size(); ++i)
    out[i] = {states[i].r_eci_m, states[i].v_eci_m_s, body_from_orbit, sun_declination_rad};
  return out;
}

}  // namespace conescan::calibration

#include "scene_calibration/scene_model.hpp"

#include "conescan/orbital_frame.hpp"
#include "conescan/scan_frame.hpp"
#include "orbit/wgs84.hpp"
#include "scene/degrees.hpp"
#include "scene/scene_earth.hpp"

namespace conescan::calibration {

checked<scene_model> scene_model::of(const scene::scene_config& scene,
                                     std::span<const double> times_s) {
  if (scene.model == scene::forward_model::bias)
    return diagnostic{"model",
                      "the calibration fits the scan model (MODEL §11): give --model scan (and "
                      "simulate the telemetry with it)"};
  checked<std::vector<row_truth>> truth = scene_truth_at(scene, times_s);
  if (!truth.ok()) return std::move(truth).error();
  scene_model m;
  m.ellipsoid_ = scene.earth == scene::earth_model::wgs84;
  m.sphere_radius_m_ = scene::truth_radius_m(scene);
  m.equatorial_m_ = orbit::wgs84().a_m;
  // horizon_polar_radius_m without the horizon terms, which the parameters supply.
  m.polar_m_ =
      scene::horizon_polar_radius_m(scene) - (scene.horizon_km + scene.horizon_pole_km) * 1000;
  std::vector<scan_frame<double>> frames;
  for (const scene::head_config& h : scene.heads) {
    m.gamma_rad_.push_back(deg_to_rad(h.gamma_deg));
    frames.push_back(
        scan_frame_from_mounting(deg_to_rad(h.alpha_deg), scene::deg_to_rad_reduced(h.beta_deg)));
  }
  const std::size_t heads = frames.size();
  m.rows_.reserve(times_s.size());
  m.views_.reserve(times_s.size() * heads);
  for (const row_truth& t : truth.value()) {
    m.rows_.push_back({norm(t.r_eci_m), std::sin(t.sun_declination_rad)});
    // Body axes from ECI through the orbital frame (MODEL §2) and the reference attitude.
    const mat3<double> eci_from_orbit = dcm_eci_from_orbit(t.r_eci_m, t.v_eci_m_s);
    auto to_body = [&](const vec3<double>& v) {
      return apply(t.body_from_orbit, apply_transpose(eci_from_orbit, v));
    };
    const vec3<double> nadir_body = apply(t.body_from_orbit, vec3<double>(0, 0, 1));
    const vec3<double> position_body = to_body(t.r_eci_m);
    const vec3<double> polar_body = to_body(vec3<double>(0, 0, 1));
    for (const scan_frame<double>& f : frames) {
      auto in_scan = [&](const vec3<double>& v) {
        return vec3<double>(dot(f.e1, v), dot(f.e2, v), dot(f.e3, v));
      };
      m.views_.push_back({in_scan(nadir_body), in_scan(position_body), in_scan(polar_body)});
    }
  }
  return m;
}

parameter_set scene_parameters(const scene::scene_config& scene) {
  parameter_set p = parameter_set::nominal(scene.heads.size());
  for (std::size_t k = 0; k < scene.heads.size(); ++k) {
    const scene::head_config& h = scene.heads[k];
    p.value(k, head_parameter::sigma) = h.sigma_deg;
    p.value(k, head_parameter::phase) = h.phase_deg;
    p.value(k, head_parameter::dgamma) = h.dgamma_deg;
    p.value(k, head_parameter::bias_in) = h.bias_in_deg;
    p.value(k, head_parameter::bias_out) = h.bias_out_deg;
  }
  p.value(earth_parameter::horizon) = scene.horizon_km;
  p.value(earth_parameter::horizon_pole) = scene.horizon_pole_km;
  p.value(earth_parameter::horizon_shift) = scene.horizon_shift_km;
  return p;
}

std::vector<head_noise> scene_noise(const scene::scene_config& scene) {
  std::vector<head_noise> out;
  for (const scene::head_config& h : scene.heads) out.push_back({h.noise_deg, h.lsb_deg});
  return out;
}

}  // namespace conescan::calibration

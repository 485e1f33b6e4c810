// Fuzz harnesses of what users type: a head spec (parse_head_spec), and the whole simulation of
// any scene that passes validate(): no crash, and no number where a status says the head could
// not measure, no NaN where it says ok. Shared by the fuzz targets and
// tests/apps/test_robustness.cpp.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

#include "scene/head_spec.hpp"
#include "scene/loaded_scene.hpp"
#include "scene/scene_config.hpp"
#include "scene/scene_validation.hpp"
#include "simulation/simulation.hpp"

namespace conescan_fuzz {

namespace detail {

inline bool finite(double x) {
  return std::isfinite(x);
}

inline std::string row_failure(const conescan::scene::scene_config& s, std::uint64_t k,
                               const std::string& what) {
  std::string heads;
  for (const auto& h : s.heads) heads += " --head " + conescan::scene::format_head_spec(h);
  return "scene row k=" + std::to_string(k) + ": " + what + " (a-km " + std::to_string(s.a_km) +
         ", e " + std::to_string(s.e) + ", model " +
         (s.model == conescan::scene::forward_model::bias ? "bias" : "scan") + ", earth " +
         (s.earth == conescan::scene::earth_model::sphere ? "sphere" : "wgs84") + heads + ")";
}

}  // namespace detail

/// Simulates rows 0, 1, the middle one and the last of a scene that validate() accepted, and
/// checks every row: the orbit columns finite, rho_p in (0, 90 deg], each head's numbers finite
/// with the chord in (0, 360 deg) when its status is ok and NaN otherwise, and the same for the
/// system solution.
inline std::string check_scene_rows(const conescan::scene::loaded_scene& s) {
  using conescan::status;
  using detail::finite;
  const conescan::scene::simulation sim = conescan::scene::simulation::of(s).value();
  conescan::scene::row r = sim.make_row();
  const std::uint64_t n = sim.rows();
  const std::uint64_t picks[] = {0, 1, n / 2, n - 1};
  const double pi = conescan::pi<double>();
  for (const std::uint64_t k : picks) {
    if (k >= n) continue;
    sim.compute(k, r);
    auto fail = [&](const std::string& what) { return detail::row_failure(s.config, k, what); };
    if (!(finite(r.t_s) && r.t_s >= 0)) return fail("t_s not finite");
    if (!(finite(r.true_anomaly_rad) && finite(r.r_m) && r.r_m > 0 && finite(r.alt_m) &&
          finite(r.lat_rad) && std::abs(r.lat_rad) <= pi / 2))
      return fail("orbit columns (nu, r, alt, lat) not finite or out of range");
    if (!(finite(r.rho_p_rad) && r.rho_p_rad > 0 && r.rho_p_rad <= pi / 2))
      return fail("rho_p not in (0, 90 deg]");
    for (std::size_t h = 0; h < r.heads.size(); ++h) {
      const conescan::scene::head_row& hr = r.heads[h];
      const double numbers[] = {hr.chord_rad, hr.phase_rad, hr.eta_err_rad, hr.roll_err_rad,
                                hr.pitch_err_rad};
      for (std::size_t i = 0; i < std::size(numbers); ++i) {
        const double x = numbers[i];
        // gimbal (MODEL §7): the measurement and the nadir error stand, roll and pitch do not.
        const bool measured = hr.state == status::ok || (hr.state == status::gimbal && i < 3);
        if (measured && !finite(x))
          return fail("head " + std::to_string(h + 1) + " is " + conescan::to_string(hr.state) +
                      " but has a non-finite number");
        if (!measured && !std::isnan(x))
          return fail("head " + std::to_string(h + 1) + " is " + conescan::to_string(hr.state) +
                      " but has a number");
      }
      if (hr.state == status::ok && !(hr.chord_rad > 0 && hr.chord_rad < 2 * pi))
        return fail("head " + std::to_string(h + 1) + " chord outside (0, 360 deg)");
      if (hr.state == status::none) return fail("a head has the system status none");
    }
    if (r.state == status::ok && !(finite(r.roll_err_rad) && finite(r.pitch_err_rad)))
      return fail("system ok but roll/pitch not finite");
    if (r.state != status::ok && !(std::isnan(r.roll_err_rad) && std::isnan(r.pitch_err_rad)))
      return fail("system not ok but has numbers");
    // MODEL §6's mean is ok or none (gimbal where roll is undefined, MODEL §7); the
    // horizon-vector fit may also be fold or invalid.
    const bool fit = s.config.processing == conescan::scene::processing_method::horizon_vector;
    if (r.state != status::ok && r.state != status::none && r.state != status::gimbal &&
        !(fit && (r.state == status::fold || r.state == status::invalid)))
      return fail("system status neither ok, none nor gimbal (nor fold or invalid of the fit)");
  }
  return {};
}

/// parse_head_spec on any text: no crash; a parsed head formats and parses back to the same
/// values; a head that validates in the paper's scene simulates (check_scene_rows) with the
/// bias model, the scan model on the sphere and the scan model on WGS84.
inline std::string check_head_spec(const std::uint8_t* data, std::size_t size) {
  namespace sc = conescan::scene;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto parsed = sc::parse_head_spec(text);
  if (!parsed.ok()) {
    if (parsed.error().message.empty()) return "parse_head_spec: empty error message";
    return {};
  }
  const sc::head_config head = parsed.value();
  const std::string canonical = sc::format_head_spec(head);
  const auto again = sc::parse_head_spec(canonical);
  if (!again.ok()) return "format_head_spec gives text that does not parse: " + canonical;
  const sc::head_config back = again.value();
  auto same = [](double a, double b) {
    return (std::isnan(a) && std::isnan(b)) || (a == b && std::signbit(a) == std::signbit(b));
  };
  if (!(same(head.alpha_deg, back.alpha_deg) && same(head.beta_deg, back.beta_deg) &&
        same(head.gamma_deg, back.gamma_deg) && same(head.sigma_deg, back.sigma_deg) &&
        same(head.phase_deg, back.phase_deg) && same(head.noise_deg, back.noise_deg) &&
        same(head.lsb_deg, back.lsb_deg) && same(head.dgamma_deg, back.dgamma_deg) &&
        same(head.bias_in_deg, back.bias_in_deg) && same(head.bias_out_deg, back.bias_out_deg) &&
        same(head.fov_deg, back.fov_deg) && head.shape == back.shape &&
        same(head.spin_hz, back.spin_hz) && same(head.tau_ms, back.tau_ms) &&
        head.locator == back.locator && same(head.threshold, back.threshold)))
    return "head spec does not round-trip: " + canonical;

  sc::scene_config scene;
  scene.heads = {head};
  for (int variant = 0; variant < 3; ++variant) {
    scene.model = variant == 0 ? sc::forward_model::bias : sc::forward_model::scan;
    scene.earth = variant == 2 ? sc::earth_model::wgs84 : sc::earth_model::sphere;
    const conescan::checked<sc::loaded_scene> loaded = sc::load_scene(scene);
    if (!loaded.ok() || !sc::validate(loaded.value()).ok()) continue;
    if (std::string f = check_scene_rows(loaded.value()); !f.empty()) return f;
  }
  return {};
}

}  // namespace conescan_fuzz

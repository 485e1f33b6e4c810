#include "scene/source_files.hpp"

#include <cmath>

#include "orbit/wgs84.hpp"

namespace conescan::scene {

bool orbit_from_file(const scene_config& s) noexcept {
  return !s.tle_file.empty() || !s.omm_file.empty() || !s.oem_file.empty();
}

const char* orbit_source_option(const scene_config& s) noexcept {
  return !s.tle_file.empty()   ? "tle"
         : !s.omm_file.empty() ? "omm"
         : !s.oem_file.empty() ? "oem"
                               : "";
}

const std::string& orbit_source_file(const scene_config& s) noexcept {
  return !s.tle_file.empty() ? s.tle_file : !s.omm_file.empty() ? s.omm_file : s.oem_file;
}

bool attitude_from_file(const scene_config& s) noexcept {
  return !s.aem_file.empty() || !s.attitude_csv_file.empty();
}

osculating_elements osculating_of(const vec3<double>& r, const vec3<double>& v) noexcept {
  const double mu = orbit::wgs84().gm_m3_s2;
  const double r_norm = norm(r);
  const vec3<double> h = cross(r, v);
  // Eccentricity vector (Laplace-Runge-Lenz / mu) and vis-viva.
  const vec3<double> e_vec = cross(v, h) / mu - r / r_norm;
  const double a = 1.0 / (2.0 / r_norm - dot(v, v) / mu);
  const double sin_nu = dot(cross(e_vec, r), h) / norm(h);
  const double cos_nu = dot(e_vec, r);
  return {a, norm(e_vec), std::atan2(sin_nu, cos_nu)};
}

}  // namespace conescan::scene

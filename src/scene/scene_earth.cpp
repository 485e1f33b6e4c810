#include "scene/scene_earth.hpp"

#include "orbit/geodetic.hpp"
#include "orbit/wgs84.hpp"

namespace conescan::scene {

double truth_radius_m(const scene_config& s) {
  if (s.earth == earth_model::wgs84) return orbit::wgs84().a_m;
  return s.radius_km ? *s.radius_km * 1000 : orbit::wgs84().a_m;
}

double horizon_polar_radius_m(const scene_config& s) {
  const orbit::earth_constants& w = orbit::wgs84();
  return (s.geodetic_flattening ? w.b_m : w.a_m) + s.horizon_km * 1000 + s.horizon_pole_km * 1000;
}

double default_processing_radius_m(const scene_config& s) {
  return truth_radius_m(s);
}

double processing_sphere::radius_at(const vec3<double>& r_eci) const noexcept {
  return kind == processing_radius_kind::local ? orbit::wgs84_radius_along(r_eci) : radius_m;
}

processing_sphere processing_sphere_of(const scene_config& s) {
  switch (s.processing_radius) {
    case processing_radius_kind::truth:
      return {s.processing_radius, default_processing_radius_m(s)};
    case processing_radius_kind::value:
      return {s.processing_radius, s.processing_radius_km * 1000};
    case processing_radius_kind::equatorial:
    case processing_radius_kind::local:
      break;
  }
  return {s.processing_radius, orbit::wgs84().a_m};
}

}  // namespace conescan::scene

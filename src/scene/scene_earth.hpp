// The Earth of a scene, each rule in one place (MODEL §3, §6): the truth surface's radii and the
// sphere the processing assumes. The validation (loaded_scene.cpp), the per-row pipeline
// (simulation.cpp) and the error budget (budget.cpp) all ask these functions.
#pragma once

#include "conescan/vector.hpp"
#include "scene/scene_config.hpp"

namespace conescan::scene {

/// The truth's equatorial radius without the horizon (m): the sphere's R (--radius-km, default
/// WGS84 a) on --earth sphere, WGS84 a on wgs84 (MODEL §3).
double truth_radius_m(const scene_config& scene);

/// The truth horizon surface's polar semi-axis (m): WGS84 b (or a, when the budget switches the
/// geodetic flattening off) + horizon-km + horizon-pole-km (the apparent surface; MODEL §3's
/// inflated ellipsoid when horizon-pole-km is 0). Meaningful on wgs84.
double horizon_polar_radius_m(const scene_config& scene);

/// The radius of the sphere the processing assumes by default (`--processing-radius` not given,
/// MODEL §6): the truth sphere's R on --earth sphere, WGS84 a on wgs84, i.e. truth_radius_m.
double default_processing_radius_m(const scene_config& scene);

/// The sphere the processing assumes (MODEL §6), without its horizon height.
struct processing_sphere {
  processing_radius_kind kind;
  /// Its radius (m) for every kind but local; for local, its largest value (WGS84 a).
  double radius_m;
  /// The radius (m) for a satellite at r_eci: the WGS84 radius along r for local (MODEL §6).
  double radius_at(const vec3<double>& r_eci) const noexcept;
};

processing_sphere processing_sphere_of(const scene_config& scene);

}  // namespace conescan::scene

// The per-source error budget (--budget): the scene once per error source switched on
// alone, and once with all of them.
#pragma once

#include <string>
#include <vector>

#include "scene/scene_config.hpp"

namespace conescan::scene {

/// The name of the budget's source with every source on (the last one; the others are summed).
inline constexpr const char* budget_all_name = "all";

/// One run of the budget: a source's name ("misalignment", ..., "all") and its scene.
struct budget_source {
  std::string name;
  scene_config scene;
};

/// The sources that are on in `all`, each alone, then `all` itself (named "all"). Every run uses
/// the scan model. "Alone" means the truth equals what the processing assumes except for that
/// source:
///   misalignment   sigma as given, truth = the processing's sphere (WGS84 a + h0, or the given
///                  processing radius), no noise or quantisation;
///   head-biases    each head's dgamma, bias-in and bias-out as given, sigma = 0;
///   oblateness     the inflated WGS84 ellipsoid (a + h0, b + h0), sigma = 0, processing as given;
///   horizon-height the truth sphere at h0, processing at --processing-horizon-km;
///   horizon-pole   a sphere of radius a + h0 with its pole lowered by horizon-pole-km;
///   horizon-season the same sphere, its centre shifted by horizon-shift-km sin(declination);
///   field-of-view  each head's fov= and fov-shape= on the radiance profile's scale height
///                  (MODEL §12; the normalised locator at 1/2, the 50 % point on the horizon);
///   detector-lag   each head's spin-hz= and tau-ms= on the same profile;
///   radiance       the profile as given (its 50 % point's offset, the disk, the season term) and
///                  each head's locator= and threshold=, a pencil beam without lag: the height a
///                  head cuts the pulse at and its variation (the season term with a fixed
///                  threshold);
///   noise          detector noise only;  quantisation  telemetry steps only.
/// A source that is off in `all` (sigma = 0 on every head, no head bias, sphere truth, processing
/// horizon = h0, no pole or shift term, no field, no lag, the radiance and locator at their
/// defaults, no noise, no steps) is left out. The physics is off in every other source. Every
/// source's scene is validated: a scene that validates alone may not as a source (a small sphere's
/// orbit below WGS84 a, which the oblateness source puts under it); the error names
/// --budget and the source.
checked<std::vector<budget_source>> budget_sources(const scene_config& all);

}  // namespace conescan::scene

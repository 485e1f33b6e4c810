// The per-source error budget (--budget): the scene once per error source switched on
// alone, and once with all of them.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "scene/loaded_scene.hpp"
#include "scene/scene_config.hpp"

namespace conescan::scene {

/// The name of the budget's source with every source on (the last one; the others are summed).
inline constexpr const char* budget_all_name = "all";

/// One run of the budget: a source's name ("misalignment", ..., "all") and its scene. A source
/// with a baseline is measured from it: its errors are its scene's less the baseline source's,
/// row by row (the sensor physics on a limb the processing does not assume: the limb's own error
/// is the baseline's, and what is left is the source's).
struct budget_source {
  std::string name;
  loaded_scene scene;                   ///< with the user's scene's files
  std::optional<std::size_t> baseline;  ///< an index into the list, before this source
};

/// The sources that are on in `all`, each alone, then `all` itself (named "all"). Every run uses
/// the scan model. "Alone" means the truth equals what the processing assumes except for that
/// source:
///   misalignment   sigma as given, truth = the processing's sphere (WGS84 a + h0, or the given
///                  processing radius), no noise or quantisation;
///   head-biases    each head's dgamma, bias-in and bias-out as given, sigma = 0;
///   oblateness     the inflated WGS84 ellipsoid (a + h0, b + h0), sigma = 0, processing as given;
///   horizon-height the user's limb on a pencil beam without lag against the horizon the
///                  processing assumes: the truth's surface at h0, the processing at
///                  --processing-horizon-km, and with the physics the radiance profile (its 50 %
///                  point's offset, H, the disk, the season term) and each head's locator= and
///                  threshold= (where the heads see the horizon: one source, the height and the
///                  radiance's shape together, so the two never cancel as two);
///   horizon-pole   a sphere of radius a + h0 with its pole lowered by horizon-pole-km;
///   horizon-season the same sphere, its centre shifted by horizon-shift-km sin(declination);
///   field-of-view  each head's fov= and fov-shape= on the user's limb (MODEL §12): the
///                  horizon-height source's scene with the field, measured from that source when
///                  it is on (its baseline);
///   detector-lag   each head's spin-hz= and tau-ms= on the user's limb, the same way;
///   noise          detector noise only;  quantisation  telemetry steps only.
/// A source that is off in `all` (sigma = 0 on every head, no head bias, sphere truth, processing
/// horizon = h0 and the radiance and locator at their defaults, no pole or shift term, no field,
/// no lag, no noise, no steps) is left out. The physics is off in every other source (they are
/// geometry: MODEL §5's crossings). Every source's scene is validated: a scene that validates
/// alone may not as a source (a small sphere's orbit below WGS84 a, which the oblateness source
/// puts under it); the error names --budget and the source.
checked<std::vector<budget_source>> budget_sources(const loaded_scene& all);

}  // namespace conescan::scene

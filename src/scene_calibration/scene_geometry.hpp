// The seam between the calibration and the scene's sources (MODEL §10, §11): the truth geometry of
// each telemetry row, i.e. everything the forward model needs that the fitted parameters do not
// change. ONE function; the forward model (scene_model.hpp) and the programs never see where the
// truth came from.
//
// Its body is the simulation layer's scene::truth_source (src/simulation/truth_source.hpp), the
// same truth the simulation computes its rows from: the orbit from classical elements (Kepler,
// optional secular J2), --tle (SGP4/SDP4) or --oem; the reference attitude from the constant
// 3-2-1 angles (--roll-deg, --pitch-deg, --yaw-deg), --aem or --attitude-csv; the Sun's
// declination from --sun-declination-deg / --date, else ERFA at the row's own time.
//
// The telemetry's span, not the scene's --duration-s, decides what the sources must cover: when
// the last telemetry time lies past the scene's last row, the files are read again, whole, for
// the telemetry's span [0, last time]. A time outside a source's usable span is refused, naming
// the row and the span the source covers.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "conescan/attitude.hpp"
#include "scene/loaded_scene.hpp"
#include "scene/scene_config.hpp"
#include "text/diagnostic.hpp"

namespace conescan::calibration {

/// The truth of one row (SI): satellite state in ECI, reference attitude (orbital to body), and
/// the Sun's declination for the apparent horizon's season term.
struct row_truth {
  vec3<double> r_eci_m;
  vec3<double> v_eci_m_s;
  mat3<double> body_from_orbit;
  double sun_declination_rad = 0;
};

/// The truth at each time t_s (s from the scene's epoch; increasing, as the telemetry reader
/// guarantees) of a validated scene. Errors (option "telemetry", `line` = the 1-based index of
/// the time among `times_s`, which the caller turns into its file's line): a time outside the
/// usable span of the orbit or attitude source (an OEM's or AEM's usable spans, an attitude
/// CSV's first to last time, SGP4's decay), or before the epoch with a source that has a span
/// (a file, or ERFA's Sun track); with classical elements, constant attitude and a constant
/// Sun every finite time is valid. Errors re-reading the scene's files keep their option.
checked<std::vector<row_truth>> scene_truth_at(const scene::loaded_scene& scene,
                                               std::span<const double> times_s);

/// The same truth handed to each(i, truth) for every i, without a vector of it: a month of
/// 1 Hz telemetry is 2.6 million rows, 330 MB of row_truth. The times are split into `threads`
/// contiguous parts, each with its own cursor on its own thread (truth_source is thread-safe),
/// so `each` is called from several threads at once, each i once, in order within a part. On
/// an error `each` may have been called for some rows; the error is that of the earliest
/// failing time.
checked<void> scene_truth_each(const scene::loaded_scene& scene, std::span<const double> times_s,
                               int threads,
                               const std::function<void(std::size_t, const row_truth&)>& each);

/// Each head's status at each time (row-major: time i, head h at [i * heads + h]) from the
/// scene's own row pipeline (scene::simulation::compute_at on the scene stretched to the last
/// time, as scene_truth_at): with --intrusions, `sun` or `moon` where a body blinds the head
/// (MODEL §13). Errors as scene_truth_at's; with --intrusions a time before the epoch is refused
/// (the Sun and Moon track starts there). The scene's physics tables, where it has any, are built
/// on up to `threads` threads (the same statuses on any number).
checked<std::vector<status>> scene_head_statuses_at(const scene::loaded_scene& scene,
                                                    std::span<const double> times_s,
                                                    int threads = 1);

}  // namespace conescan::calibration

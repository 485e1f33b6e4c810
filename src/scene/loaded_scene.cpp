#include "scene/loaded_scene.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "conescan/scalar.hpp"
#include "orbit/wgs84.hpp"
#include "scene/degrees.hpp"
#include "scene/scene_earth.hpp"
#include "text/number_text.hpp"
#include "text/out_of_memory.hpp"
#include "text/text_lines.hpp"

namespace conescan::scene {

namespace {

diagnostic refuse(const char* option, std::string message) {
  return diagnostic{option, std::move(message)};
}

// A source's diagnostic (file, line, what) pinned on the option that named the source (a
// catalogue's verdict keeps --object's).
diagnostic refuse(const char* option, diagnostic e) {
  if (e.option != "object") e.option = option;
  return e;
}

// The TLE's epoch (UTC) as an instant.
checked<sources::instant> tle_epoch_instant(const orbit::tle& set) {
  const orbit::utc_calendar c = orbit::calendar(set.epoch);
  return sources::from_calendar({c.year, c.month, c.day, c.hour, c.minute, c.second},
                                sources::time_scale::utc);
}

// The element set's epoch and its SGP4 model, which must accept the set at its epoch.
checked<void> start_sgp4(const scene_config& s, source_files& f, const orbit::sgp4_elements& el) {
  const char* option = orbit_source_option(s);
  const std::string where = orbit_source_file(s) + ":" +
                            (f.tle->line_number ? std::to_string(f.tle->line_number) + ": " : " ");
  checked<sources::instant> epoch = tle_epoch_instant(*f.tle);
  if (!epoch.ok())
    return refuse(option, where + "the element set's epoch: " + epoch.error().message);
  f.tle_epoch = epoch.value();
  f.sgp4.emplace(el);
  if (f.sgp4->status_at_epoch() != orbit::sgp4_status::ok)
    return refuse(option, where + "SGP4 refuses the element set at its epoch: " +
                              orbit::describe(f.sgp4->status_at_epoch()));
  return success();
}

// The TLE of the scene: the file's one set, or the one --object names in a catalogue (a file
// of several without it is refused: which one would be meant?), a model SGP4 accepts at its
// epoch.
checked<void> load_tle(const scene_config& s, source_files& f) {
  checked<orbit::tle> read = text::naming_input(
      "tle", s.tle_file, [&] { return orbit::read_tle_object(s.tle_file, s.object); });
  if (!read.ok()) return refuse("tle", read.error());
  f.tle = read.value();
  return start_sgp4(s, f, orbit::mean_elements(*f.tle));
}

// The OMM of the scene: one set, as a TLE's.
checked<void> load_omm(const scene_config& s, source_files& f) {
  checked<orbit::omm_element_set> read = text::naming_input(
      "omm", s.omm_file, [&] { return orbit::read_omm_object(s.omm_file, s.object); });
  if (!read.ok()) return refuse("omm", read.error());
  f.tle = read.value().elements;
  f.omm_format = read.value().format;
  return start_sgp4(s, f, orbit::mean_elements(read.value()));
}

// The scene's epoch: --epoch, else the TLE's, else the OEM's first usable time, else 2000-01-01
// 12:00 UTC (MODEL §10).
checked<void> find_epoch(const scene_config& s, source_files& f) {
  if (!s.epoch_utc.empty()) {
    checked<sources::instant> t = sources::parse_epoch(s.epoch_utc, sources::time_scale::utc);
    if (!t.ok()) return refuse("epoch", t.error());
    f.epoch = t.value();
  } else if (f.tle) {
    f.epoch = f.tle_epoch;
  } else if (f.oem) {
    f.epoch = f.oem->usable_start();
  } else {
    f.epoch = sources::parse_epoch(default_epoch_utc, sources::time_scale::utc).value();
    f.default_epoch = true;
  }
  if (f.tle) {
    f.tle_offset_s = sources::seconds_between(f.tle_epoch, f.epoch);
  }
  return success();
}

// The file orbit's state at the epoch: what --orbits and the perigee check use.
checked<void> find_state_at_epoch(const scene_config& s, source_files& f) {
  sources::cartesian_state state;
  if (f.tle) {
    const orbit::teme_state teme = f.sgp4_state_at(0);
    if (teme.status != orbit::sgp4_status::ok)
      return refuse(orbit_source_option(s), orbit_source_file(s) + ": SGP4 at the scene's epoch " +
                                                sources::format_utc(f.epoch, 3) +
                                                " UTC: " + orbit::describe(teme.status));
    state = cartesian_of(teme);
  } else if (f.oem) {
    const auto at = f.oem->state_at(f.epoch);
    if (!at.ok()) return refuse("oem", at.error());
    state = at.value().state;
  } else {
    return success();
  }
  const osculating_elements el = osculating_of(state.r_m, state.v_m_s);
  const char* option = orbit_source_option(s);
  // A state that is not finite (elements SGP4 cannot propagate: a BSTAR or mean motion of
  // 1e300 overflows without an error code of its own), or no orbit at all (a position or
  // velocity of zero, or the two parallel): say so, rather than show NaN.
  const bool finite = std::isfinite(state.r_m.x) && std::isfinite(state.r_m.y) &&
                      std::isfinite(state.r_m.z) && std::isfinite(state.v_m_s.x) &&
                      std::isfinite(state.v_m_s.y) && std::isfinite(state.v_m_s.z);
  if (!finite)
    return refuse(option,
                  orbit_source_file(s) +
                      ": the elements give no finite state at the scene's epoch: check the mean "
                      "motion, eccentricity and drag terms (BSTAR, their derivatives) for values "
                      "SGP4 cannot propagate");
  if (!(norm(cross(state.r_m, state.v_m_s)) > 0))
    return refuse(option, "the state at the scene's epoch (|r| = " +
                              text::shortest_text(norm(state.r_m) / 1000) +
                              " km, |v| = " + text::shortest_text(norm(state.v_m_s) / 1000) +
                              " km/s) is no orbit: position and velocity must be non-zero and "
                              "not parallel");
  if (!(el.a_m > 0 && el.e < 1))
    return refuse(option, "the orbit at the scene's epoch is not bound (e = " +
                              text::shortest_text(el.e) + ")");
  f.state_at_epoch = orbit::orbit_state{state.r_m, state.v_m_s, el.true_anomaly_rad};
  return success();
}

// The scene's span once the orbit is known (nullopt when the scene's time options are not yet
// valid: validate() refuses them).
std::optional<sources::time_span> scene_span(const loaded_scene& scene) {
  const scene_config& s = scene.config;
  const source_files& f = *scene.files;
  const bool duration_valid = s.duration_s ? std::isfinite(*s.duration_s) && *s.duration_s >= 0
                                           : std::isfinite(s.orbits) && s.orbits >= 0;
  if (!(duration_valid && std::isfinite(s.step_s) && s.step_s > 0)) return std::nullopt;
  const std::uint64_t rows = row_count(scene);
  if (rows == 0 || rows > s.max_rows) return std::nullopt;
  return sources::time_span{
      f.epoch, sources::add_seconds(f.epoch, static_cast<double>(rows - 1) * s.step_s)};
}

// The frame a CCSDS file names for a source (frame_names: upper case as read).
sources::reference_frame frame_named(const std::string& name) {
  return sources::reference_frame_from_name(text::to_upper(name))
      .value_or(sources::reference_frame::tod);  // the readers accept only these names
}

// The attitude files, once the orbit and the epoch are in `files` (the scene's span needs them).
checked<void> load_attitude(const scene_config& s, const std::shared_ptr<source_files>& files,
                            bool span_may_change) {
  source_files& f = *files;
  const std::optional<sources::time_span> span =
      span_may_change ? std::nullopt : scene_span(loaded_scene{s, files});
  if (!s.aem_file.empty()) {
    checked<sources::aem_attitude> aem = text::naming_input(
        "aem", s.aem_file, [&] { return sources::read_aem(s.aem_file, {span}); });
    if (!aem.ok()) return refuse("aem", aem.error());
    f.aem = std::move(aem).value();
    for (const sources::aem_segment& segment : f.aem->segments())
      f.aem_frames.push_back(frame_named(segment.inertial_frame));
  }
  if (!s.attitude_csv_file.empty()) {
    // Absolute times (utc, GPS) in the table are taken from the scene's epoch, one the user
    // gave (--epoch, or the orbit file's): the default epoch of 2000 would put a table of 2026
    // 26 years past the scene, which the reader refuses as needing an epoch.
    std::optional<sources::instant> epoch;
    if (!f.default_epoch) epoch = f.epoch;
    checked<sources::attitude_table> table = text::naming_input(
        "attitude-csv", s.attitude_csv_file,
        [&] { return sources::read_attitude_csv(s.attitude_csv_file, {epoch}); });
    if (!table.ok()) return refuse("attitude-csv", table.error());
    f.attitude_csv = std::move(table).value();
    f.attitude_table_frame = frame_named(s.attitude_frame);
  }
  // --attitude-frame names the inertial frame of a quaternion table: another frame than the
  // default with no table, or with angles (orbital -> body), would change nothing (refused as a
  // sweep that changes nothing is).
  const bool quaternions =
      f.attitude_csv && f.attitude_csv->kind() == sources::attitude_table_kind::quaternions;
  if (s.attitude_frame != scene_config{}.attitude_frame && !quaternions)
    return refuse("attitude-frame",
                  "names the inertial frame of --attitude-csv's quaternions, " +
                      std::string(f.attitude_csv ? "and this table holds angles (orbital to body)"
                                                 : "and no --attitude-csv is given") +
                      ": drop it");
  return success();
}

// --eop turns an ITRF OEM's states (earth_orientation.hpp); any other orbit source would not use
// it.
std::string no_itrf_source(const scene_config& s) {
  return "turns an ITRF --oem's states with the Earth's orientation, and this scene's orbit " +
         std::string(s.oem_file.empty() ? "is not an OEM" : "OEM has no ITRF segment") +
         ": drop it";
}

checked<void> load_oem(const scene_config& s, source_files& f, bool span_may_change) {
  sources::oem_read_options options;
  if (!s.eop_file.empty()) {
    checked<sources::earth_orientation> eop =
        sources::earth_orientation::read_finals2000a(s.eop_file);
    if (!eop.ok()) return refuse("eop", eop.error());
    f.eop = std::move(eop).value();
    options.eop = &*f.eop;
  }
  // With the span known before reading (--epoch and --duration-s), only the states it needs
  // are kept: a file of any length is read in bounded memory.
  if (!span_may_change && !s.epoch_utc.empty() && s.duration_s && *s.duration_s >= 0) {
    checked<sources::instant> t0 = sources::parse_epoch(s.epoch_utc, sources::time_scale::utc);
    if (!t0.ok()) return refuse("epoch", t0.error());
    const sources::instant start = t0.value();
    options.span = sources::time_span{start, sources::add_seconds(start, *s.duration_s)};
  }
  checked<sources::oem_ephemeris> oem =
      text::naming_input("oem", s.oem_file, [&] { return sources::read_oem(s.oem_file, options); });
  if (!oem.ok()) {
    diagnostic error = refuse("oem", oem.error());
    if (!options.span && error.message.find("lines to keep") != std::string::npos)
      error.message += " (with --epoch and --duration-s only the states the scene needs are kept)";
    return error;
  }
  f.oem = std::move(oem).value();
  for (const sources::oem_segment& segment : f.oem->segments()) {
    const sources::reference_frame frame = frame_named(segment.ref_frame);
    // An ITRF segment's states were turned CIRS as they were read (sources/oem.hpp).
    f.oem_frames.push_back({frame, frame == sources::reference_frame::itrf});
  }
  return success();
}

// The files `s` names, read and checked, and its epoch (load_scene's work).
checked<std::shared_ptr<const source_files>> read_source_files(const scene_config& s,
                                                               bool span_may_change) {
  auto f = std::make_shared<source_files>();
  if (!s.object.empty() && s.tle_file.empty() && s.omm_file.empty())
    return refuse("object",
                  "chooses the element set of a catalogue --tle or --omm, and this scene's orbit " +
                      std::string(s.oem_file.empty() ? "is classical elements" : "is an OEM") +
                      ": drop it");
  if (!s.tle_file.empty())
    if (checked<void> tle = load_tle(s, *f); !tle.ok()) return tle.error();
  if (!s.omm_file.empty())
    if (checked<void> omm = load_omm(s, *f); !omm.ok()) return omm.error();
  if (!s.oem_file.empty())
    if (checked<void> oem = load_oem(s, *f, span_may_change); !oem.ok()) return oem.error();
  if (!s.eop_file.empty() && !f->eop) return refuse("eop", no_itrf_source(s));
  if (f->eop && std::none_of(f->oem_frames.begin(), f->oem_frames.end(),
                             [](const source_frame& frame) { return frame.cirs; }))
    return refuse("eop", no_itrf_source(s));
  if (checked<void> epoch = find_epoch(s, *f); !epoch.ok()) return epoch.error();
  if (checked<void> state = find_state_at_epoch(s, *f); !state.ok()) return state.error();
  if (checked<void> attitude = load_attitude(s, f, span_may_change); !attitude.ok())
    return attitude.error();
  return std::shared_ptr<const source_files>(std::move(f));
}

}  // namespace

checked<loaded_scene> load_scene(scene_config config, bool span_may_change) {
  checked<std::shared_ptr<const source_files>> files = read_source_files(config, span_may_change);
  if (!files.ok()) return std::move(files).error();
  return loaded_scene{std::move(config), std::move(files).value()};
}

double orbital_period_s(const loaded_scene& scene) {
  double a_m = scene.config.a_km * 1000;
  if (scene.files && scene.files->state_at_epoch)
    a_m =
        osculating_of(scene.files->state_at_epoch->r_eci_m, scene.files->state_at_epoch->v_eci_m_s)
            .a_m;
  return orbit::orbital_period_s(a_m, orbit::wgs84().gm_m3_s2);
}

double scene_duration_s(const loaded_scene& scene) {
  const scene_config& s = scene.config;
  return s.duration_s ? *s.duration_s : s.orbits * orbital_period_s(scene);
}

std::uint64_t row_count(const loaded_scene& scene) {
  const double duration = scene_duration_s(scene);
  const double step_s = scene.config.step_s;
  const double estimate = std::floor(duration / step_s);
  if (!(estimate < 1.8e19)) return UINT64_MAX;
  auto k = static_cast<std::uint64_t>(estimate);
  // The quotient may be off by one ulp either way: settle on the product, as the grid does.
  while (static_cast<double>(k + 1) * step_s <= duration) ++k;
  while (k > 0 && static_cast<double>(k) * step_s > duration) --k;
  return k + 1;
}

double last_row_t_s(const loaded_scene& scene) {
  return static_cast<double>(row_count(scene) - 1) * scene.config.step_s;
}

namespace {

// SGP4 at the first and last rows and at least every tenth of an orbit between: a decay or an
// element gone out of range is found before any row (the model's statuses are monotonic in
// practice, decay being final; a tenth of an orbit is far below any decay's time scale).
checked<void> check_sgp4_over(const loaded_scene& scene, double last_t_s) {
  const scene_config& s = scene.config;
  const source_files& f = *scene.files;
  const double spacing = std::max(orbital_period_s(scene) / 10, s.step_s);
  const double steps = std::ceil(last_t_s / spacing);
  const auto n = static_cast<std::uint64_t>(std::min(steps, 1e6));
  // The resonance integration carried from one time to the next (not restarted at the epoch).
  orbit::sgp4_propagator::resonance_cursor carried;
  for (std::uint64_t k = 0; k <= n; ++k) {
    const double t = n == 0 ? 0 : last_t_s * static_cast<double>(k) / static_cast<double>(n);
    const orbit::teme_state state = f.sgp4_state_at(t, carried);
    if (state.status == orbit::sgp4_status::ok) continue;
    return refuse(orbit_source_option(s),
                  orbit_source_file(s) + ": SGP4 at t_s = " + text::shortest_text(t) + " (" +
                      sources::format_utc(sources::add_seconds(f.epoch, t), 3) +
                      " UTC): " + orbit::describe(state.status) + "; shorten the scene");
  }
  return success();
}

}  // namespace

checked<void> check_source_coverage(const loaded_scene& scene) {
  if (!scene.files) return success();
  const scene_config& s = scene.config;
  const source_files& f = *scene.files;
  const std::uint64_t rows = row_count(scene);
  const double last_t_s = static_cast<double>(rows - 1) * s.step_s;
  const sources::instant t0 = f.epoch, t1 = sources::add_seconds(f.epoch, last_t_s);
  if (checked<void> e = sources::check_in_utc_table(t0, t1); !e.ok())
    return refuse(!s.epoch_utc.empty()                       ? "epoch"
                  : s.tle_file.empty() && s.omm_file.empty() ? "duration-s"
                                                             : orbit_source_option(s),
                  e.error());
  if (f.sgp4)
    if (checked<void> sgp4 = check_sgp4_over(scene, last_t_s); !sgp4.ok()) return sgp4;
  if (f.oem)
    if (checked<void> e = f.oem->check_coverage(t0, t1, deg_to_rad(s.interpolation_tolerance_deg));
        !e.ok())
      return refuse("oem", e.error());
  // The attitude's interpolation held to the orbit's tolerance, with the same escape.
  const double tolerance_rad = deg_to_rad(s.interpolation_tolerance_deg);
  if (f.aem)
    if (checked<void> e = f.aem->check_coverage(t0, t1, tolerance_rad); !e.ok())
      return refuse("aem", e.error());
  if (f.attitude_csv)
    if (checked<void> e = f.attitude_csv->check_coverage(0.0, last_t_s, tolerance_rad); !e.ok())
      return refuse("attitude-csv", e.error());
  return success();
}

std::optional<std::string> interpolation_tolerance_note(const loaded_scene& scene,
                                                        double last_t_s) {
  const scene_config& s = scene.config;
  if (!scene.files || !scene.files->oem || !scene.files->state_at_epoch ||
      !(s.interpolation_tolerance_deg > default_interpolation_tolerance_deg))
    return std::nullopt;
  const source_files& f = *scene.files;
  const sources::worst_interval_error w =
      f.oem->worst_error(f.epoch, sources::add_seconds(f.epoch, last_t_s));
  const double angle_deg = rad_to_deg(static_cast<double>(w.error.angle_rad));
  if (w.segment_line == 0 || !(angle_deg > default_interpolation_tolerance_deg))
    return std::nullopt;
  // SOURCES.md: a direction error A moves the nadir and the orbital frame by A, and an altitude
  // error moves the Earth's angular radius rho by tan rho times A.
  const double r_m = norm(f.state_at_epoch->r_eci_m);
  const double sin_rho = std::min(1.0, truth_radius_m(s) / r_m);
  const double tan_rho = sin_rho / std::sqrt((1 - sin_rho) * (1 + sin_rho));
  return "--interpolation-tolerance-deg " + text::shortest_text(s.interpolation_tolerance_deg) +
         ": the OEM's interpolation error estimate reaches " + text::rounded_text(angle_deg) +
         " deg (" + text::rounded_text(w.error.position_m) + " m) at " +
         sources::format_utc(w.at, 3) + " UTC (" + s.oem_file + ":" +
         std::to_string(w.data_line != 0 ? w.data_line : w.segment_line) +
         "): each row's truth (its orbital frame and nadir, and the Earth's angular radius, "
         "tan rho = " +
         text::rounded_text(tan_rho) + " times as much) may be off by up to " +
         text::rounded_text(angle_deg * (1 + tan_rho)) + " deg";
}

std::optional<std::string> interpolation_tolerance_note(const loaded_scene& scene) {
  if (!scene.files) return std::nullopt;
  return interpolation_tolerance_note(scene, last_row_t_s(scene));
}

}  // namespace conescan::scene

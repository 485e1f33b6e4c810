#include "scene/truth_source.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "conescan/attitude.hpp"
#include "conescan/orbital_frame.hpp"
#include "conescan/scalar.hpp"
#include "orbit/wgs84.hpp"
#include "scene/degrees.hpp"
#include "scene/scene_earth.hpp"
#include "scene/scene_physics.hpp"
#include "sources/earth_rotation.hpp"
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

sources::cartesian_state cartesian_of(const orbit::teme_state& s) {
  return {s.r_teme_km * 1000.0, s.v_teme_km_s * 1000.0};
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

}  // namespace

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

checked<std::shared_ptr<const source_files>> load_source_files(const scene_config& s,
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

checked<truth_source> truth_source::of(const loaded_scene& scene) {
  truth_source t;
  if (checked<void> built = t.build(scene); !built.ok()) return built.error();
  return t;
}

checked<void> truth_source::build(const loaded_scene& scene) {
  const scene_config& s = scene.config;
  files_ = scene.files;
  epoch_ = files_->epoch;
  const orbit::earth_constants& w = orbit::wgs84();
  const orbit::elements elements{s.a_km * 1000,
                                 s.e,
                                 deg_to_rad(effective_inclination_deg(s)),
                                 deg_to_rad_reduced(s.raan_deg),
                                 deg_to_rad_reduced(s.argp_deg),
                                 deg_to_rad_reduced(s.m0_deg)};
  kepler_ = orbit::kepler_orbit(elements,
                                s.j2 ? orbit::j2_secular_rates(elements, w.gm_m3_s2, w.j2, w.a_m)
                                     : orbit::two_body_rates(elements, w.gm_m3_s2),
                                w.gm_m3_s2);
  body_from_orbit_ = dcm_body_from_orbit(deg_to_rad_reduced(s.roll_deg), deg_to_rad(s.pitch_deg),
                                         deg_to_rad_reduced(s.yaw_deg));
  if (s.sun_declination_deg) {
    sun_declination_rad_ = deg_to_rad(*s.sun_declination_deg);
  } else if (has_season_terms(s)) {
    // The season terms follow each row's time (MODEL §10).
    const double last_t_s = last_row_t_s(scene);
    auto track =
        sources::sun_declination_track::over(epoch_, sources::add_seconds(epoch_, last_t_s));
    if (!track.ok()) return track.error();
    sun_track_ = std::move(track).value();
  }
  // The rotations into TOD, for the sources that need them (classical elements with constant
  // angles are TOD already: no track, the paper's rows bit for bit).
  if (orbit_from_file(s) || files_->aem ||
      (files_->attitude_csv &&
       files_->attitude_csv->kind() == sources::attitude_table_kind::quaternions)) {
    const double last_t_s = last_row_t_s(scene);
    auto frames = sources::frame_track::over(epoch_, sources::add_seconds(epoch_, last_t_s));
    if (!frames.ok()) return frames.error();
    frames_ = std::move(frames).value();
  }
  return success();
}

sources::cartesian_state truth_source::in_scene_frame(
    const source_frame& frame, const sources::instant& t,
    const sources::cartesian_state& state) const noexcept {
  if (!frames_ || (frame.frame == sources::reference_frame::tod && !frame.cirs)) return state;
  if (!frame.cirs) return sources::to_tod(frames_->at(frame.frame, t), state);
  // CIRS -> ITRF is R3(ERA), ITRF -> TOD R3(-GAST): CIRS -> TOD is their product, a rotation by
  // the equation of the origins (no spin: CIRS is inertial as TOD is).
  sources::rotation_to_tod r = frames_->at(sources::reference_frame::itrf, t);
  r.tod_from_source = r.tod_from_source * sources::about_z(-sources::earth_rotation_angle_rad(t));
  r.spin_rad_s = 0;
  return sources::to_tod(r, state);
}

mat3<double> truth_source::tod_from(sources::reference_frame frame,
                                    const sources::instant& t) const noexcept {
  if (!frames_ || frame == sources::reference_frame::tod) return mat3<double>(1.0);
  return frames_->at(frame, t).tod_from_source;
}

void truth_source::orbit_at(double t_s, const sources::instant& t, cursor& carried,
                            truth_state& out) const noexcept {
  sources::cartesian_state state;
  if (files_->sgp4) {
    const orbit::teme_state teme = files_->sgp4_state_at(t_s, carried.sgp4);
    out.ok = teme.status == orbit::sgp4_status::ok;
    state = in_scene_frame({sources::reference_frame::teme}, t, cartesian_of(teme));
  } else if (files_->oem) {
    const auto at = files_->oem->state_at(t);
    out.ok = at.ok();
    if (out.ok) {
      const sources::oem_segment* segment = sources::segment_at(files_->oem->segments(), t);
      const auto k = static_cast<std::size_t>(segment - files_->oem->segments().data());
      state = in_scene_frame(files_->oem_frames[k], t, at.value().state);
    }
  } else {
    orbit::orbit_state kepler_state;
    kepler_.states_at(&t_s, &kepler_state, 1);
    out.r_eci_m = kepler_state.r_eci_m;
    out.v_eci_m_s = kepler_state.v_eci_m_s;
    out.true_anomaly_rad = kepler_state.true_anomaly_rad;
    return;
  }
  out.r_eci_m = state.r_m;
  out.v_eci_m_s = state.v_m_s;
  out.true_anomaly_rad = osculating_of(state.r_m, state.v_m_s).true_anomaly_rad;
}

void truth_source::attitude_at(double t_s, const sources::instant& t,
                               truth_state& out) const noexcept {
  if (files_->aem) {
    const auto at = files_->aem->attitude_at(t);
    if (!at.ok()) {
      out.ok = false;
      return;
    }
    // body <- orbital = (body <- inertial)(inertial <- TOD)(TOD <- orbital).
    const sources::aem_segment* segment = sources::segment_at(files_->aem->segments(), t);
    const auto k = static_cast<std::size_t>(segment - files_->aem->segments().data());
    out.body_from_orbit = at.value().dcm() * glm::transpose(tod_from(files_->aem_frames[k], t)) *
                          dcm_eci_from_orbit(out.r_eci_m, out.v_eci_m_s);
  } else if (files_->attitude_csv &&
             files_->attitude_csv->kind() == sources::attitude_table_kind::quaternions) {
    const auto at = files_->attitude_csv->body_from_inertial_at(t_s);
    if (!at.ok()) {
      out.ok = false;
      return;
    }
    // body <- orbital = (body <- inertial)(inertial <- TOD)(TOD <- orbital), as an AEM's.
    out.body_from_orbit = sources::rotation_matrix(at.value()) *
                          glm::transpose(tod_from(files_->attitude_table_frame, t)) *
                          dcm_eci_from_orbit(out.r_eci_m, out.v_eci_m_s);
  } else if (files_->attitude_csv) {
    const auto at = files_->attitude_csv->angles_at(t_s);
    if (!at.ok()) {
      out.ok = false;
      return;
    }
    const sources::attitude_angles& a = at.value();
    out.body_from_orbit = dcm_body_from_orbit(a.roll_rad, a.pitch_rad, a.yaw_rad);
  } else {
    out.body_from_orbit = body_from_orbit_;
  }
}

truth_state truth_source::truth_at(double t_s) const noexcept {
  cursor from_epoch;
  return truth_at(t_s, from_epoch);
}

truth_state truth_source::truth_at(double t_s, cursor& carried) const noexcept {
  truth_state out;
  const sources::instant t = sources::add_seconds(epoch_, t_s);
  orbit_at(t_s, t, carried, out);
  if (out.ok) attitude_at(t_s, t, out);
  out.sun_declination_rad = sun_track_ ? sun_track_->at(t) : sun_declination_rad_;
  if (!out.ok) {
    const double nan = not_a_number<double>();
    out.r_eci_m = out.v_eci_m_s = vec3<double>(nan);
    out.true_anomaly_rad = nan;
    out.body_from_orbit = mat3<double>(nan);
  }
  return out;
}

}  // namespace conescan::scene

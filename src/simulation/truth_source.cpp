#include "simulation/truth_source.hpp"

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

namespace conescan::scene {

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

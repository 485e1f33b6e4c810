#include "simulation/simulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "conescan/earth_disk.hpp"
#include "conescan/horizon_vector.hpp"
#include "conescan/intrusion.hpp"
#include "conescan/orbital_frame.hpp"
#include "conescan/sensor_physics.hpp"
#include "orbit/geodetic.hpp"
#include "orbit/wgs84.hpp"
#include "scene/degrees.hpp"
#include "scene/scene_physics.hpp"
#include "scene/scene_validation.hpp"
#include "simulation/physics_table.hpp"
#include "simulation/random.hpp"

namespace conescan::scene {

checked<simulation> simulation::of(const scene_config& scene, int threads) {
  checked<loaded_scene> loaded = load_scene(scene);
  if (!loaded.ok()) return std::move(loaded).error();
  return of(loaded.value(), threads);
}

checked<simulation> simulation::of(const loaded_scene& loaded, int threads) {
  if (checked<void> valid = validate(loaded); !valid.ok()) return valid.error();
  checked<truth_source> truth = truth_source::of(loaded);
  if (!truth.ok()) return truth.error();
  simulation sim;
  sim.truth_.emplace(std::move(truth).value());
  sim.set_up(loaded);
  if (loaded.config.intrusions) {  // validate() checked the ephemerides' span
    checked<scene_sky> sky =
        scene_sky::over(sim.truth_->epoch(), static_cast<double>(sim.rows_ - 1) * sim.step_s_);
    if (!sky.ok()) return sky.error();
    sim.sky_.emplace(std::move(sky).value());
  }
  sim.set_up_physics_tables(threads);
  return sim;
}

void simulation::set_up(const loaded_scene& loaded) {
  const scene_config& scene = loaded.config;
  const orbit::earth_constants& w = orbit::wgs84();
  step_s_ = scene.step_s;
  rows_ = row_count(loaded);
  earth_ = scene.earth;
  model_ = scene.model;
  horizon_m_ = scene.horizon_km * 1000;
  truth_radius_m_ = truth_radius_m(scene);
  // MODEL §3's inflated ellipsoid, or the apparent horizon surface.
  a_eq_m_ = w.a_m + horizon_m_;
  b_pol_m_ = horizon_polar_radius_m(scene);
  horizon_shift_m_ = scene.horizon_shift_km * 1000;
  processing_horizon_m_ = scene.processing_horizon_km.value_or(scene.horizon_km) * 1000;
  processing_sphere_ = processing_sphere_of(scene);
  seed_ = scene.seed;
  processing_ = scene.processing;
  for (const head_config& h : scene.heads) {
    const sensor_head<double> head = sensor_head<double>::from_mounting(
        deg_to_rad(h.alpha_deg), deg_to_rad_reduced(h.beta_deg),
        {deg_to_rad(h.gamma_deg), deg_to_rad(h.sigma_deg), deg_to_rad_reduced(h.phase_deg)},
        {deg_to_rad(h.noise_deg), deg_to_rad(h.lsb_deg)}, deg_to_rad(scene.attitude_envelope_deg),
        {deg_to_rad(h.dgamma_deg), deg_to_rad(h.bias_in_deg), deg_to_rad(h.bias_out_deg)});
    heads_.push_back({head, head.bias_cone_angle(), deg_to_rad(h.field_of_view_deg()), nullptr,
                      nullptr, nullptr});
    if (physics_on(scene, h))  // validate() checked the settings (check_physics)
      heads_.back().physics = std::make_shared<const sensor_physics_head<double>>(
          sensor_physics_head_of(physics_settings_of(scene, h)));
  }
  sphere_polar_ =
      scene.earth == earth_model::sphere && scene.radiance_season != 0 && any_physics(scene);
  // The constant attitude's roll and pitch as given (not through the nadir: the same bits as
  // the angles the user typed).
  constant_view_ =
      view_of(deg_to_rad_reduced(scene.roll_deg), deg_to_rad(scene.pitch_deg),
              truth_->constant_body_from_orbit(), truth_->constant_sun_declination_rad());
}

template <class Visit>
void simulation::for_each_row_truth(Visit&& visit) const {
  if (truth_->kepler_with_constant_attitude()) {
    for (std::uint64_t first = 0; first < rows_; first += rows_per_block) {
      const std::size_t n =
          static_cast<std::size_t>(std::min<std::uint64_t>(rows_per_block, rows_ - first));
      double times[rows_per_block];
      orbit::orbit_state states[rows_per_block];
      for (std::size_t i = 0; i < n; ++i)  // MODEL §3: a product, never a sum
        times[i] = static_cast<double>(first + i) * step_s_;
      truth_->kepler().states_at(times, states, n);
      for (std::size_t i = 0; i < n; ++i)
        visit(states[i].r_eci_m, states[i].v_eci_m_s, constant_view_);
    }
    return;
  }
  truth_source::cursor carried;
  for (std::uint64_t k = 0; k < rows_; ++k) {
    const truth_state truth = truth_->truth_at(static_cast<double>(k) * step_s_, carried);
    if (truth.ok) visit(truth.r_eci_m, truth.v_eci_m_s, view_at(truth));
  }
}

void simulation::set_up_physics_tables(int threads) {
  // Too few rows to pay for any table: no pass over them either.
  if (static_cast<long>(rows_) / physics_table_rows_per_evaluation <
      physics_table_least_evaluations)
    return;
  bool any = false;
  for (const head_view& h : heads_) any = any || h.physics != nullptr;
  if (!any) return;
  // The ellipsoid's six variables hold the row on WGS84, and on the sphere with the season term
  // (which adds the pole); the sphere's three without it; and only for the scan model the chain
  // runs on.
  if (earth_ == earth_model::wgs84 ||
      (earth_ == earth_model::sphere && model_ == forward_model::scan && sphere_polar_))
    return set_up_ellipsoid_tables(threads);
  if (earth_ != earth_model::sphere || model_ != forward_model::scan) return;
  std::array<physics_table_range, max_heads> ranges{};
  for_each_row_truth([&](const vec3<double>& r, const vec3<double>&, const attitude_view& view) {
    const double r_m = norm(r);
    for (std::size_t h = 0; h < heads_.size(); ++h)
      if (heads_[h].physics) ranges[h].add({r_m, view.heads[h].eta_true, view.heads[h].phi_n_true});
  });
  for (std::size_t h = 0; h < heads_.size(); ++h)
    if (heads_[h].physics)
      heads_[h].table = physics_table::of(*heads_[h].physics, heads_[h].head, truth_sphere_m(),
                                          ranges[h], static_cast<long>(rows_), nullptr, threads);
}

template <class Tabulated, class Use>
void simulation::for_each_table_surface(const Tabulated& tabulated, Use&& use) const {
  const bool sphere = earth_ == earth_model::sphere;
  for_each_row_truth([&](const vec3<double>& r, const vec3<double>& v, const attitude_view& view) {
    const ellipsoid_horizon<double> body =
        sphere ? ellipsoid_horizon<double>{} : truth_surface_in_body(r, v, view);
    const vec3<double> polar = sphere ? polar_in_body(r, v, view) : vec3<double>(0.0);
    for (std::size_t h = 0; h < heads_.size(); ++h) {
      if (!tabulated(h)) continue;
      const sensor_head<double>& head = heads_[h].head;
      use(h,
          sphere
              ? sphere_in_scan_frame(view.heads[h].nadir_scan, norm(r), head.in_scan_frame(polar))
              : head.in_scan_frame(body),
          view);
    }
  });
}

void simulation::set_up_ellipsoid_tables(int threads) {
  // A pencil's, and a field's from 512 rows: a field's chain costs ~10 ms a row on an idle
  // core, its table some 90 of them over 20 minutes' rows and 850 over a day's (some 8 s before
  // the first row, against some 12 minutes for the day by the chain); the build never spends
  // more than a quarter of what the chain would cost on every row (docs/SENSOR_PHYSICS.md, "The
  // table", decision 26).
  const bool many_rows = static_cast<long>(rows_) / physics_table_rows_per_evaluation >=
                         physics_table_least_field_evaluations;
  const auto tabulated = [this, many_rows](std::size_t h) {
    return heads_[h].physics != nullptr &&
           (heads_[h].physics->settings.field.fov_rad == 0 || many_rows);
  };
  const bool sphere = earth_ == earth_model::sphere;
  // Two passes over the rows: the axes the pole turns about in each head's scan frame, then the
  // box of the six variables (physics_table.hpp).
  std::array<ellipsoid_axes_finder, max_heads> finders{};
  for_each_table_surface(tabulated, [&](std::size_t h, const ellipsoid_horizon<double>& e,
                                        const attitude_view&) { finders[h].add(e.polar); });
  std::array<ellipsoid_table_axes, max_heads> axes{};
  for (std::size_t h = 0; h < heads_.size(); ++h) axes[h] = finders[h].axes();
  std::array<ellipsoid_table_range, max_heads> ranges{};
  const double a_m = table_a_m();
  auto each_point = [&](auto&& use) {
    for_each_table_surface(tabulated, [&](std::size_t h, const ellipsoid_horizon<double>& e,
                                          const attitude_view& view) {
      use(h, ellipsoid_table_point_of(e, a_m, axes[h], view.sin_sun_declination));
    });
  };
  each_point([&](std::size_t h, const ellipsoid_table_point& x) {
    if (std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); }))
      ranges[h].add(x);
  });
  std::vector<physics_table_cells<6>> cells;
  for (std::size_t h = 0; h < heads_.size(); ++h)
    cells.push_back(ellipsoid_physics_table::cells_for(ranges[h], static_cast<long>(rows_)));
  // Two more: the cells' boxes, then each cell's rows along the curve through its neighbours
  // (physics_table_cells::add_along: on an orbit the distance follows the pole's azimuth and
  // takes one node where it took two).
  each_point([&](std::size_t h, const ellipsoid_table_point& x) { cells[h].add(x); });
  each_point([&](std::size_t h, const ellipsoid_table_point& x) { cells[h].add_along(x); });
  const long rows = static_cast<long>(rows_);
  for (std::size_t h = 0; h < heads_.size(); ++h) {
    if (!tabulated(h) || ranges[h].empty) continue;
    const sensor_physics_head<double>& physics = *heads_[h].physics;
    heads_[h].ellipsoid_table =
        sphere ? ellipsoid_physics_table::of_sphere(physics, heads_[h].head, a_m, axes[h], cells[h],
                                                    rows, nullptr, threads)
               : ellipsoid_physics_table::of(physics, heads_[h].head, a_eq_m_, b_pol_m_, axes[h],
                                             cells[h], rows, nullptr, threads);
  }
}

double simulation::table_a_m() const noexcept {
  return earth_ == earth_model::sphere ? truth_sphere_m() : a_eq_m_;
}

ellipsoid_horizon<double> simulation::sphere_in_scan_frame(
    const vec3<double>& nadir_scan, double r_m, const vec3<double>& polar_scan) const noexcept {
  const double radius_m = truth_sphere_m();
  return ellipsoid_horizon_of(scaled(nadir_scan, -r_m), polar_scan, radius_m, radius_m);
}

simulation::attitude_view simulation::view_of(double roll, double pitch,
                                              const mat3<double>& body_from_orbit,
                                              double sun_declination_rad) const noexcept {
  attitude_view v;
  v.roll_true = roll;
  v.pitch_true = pitch;
  v.pitch_state = classify_true_pitch(pitch);
  v.body_from_orbit = body_from_orbit;
  v.centre_z_m = horizon_shift_m_ == 0 ? 0 : horizon_shift_m_ * std::sin(sun_declination_rad);
  v.sin_sun_declination = std::sin(sun_declination_rad);
  const vec3<double> nadir_body = nadir_in_body(roll, pitch);
  for (std::size_t h = 0; h < heads_.size(); ++h) {
    const sensor_head<double>& head = heads_[h].head;
    const scan_angles<double> nadir = scan_angles_of(head.frame(), nadir_body);
    v.heads[h] = {nadir.polar, nadir.azimuth, head.in_scan_frame(nadir_body)};
  }
  return v;
}

namespace {

// alt_m and lat_rad of up to rows_per_block rows from their ECI positions, in one pass.
void set_geodetic(const vec3<double>* positions, row* out, std::size_t n) noexcept {
  orbit::geodetic_position geodetic[simulation::rows_per_block];
  orbit::geodetic_from_eci(positions, geodetic, n);
  for (std::size_t i = 0; i < n; ++i) {
    out[i].alt_m = geodetic[i].alt_m;
    out[i].lat_rad = geodetic[i].lat_rad;
  }
}

}  // namespace

void simulation::compute_rows(std::uint64_t first_k, std::size_t count, row* out,
                              std::uint64_t run) const noexcept {
  if (!truth_->kepler_with_constant_attitude()) {
    compute_rows_from_truth(first_k, count, out, run);
    return;
  }
  for (std::size_t first = 0; first < count; first += rows_per_block) {
    const std::size_t n = std::min(rows_per_block, count - first);
    vec3<double> positions[rows_per_block];
    double times[rows_per_block];
    orbit::orbit_state states[rows_per_block];
    for (std::size_t i = 0; i < n; ++i)  // MODEL §3: a product, never a sum
      times[i] = static_cast<double>(first_k + first + i) * step_s_;
    truth_->kepler().states_at(times, states, n);
    for (std::size_t i = 0; i < n; ++i) {
      compute_from_state(times[i], states[i], constant_view_, out[first + i], run,
                         first_k + first + i);
      positions[i] = states[i].r_eci_m;
    }
    set_geodetic(positions, out + first, n);
  }
}

// The attitude view of a row: the constant one where the truth's attitude and Sun are constant
// (or the truth has no value: the row's NaN state makes every status invalid anyway).
simulation::attitude_view simulation::view_at(const truth_state& truth) const noexcept {
  if (!truth.ok || (!truth_->attitude_varies() && !truth_->sun_varies())) return constant_view_;
  if (!truth_->attitude_varies())
    return view_of(constant_view_.roll_true, constant_view_.pitch_true, truth.body_from_orbit,
                   truth.sun_declination_rad);
  // The true roll and pitch of the true nadir (orbital +z) in body axes.
  const roll_pitch<double> rp =
      roll_pitch_from_nadir(apply(truth.body_from_orbit, vec3<double>(0, 0, 1)));
  return view_of(rp.roll, rp.pitch, truth.body_from_orbit, truth.sun_declination_rad);
}

// The same rows, the truth asked row by row (truth_source::truth_at, its cursor carried over
// the call's rows); the geodetic conversion still runs over blocks.
void simulation::compute_rows_from_truth(std::uint64_t first_k, std::size_t count, row* out,
                                         std::uint64_t run) const noexcept {
  truth_source::cursor carried;
  for (std::size_t first = 0; first < count; first += rows_per_block) {
    const std::size_t n = std::min(rows_per_block, count - first);
    vec3<double> positions[rows_per_block];
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint64_t k = first_k + first + i;
      const double t = static_cast<double>(k) * step_s_;  // MODEL §3: a product, never a sum
      const truth_state truth = truth_->truth_at(t, carried);
      const orbit::orbit_state state{truth.r_eci_m, truth.v_eci_m_s, truth.true_anomaly_rad};
      compute_from_state(t, state, view_at(truth), out[first + i], run, k);
      positions[i] = state.r_eci_m;
    }
    set_geodetic(positions, out + first, n);
  }
}

void simulation::compute_at(double t_s, row& out) const noexcept {
  const truth_state truth = truth_->truth_at(t_s);
  const orbit::orbit_state state{truth.r_eci_m, truth.v_eci_m_s, truth.true_anomaly_rad};
  compute_from_state(t_s, state, view_at(truth), out, 0, 0);
  set_geodetic(&state.r_eci_m, &out, 1);
}

ellipsoid_horizon<double> simulation::truth_surface_in_body(
    const vec3<double>& r_eci, const vec3<double>& v_eci,
    const attitude_view& truth) const noexcept {
  // Orbital frame from the state (MODEL §2), then body axes by the constant attitude: the
  // satellite from the surface's centre and the polar axis, which is all the surface needs.
  const mat3<double> eci_from_orbit = dcm_eci_from_orbit(r_eci, v_eci);
  auto to_body = [&](const vec3<double>& v) {
    return apply(truth.body_from_orbit, apply_transpose(eci_from_orbit, v));
  };
  return ellipsoid_horizon_of(to_body(r_eci - vec3<double>(0, 0, truth.centre_z_m)),
                              to_body(vec3<double>(0, 0, 1)), a_eq_m_, b_pol_m_);
}

vec3<double> simulation::polar_in_body(const vec3<double>& r_eci, const vec3<double>& v_eci,
                                       const attitude_view& truth) noexcept {
  return apply(truth.body_from_orbit,
               apply_transpose(dcm_eci_from_orbit(r_eci, v_eci), vec3<double>(0, 0, 1)));
}

// --- The row's pipeline (MODEL §5-§6), one named step a function --------------------------------

simulation::row_geometry simulation::geometry_at(const orbit::orbit_state& st,
                                                 const attitude_view& truth) const noexcept {
  row_geometry g;
  g.r_m = norm(st.r_eci_m);
  const double processing_radius = processing_sphere_.radius_at(st.r_eci_m) + processing_horizon_m_;
  g.rho_p = disk_angular_radius(processing_radius, g.r_m).value;
  g.assumed = disk_trig_of(processing_radius, g.r_m);
  // The truth: the sphere (usually the one the processing assumes: the paper's scene, whose
  // disk is then reused) or the ellipsoid seen from the satellite.
  const double truth_radius = truth_sphere_m();
  const bool same_sphere = truth_radius == processing_radius;
  if (earth_ == earth_model::wgs84) {
    g.surface_body = truth_surface_in_body(st.r_eci_m, st.v_eci_m_s, truth);
  } else if (model_ == forward_model::scan) {
    g.truth_disk = same_sphere ? g.assumed : disk_trig_of(truth_radius, g.r_m);
    if (sphere_polar_) g.polar_body = polar_in_body(st.r_eci_m, st.v_eci_m_s, truth);
  } else {
    g.rho_truth = same_sphere ? g.rho_p : disk_angular_radius(truth_radius, g.r_m).value;
  }
  return g;
}

crossings<double> simulation::truth_crossings(std::size_t h, const row_geometry& g,
                                              const head_truth& seen) const noexcept {
  const head_view& view = heads_[h];
  const sensor_head<double>& head = view.head;
  if (earth_ == earth_model::wgs84) return head.scan_crossings(head.in_scan_frame(g.surface_body));
  if (model_ == forward_model::scan) return head.scan_crossings(seen.nadir_scan, g.truth_disk);
  return head.bias_crossings(view.psi_bias, seen.eta_true, seen.phi_n_true, g.rho_truth);
}

namespace {

// The chain's workspace (sensor_physics/chain.hpp, ~100 KB): one
// per thread, made on the thread's first physics row and kept. compute_rows runs on every
// campaign worker at once (campaign_run.cpp), so a workspace is never shared between threads,
// and no row allocates.
sensor_physics_workspace<double>& physics_workspace() {
  thread_local const std::unique_ptr<sensor_physics_workspace<double>> work =
      std::make_unique<sensor_physics_workspace<double>>();
  return *work;
}

}  // namespace

crossings<double> simulation::physics_crossings(std::size_t h, const row_geometry& g,
                                                const head_truth& seen, const attitude_view& truth,
                                                const crossings<double>& geometric) const noexcept {
  const head_view& view = heads_[h];
  const sensor_head<double>& head = view.head;
  if (earth_ == earth_model::wgs84) {
    const ellipsoid_horizon<double> scan = head.in_scan_frame(g.surface_body);
    crossings<double> by_table;
    if (view.ellipsoid_table && geometric.state == status::ok &&
        view.ellipsoid_table->crossings_at(
            ellipsoid_table_point_of(scan, a_eq_m_, view.ellipsoid_table->axes(),
                                     truth.sin_sun_declination),
            geometric, by_table))
      return by_table;
    const ellipsoid_surface<double> surface = ellipsoid_surface_of(scan, a_eq_m_);
    return sensor_physics_crossings(*view.physics, head.circle(), surface,
                                    truth.sin_sun_declination, geometric, physics_workspace());
  }
  crossings<double> by_table;
  if (view.table && geometric.state == status::ok &&
      view.table->crossings_at({g.r_m, seen.eta_true, seen.phi_n_true}, geometric, by_table))
    return by_table;
  // The polar axis serves only the season term: without it, any unit vector.
  const vec3<double> polar = sphere_polar_ ? head.in_scan_frame(g.polar_body) : seen.nadir_scan;
  if (view.ellipsoid_table && geometric.state == status::ok &&
      view.ellipsoid_table->crossings_at(
          ellipsoid_table_point_of(sphere_in_scan_frame(seen.nadir_scan, g.r_m, polar), table_a_m(),
                                   view.ellipsoid_table->axes(), truth.sin_sun_declination),
          geometric, by_table))
    return by_table;
  const sphere_surface<double> surface =
      sphere_surface_of(seen.nadir_scan, g.truth_disk, truth_sphere_m(), polar);
  return sensor_physics_crossings(*view.physics, head.circle(), surface, truth.sin_sun_declination,
                                  geometric, physics_workspace());
}

crossings<double> simulation::measured_crossings(std::size_t h, const crossings<double>& truth,
                                                 double t, std::uint64_t k,
                                                 std::uint64_t run) const noexcept {
  const sensor_head<double>& head = heads_[h].head;
  // Each draw is a pure function of (seed, run, row, head, crossing), so runs are reproducible
  // on any machine and independent of evaluation order; none is drawn for a head without noise.
  const bool noisy = head.errors().noise > 0;
  crossings<double> c = head.measured(truth, noisy ? standard_normal(seed_, run, k, h, 0) : 0.0,
                                      noisy ? standard_normal(seed_, run, k, h, 1) : 0.0);
  if (correction_) c = correction_->corrected(k, t, h, c);
  return c;
}

void simulation::set_head_row(const crossings<double>& measured, const head_estimate<double>& est,
                              const head_truth& seen, const attitude_view& truth,
                              head_row& out) noexcept {
  out.state = est.state;
  if (est.state != status::ok) {
    const double nan = not_a_number<double>();
    out.chord_rad = out.phase_rad = out.eta_err_rad = out.roll_err_rad = out.pitch_err_rad = nan;
    return;
  }
  out.chord_rad = measured.chord();
  out.phase_rad = measured.phase();
  out.eta_err_rad = est.eta_s - seen.eta_true;
  if (truth.pitch_state != status::ok) {  // gimbal: the nadir error stands, roll has no meaning
    out.state = truth.pitch_state;
    out.roll_err_rad = out.pitch_err_rad = not_a_number<double>();
    return;
  }
  const roll_pitch<double> sensed = roll_pitch_from_nadir(est.nadir);
  out.roll_err_rad = wrap_pi(sensed.roll - truth.roll_true);
  out.pitch_err_rad = sensed.pitch - truth.pitch_true;
}

head_estimate<double> simulation::horizon_vector_solution(const head_estimate<double>& chord_phase,
                                                          const horizon_list& horizons,
                                                          const row_geometry& g,
                                                          row& out) const noexcept {
  // One least-squares nadir from every crossing, seeded from the chord/phase solution (which
  // picks the right mirror image when a single head is left), else from the nominal nadir.
  head_estimate<double> system = chord_phase;
  const vec3<double> seed_nadir = system.state == status::ok ? system.nadir : vec3<double>(0, 0, 1);
  if (horizons.count == 0) {
    system.state = status::none;
    return system;
  }
  const horizon_nadir_fit<double> fit = nadir_from_horizon_vectors(
      horizons.vectors.data(), horizons.count, g.assumed.cos_rho, seed_nadir);
  out.condition = fit.condition;
  system.nadir = fit.nadir;
  system.state = fit.state;
  return system;
}

void simulation::set_system_row(const head_estimate<double>& system, const attitude_view& truth,
                                int heads_ok, std::size_t last_ok, row& out) const noexcept {
  out.state = system.state == status::ok ? truth.pitch_state : system.state;
  if (out.state != status::ok) {
    out.roll_err_rad = out.pitch_err_rad = not_a_number<double>();
    return;
  }
  if (processing_ == processing_method::chord_phase && heads_ok == 1) {
    // The normalised mean of one unit vector is that vector: the system's errors are the
    // head's, already computed (saves the atan2s of a second roll/pitch).
    out.roll_err_rad = out.heads[last_ok].roll_err_rad;
    out.pitch_err_rad = out.heads[last_ok].pitch_err_rad;
    return;
  }
  const roll_pitch<double> sensed = roll_pitch_from_nadir(system.nadir);
  out.roll_err_rad = wrap_pi(sensed.roll - truth.roll_true);
  out.pitch_err_rad = sensed.pitch - truth.pitch_true;
}

// --- The intrusion step (MODEL §13, --intrusions) ---------------------------------------------

simulation::row_sky simulation::sky_at(double t, const orbit::orbit_state& st,
                                       const attitude_view& truth,
                                       const row_geometry& g) const noexcept {
  // Seam (MODEL §10): the row's ECI position is taken as TOD (scene_sky.hpp).
  const vec3<double>& r_tod = st.r_eci_m;
  const scene_sky::bodies seen = sky_->at(t, r_tod);
  // Body axes from ECI through the orbital frame (MODEL §2) and the true attitude.
  const mat3<double> eci_from_orbit = dcm_eci_from_orbit(st.r_eci_m, st.v_eci_m_s);
  const auto body_of = [&](const sources::body_view& v) {
    sky_body b;
    b.in_body = apply(truth.body_from_orbit, apply_transpose(eci_from_orbit, v.direction_tod));
    b.angular_radius = v.angular_radius_rad;
    // Hidden behind the horizon surface the truth crossings come from: the ellipsoid (in body
    // axes, as geometry_at made it) or the sphere R + h.
    b.hidden = earth_ == earth_model::wgs84
                   ? body_hidden_by_ellipsoid(g.surface_body, a_eq_m_,
                                              vec3<double>(b.in_body * v.distance_m))
                         .hidden
                   : body_hidden_by_sphere(vec3<double>(v.direction_tod * v.distance_m), r_tod,
                                           truth_sphere_m())
                         .hidden;
    return b;
  };
  return {body_of(seen.sun), body_of(seen.moon)};
}

status simulation::intrusion_check(std::size_t h, const crossings<double>& truth,
                                   const row_sky& sky, head_row& out) const noexcept {
  const sensor_head<double>& head = heads_[h].head;
  const double fov = heads_[h].fov_rad;
  const body_intrusion<double> sun = body_intrusion_of(
      head.circle(), truth, head.in_scan_frame(sky.sun.in_body), sky.sun.angular_radius, fov);
  const body_intrusion<double> moon = body_intrusion_of(
      head.circle(), truth, head.in_scan_frame(sky.moon.in_body), sky.moon.angular_radius, fov);
  out.sun_offset_rad = sun.cone_offset;
  out.moon_offset_rad = moon.cone_offset;
  return intrusion_status(truth, sun, sky.sun.hidden, moon, sky.moon.hidden);
}

void simulation::sky_check_at(double t_s, sky_check& out) const noexcept {
  const truth_state truth = truth_->truth_at(t_s);
  out.ok = sky_.has_value() && truth.ok;
  if (!out.ok) return;
  const orbit::orbit_state st{truth.r_eci_m, truth.v_eci_m_s, truth.true_anomaly_rad};
  const attitude_view view = view_at(truth);
  const row_geometry g = geometry_at(st, view);
  const row_sky sky = sky_at(t_s, st, view, g);
  out.r_tod_m = st.r_eci_m;  // the seam of sky_at (MODEL §10)
  out.v_tod_m_s = st.v_eci_m_s;
  const bool ellipsoid = earth_ == earth_model::wgs84;
  out.centre_tod_m = vec3<double>(0, 0, ellipsoid ? view.centre_z_m : 0.0);
  out.inner_radius_m = ellipsoid ? std::min(a_eq_m_, b_pol_m_) : truth_sphere_m();
  out.outer_radius_m = ellipsoid ? std::max(a_eq_m_, b_pol_m_) : truth_sphere_m();
  out.bodies = sky_->at(t_s, st.r_eci_m);
  // TOD from body axes: through the orbital frame (MODEL §2) and the true attitude.
  const mat3<double> eci_from_orbit = dcm_eci_from_orbit(st.r_eci_m, st.v_eci_m_s);
  head_row scratch{};
  for (std::size_t h = 0; h < heads_.size(); ++h) {
    const sensor_head<double>& head = heads_[h].head;
    const vec3<double>& a = head.circle().axis;  // scan-frame components
    const scan_frame<double>& f = head.frame();
    const vec3<double> axis_body = scaled(f.e1, a.x) + scaled(f.e2, a.y) + scaled(f.e3, a.z);
    sky_head& out_head = out.heads[h];
    out_head.axis_tod = apply(eci_from_orbit, apply_transpose(view.body_from_orbit, axis_body));
    out_head.fov_rad = heads_[h].fov_rad;
    out_head.state = intrusion_check(h, truth_crossings(h, g, view.heads[h]), sky, scratch);
    out_head.sun_offset_rad = scratch.sun_offset_rad;
    out_head.moon_offset_rad = scratch.moon_offset_rad;
  }
}

void simulation::compute_from_state(double t, const orbit::orbit_state& st,
                                    const attitude_view& truth, row& out, std::uint64_t run,
                                    std::uint64_t k) const noexcept {
  const row_geometry g = geometry_at(st, truth);
  out.t_s = t;
  out.true_anomaly_rad = st.true_anomaly_rad;
  out.r_m = g.r_m;
  out.rho_p_rad = g.rho_p;
  out.condition = not_a_number<double>();
  std::array<head_estimate<double>, max_heads> estimates;
  horizon_list horizons;
  int heads_ok = 0;
  std::size_t last_ok = 0;
  const row_sky sky = sky_ ? sky_at(t, st, truth, g) : row_sky{};  // the Sun and Moon, once
  for (std::size_t h = 0; h < heads_.size(); ++h) {
    const head_truth& seen = truth.heads[h];
    head_row& hr = out.heads[h];
    const crossings<double> geometric = truth_crossings(h, g, seen);  // 1. truth crossings
    // 1b. A body's pulse on the Earth's: the head loses the crossings (MODEL §13).
    const status blinded = sky_ ? intrusion_check(h, geometric, sky, hr) : status::ok;
    crossings<double> c = crossings<double>::failed(blinded);
    if (geometric.state != status::ok || blinded == status::ok) {
      // 1c. What the radiance, field, detector and locator make of the pulse (MODEL §12).
      const crossings<double> sensed =
          heads_[h].physics ? physics_crossings(h, g, seen, truth, geometric) : geometric;
      c = measured_crossings(h, sensed, t, k, run);  // 2. measurement
    }
    // Only the horizon-vector processing reads them; on the chord/phase path they would cost
    // four sincos per head and row for nothing (docs/PERFORMANCE.md).
    if (processing_ == processing_method::horizon_vector)
      horizons.count =
          append_horizon_vectors(heads_[h].head.frame(), heads_[h].head.optics().gamma, c,
                                 horizons.vectors.data(), horizons.count, horizons.vectors.size());
    estimates[h] = heads_[h].head.process(c, g.assumed);  // 3. processing
    hr.iterations = geometric.iterations;
    set_head_row(c, estimates[h], seen, truth, hr);  // 4. roll and pitch
    if (hr.state == status::ok) {
      ++heads_ok;
      last_ok = h;
    }
  }
  head_estimate<double> system =
      combine_heads<double>(estimates.begin(), estimates.begin() + heads_.size());
  if (processing_ == processing_method::horizon_vector)
    system = horizon_vector_solution(system, horizons, g, out);
  set_system_row(system, truth, heads_ok, last_ok, out);
}

}  // namespace conescan::scene

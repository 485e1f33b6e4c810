// The scene pipeline, one time step at a time (MODEL §3-§6): orbit -> frames -> per head: truth
// geometry -> crossings -> chord and phase -> inversion -> sensed nadir -> roll/pitch errors ->
// system solution.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "conescan/attitude.hpp"
#include "conescan/sensor_head.hpp"
#include "orbit/geodetic.hpp"
#include "orbit/kepler.hpp"
#include "scene/loaded_scene.hpp"
#include "scene/scene_config.hpp"
#include "scene/scene_earth.hpp"
#include "scene/scene_sky.hpp"
#include "simulation/truth_source.hpp"

namespace conescan {
template <class T>
struct sensor_physics_head;  // sensor_physics/chain.hpp
}  // namespace conescan

namespace conescan::scene {

class physics_table;            // physics_table.hpp
class ellipsoid_physics_table;  // physics_table.hpp

/// One head's columns (SI, rad). On any status but ok the numbers are NaN.
struct head_row {
  double chord_rad;      ///< W = phi_out - phi_in, (0, 2 pi)
  double phase_rad;      ///< m = (phi_in + phi_out) / 2, not wrapped
  double eta_err_rad;    ///< eta_s - eta (sensed minus true)
  double roll_err_rad;   ///< roll of n_s minus true roll
  double pitch_err_rad;  ///< pitch of n_s minus true pitch
  status state;
  int iterations;  ///< root-finder steps of the scan model (0 for the bias model)
  /// With --intrusions (MODEL §13): the Sun's and the Moon's angle from the true cone,
  /// angle(A, X) - gamma, rad, whatever the status (geometry: NaN only for a row without truth).
  double sun_offset_rad = 0;
  double moon_offset_rad = 0;
};

/// One time step (SI, rad).
struct row {
  double t_s;
  double true_anomaly_rad;  ///< not wrapped
  double r_m;
  double alt_m;      ///< geodetic, WGS84
  double lat_rad;    ///< geodetic, WGS84
  double rho_p_rad;  ///< Earth angular radius the processing assumed
  std::vector<head_row> heads;
  double roll_err_rad;  ///< system solution
  double pitch_err_rad;
  status state;      ///< ok or none (horizon-vector processing: also fold, invalid)
  double condition;  ///< horizon-vector processing: the fit's geometry figure; else NaN
};

/// A change of each head's measured crossings before the processing: conescan-sim --apply
/// subtracts a fit's modelled errors this way (src/scene_calibration/fit_correction.hpp).
class crossing_correction {
 public:
  virtual ~crossing_correction() = default;
  /// Row k (time t_s), head h (0-based): the crossings as measured, corrected. A measurement
  /// that cannot be corrected comes back failed, with the status saying why.
  virtual crossings<double> corrected(std::uint64_t k, double t_s, std::size_t head,
                                      const crossings<double>& measured) const noexcept = 0;
};

class simulation {
 public:
  /// The simulation of `scene`, or validate()'s diagnostic when the scene is invalid. Its physics
  /// tables are built on up to `threads` threads (the same tables on any number).
  static checked<simulation> of(const loaded_scene& scene, int threads = 1);
  /// The same for a caller without a plan (tests, benchmarks): load_scene(scene) first, its
  /// diagnostic when a file cannot be read.
  static checked<simulation> of(const scene_config& scene, int threads = 1);

  /// The truth the rows are computed from (truth_source.hpp): orbit, attitude, Sun.
  const truth_source& truth() const noexcept { return *truth_; }

  std::uint64_t rows() const noexcept { return rows_; }

  /// Every measurement corrected by `correction` (not owned; nullptr: none) before processing.
  void set_correction(const crossing_correction* correction) noexcept { correction_ = correction; }
  std::size_t head_count() const noexcept { return heads_.size(); }
  /// Whether head h's physics rows come from its table (physics_table.hpp) where they can.
  bool physics_by_table(std::size_t h) const noexcept {
    return heads_[h].table != nullptr || heads_[h].ellipsoid_table != nullptr;
  }
  double step_s() const noexcept { return step_s_; }

  /// A row with room for every head: compute() then never allocates.
  row make_row() const {
    return row{0, 0, 0, 0, 0, 0, std::vector<head_row>(heads_.size()), 0, 0, status::none, 0};
  }

  /// Fills `out` for t = k step of repetition `run` (0-based; runs differ only by their noise
  /// draws). `out` must come from make_row().
  void compute(std::uint64_t k, row& out, std::uint64_t run = 0) const noexcept {
    compute_rows(k, 1, &out, run);
  }

  /// Rows that compute_rows takes through the Kepler solve and the geodetic conversion together.
  static constexpr std::size_t rows_per_block = orbit::geodetic_lanes;
  static_assert(rows_per_block == orbit::kepler_lanes, "one block, one pass of each");

  /// out[i] = compute(first_k + i, ..., run) for i < count, bit for bit, in less time per row
  /// (docs/PERFORMANCE.md): the Kepler solve and the geodetic conversion run over up to
  /// rows_per_block rows at once.
  void compute_rows(std::uint64_t first_k, std::size_t count, row* out,
                    std::uint64_t run = 0) const noexcept;

  /// The row at any time t_s of the scene's span, not only at a multiple of the step, from the
  /// truth source (truth_at), with row 0's noise draws: for callers that ask what the scene's
  /// truth does at other times (the fit asks which heads the Sun and Moon blind at its
  /// telemetry's times, scene_calibration/scene_geometry.hpp). `out` must come from make_row().
  void compute_at(double t_s, row& out) const noexcept;

  /// One head against the Sun and the Moon at one time (sky_check_at).
  struct sky_head {
    vec3<double> axis_tod{0.0};  ///< the true optical axis A, unit, TOD
    double sun_offset_rad = 0;   ///< angle(A, X) - gamma of the Sun (hK_sun_deg, rad)
    double moon_offset_rad = 0;
    double fov_rad = 0;              ///< the field's full width (MODEL §13's eps = fov/2 + r_X)
    status state = status::invalid;  ///< intrusion_status: ok, sun, moon or the crossings' own
  };
  /// The Sun and the Moon against every head at one time, and the geometry an event finder
  /// bounds its steps with (blinding_calendar.hpp).
  struct sky_check {
    bool ok = false;  ///< the truth has a value at t_s
    vec3<double> r_tod_m{0.0}, v_tod_m_s{0.0};
    vec3<double> centre_tod_m{0.0};  ///< the centre of the horizon surface the crossings cut
    double inner_radius_m = 0;       ///< a sphere about the centre inside that surface
    double outer_radius_m = 0;       ///< and one that holds it
    scene_sky::bodies bodies{};      ///< seen from the satellite (scene_sky::at)
    std::array<sky_head, max_heads> heads{};
  };
  /// With --intrusions (MODEL §13): every head's verdict at any t_s of the scene's span, as
  /// compute_at's row has it (the same truth crossings, bodies and rule), without the sensor
  /// physics, the measurement or the processing: the blinding calendar's one question
  /// (blinding_calendar.hpp). Without --intrusions, out.ok is false.
  void sky_check_at(double t_s, sky_check& out) const noexcept;

 private:
  simulation() = default;
  /// of()'s work once the scene is valid and its truth built.
  void set_up(const loaded_scene& scene);
  /// The physics tables (physics_table.hpp): on the sphere without the season term, a pass over
  /// the rows' distances and nadir directions, then each physics head's table over its box; on
  /// the ellipsoid, with or without the season term, and on the sphere with it, the same over
  /// the six variables.
  void set_up_physics_tables(int threads);
  void set_up_ellipsoid_tables(int threads);
  /// Calls use(h, e, view) for every row and every head h that tabulated(h) admits: the row's
  /// truth surface e in the head's scan frame (the ellipsoid, or the sphere as the six-variable
  /// table sees it: sphere_in_scan_frame) and its true attitude view.
  template <class Tabulated, class Use>
  void for_each_table_surface(const Tabulated& tabulated, Use&& use) const;
  /// Calls visit(r, v, view) for every row's position, velocity (ECI, m and m/s) and true
  /// attitude, in row order.
  template <class Visit>
  void for_each_row_truth(Visit&& visit) const;

  /// A head and its bias model's fixed cone angle.
  struct head_view {
    sensor_head<double> head;
    result<double> psi_bias;  // the bias model's fixed cone angle, rad
    double fov_rad = 0;       // the field's full width (MODEL §13's pulses)
    // MODEL §12's chain, prepared once (scene_physics.hpp; sensor_physics/chain.hpp); null: the
    // crossings are §5's.
    std::shared_ptr<const sensor_physics_head<double>> physics;
    // The same crossings by table where the scene's rows pay for one (physics_table.hpp); null:
    // every row runs the chain.
    std::shared_ptr<const physics_table> table;
    // The six-variable table: on WGS84, and on the sphere with the season term.
    std::shared_ptr<const ellipsoid_physics_table> ellipsoid_table;
  };
  /// The true nadir as one head sees it.
  struct head_truth {
    double eta_true;          // true nadir's angle from S, rad (the bias model's input)
    double phi_n_true;        // its azimuth about S, rad
    vec3<double> nadir_scan;  // the unit true nadir in scan-frame components (the scan model's)
  };
  /// The true attitude and Sun of a row (constant_view_ for the whole scene when they are
  /// constant; per row from the truth source when not).
  struct attitude_view {
    double roll_true = 0, pitch_true = 0;  // of the true nadir in body axes, rad
    status pitch_state = status::ok;       // gimbal where roll is undefined (MODEL §7)
    mat3<double> body_from_orbit{1.0};
    double centre_z_m = 0;           // the truth ellipsoid's centre along ECI z (seasonal shift)
    double sin_sun_declination = 0;  // the radiance's season term (MODEL §12)
    std::array<head_truth, max_heads> heads{};
  };
  attitude_view view_of(double roll, double pitch, const mat3<double>& body_from_orbit,
                        double sun_declination_rad) const noexcept;
  attitude_view view_at(const truth_state& truth) const noexcept;

  /// The disks and the surface of one row: what the processing assumes and what is true.
  struct row_geometry {
    double r_m = 0;
    double rho_p = 0;             // the processing's disk radius, rad
    disk_trig<double> assumed{};  // the processing's disk
    disk_trig<double> truth_disk{not_a_number<double>(), not_a_number<double>(), status::invalid};
    double rho_truth = not_a_number<double>();  // the bias model's true disk radius, rad
    ellipsoid_horizon<double> surface_body{};   // the true ellipsoid in body axes
    vec3<double> polar_body{0.0};  // the sphere's polar axis in body axes (the radiance's season)
  };
  /// The crossings of every head, for the horizon-vector processing.
  struct horizon_list {
    std::array<vec3<double>, 2 * max_heads> vectors;
    std::size_t count = 0;
  };

  // The steps of compute_from_state (MODEL §5-§6).
  row_geometry geometry_at(const orbit::orbit_state& st, const attitude_view& truth) const noexcept;
  crossings<double> truth_crossings(std::size_t h, const row_geometry& g,
                                    const head_truth& seen) const noexcept;
  /// MODEL §12: the crossings head h's radiance, field, detector and locator make of its pulse,
  /// from its geometric crossings on the same surface (the one call of the chain: a faster method
  /// is switched here).
  crossings<double> physics_crossings(std::size_t h, const row_geometry& g, const head_truth& seen,
                                      const attitude_view& truth,
                                      const crossings<double>& geometric) const noexcept;
  crossings<double> measured_crossings(std::size_t h, const crossings<double>& truth, double t,
                                       std::uint64_t k, std::uint64_t run) const noexcept;
  static void set_head_row(const crossings<double>& measured, const head_estimate<double>& est,
                           const head_truth& seen, const attitude_view& truth,
                           head_row& out) noexcept;
  head_estimate<double> horizon_vector_solution(const head_estimate<double>& chord_phase,
                                                const horizon_list& horizons, const row_geometry& g,
                                                row& out) const noexcept;
  void set_system_row(const head_estimate<double>& system, const attitude_view& truth, int heads_ok,
                      std::size_t last_ok, row& out) const noexcept;

  // The intrusion step (MODEL §13, --intrusions), after the truth crossings: the bodies once per
  // row, then each head's verdict.
  /// A body of the row in body axes: unit direction, angular radius, and whether the Earth's
  /// horizon surface hides its centre.
  struct sky_body {
    vec3<double> in_body{0.0};
    double angular_radius = 0;
    bool hidden = false;
  };
  struct row_sky {
    sky_body sun, moon;
  };
  row_sky sky_at(double t, const orbit::orbit_state& st, const attitude_view& truth,
                 const row_geometry& g) const noexcept;
  /// Head h's verdict (ok, sun, moon, or its crossings' own status) against the row's bodies,
  /// from its true crossings; writes the head's two offset columns.
  status intrusion_check(std::size_t h, const crossings<double>& truth, const row_sky& sky,
                         head_row& out) const noexcept;

  /// compute() but for alt_m and lat_rad, from row k's time t, orbit state and true attitude.
  void compute_from_state(double t, const orbit::orbit_state& st, const attitude_view& truth,
                          row& out, std::uint64_t run, std::uint64_t k) const noexcept;
  /// compute_rows for a truth that varies beyond the Kepler orbit (files, the Sun's track).
  void compute_rows_from_truth(std::uint64_t first_k, std::size_t count, row* out,
                               std::uint64_t run) const noexcept;
  /// The truth ellipsoid seen from the satellite at r_eci (v_eci fixes the orbital frame), in
  /// body axes.
  ellipsoid_horizon<double> truth_surface_in_body(const vec3<double>& r_eci,
                                                  const vec3<double>& v_eci,
                                                  const attitude_view& truth) const noexcept;
  /// The Earth's polar axis (ECI z) in body axes at r_eci, v_eci under the truth attitude.
  static vec3<double> polar_in_body(const vec3<double>& r_eci, const vec3<double>& v_eci,
                                    const attitude_view& truth) noexcept;
  /// The truth sphere as the six-variable table sees it (physics_table.hpp, sphere_row_at): an
  /// ellipsoid of semi-axes R, R (kappa = 0) from the satellite at -r_m nadir_scan, in the head's
  /// scan frame with its polar axis.
  ellipsoid_horizon<double> sphere_in_scan_frame(const vec3<double>& nadir_scan, double r_m,
                                                 const vec3<double>& polar_scan) const noexcept;
  /// The six-variable table's equatorial radius: the truth sphere's R, or the ellipsoid's a_eq.
  double table_a_m() const noexcept;
  /// The truth sphere's radius: R raised by the horizon's height (the surface the sphere's rows
  /// and tables see).
  double truth_sphere_m() const noexcept { return truth_radius_m_ + horizon_m_; }

  std::optional<truth_source> truth_;
  double step_s_ = 0;
  std::uint64_t rows_ = 0;
  earth_model earth_ = earth_model::sphere;
  forward_model model_ = forward_model::bias;
  double truth_radius_m_ = 0;  // sphere R
  double horizon_m_ = 0;
  double a_eq_m_ = 0, b_pol_m_ = 0;  // truth ellipsoid semi-axes (inflated or apparent)
  double horizon_shift_m_ = 0;       // its centre moves by this times sin(Sun's declination)
  bool sphere_polar_ = false;  // the physics' season term on the sphere: geometry_at's polar_body
  double processing_horizon_m_ = 0;
  processing_sphere processing_sphere_{};
  std::uint64_t seed_ = 0;
  processing_method processing_ = processing_method::chord_phase;
  std::vector<head_view> heads_;
  const crossing_correction* correction_ = nullptr;
  attitude_view constant_view_;   // the truth's constant attitude and Sun (when they are)
  std::optional<scene_sky> sky_;  // with --intrusions: the Sun and Moon (MODEL §13)
};

}  // namespace conescan::scene

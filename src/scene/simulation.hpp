// The scene pipeline, one time step at a time (SPEC §3-§6): orbit -> frames -> per head: truth
// geometry -> crossings -> chord and phase -> inversion -> sensed nadir -> roll/pitch errors ->
// system solution.
#pragma once

#include <cstdint>
#include <vector>

#include "conescan/crossings.hpp"
#include "conescan/scan_frame.hpp"
#include "orbit/geodetic.hpp"
#include "orbit/kepler.hpp"
#include "scene/scene_config.hpp"

namespace conescan::scene {

/// One head's columns (SI, rad). On any status but ok the numbers are NaN.
struct head_row {
  double chord_rad;      ///< W = phi_out - phi_in, (0, 2 pi)
  double phase_rad;      ///< m = (phi_in + phi_out) / 2, not wrapped
  double eta_err_rad;    ///< eta_s - eta (sensed minus true)
  double roll_err_rad;   ///< roll of n_s minus true roll
  double pitch_err_rad;  ///< pitch of n_s minus true pitch
  status state;
  int iterations;  ///< root-finder steps of the scan model (0 for the bias model)
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

class simulation {
 public:
  /// Throws std::invalid_argument with validate()'s message when the scene is invalid.
  explicit simulation(const scene_config& scene);

  std::uint64_t rows() const noexcept { return rows_; }
  std::size_t head_count() const noexcept { return heads_.size(); }
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

 private:
  struct head_geometry {
    head_optics<double> optics;  // rad
    scan_frame<double> frame_body;
    scan_frame<double> frame_orbit;  // the same axes in the orbital frame
    double eta_true;                 // true nadir's angle from S, rad
    double phi_n_true;               // true nadir's azimuth about S, rad
    double eta0;                     // nominal nadir angle of the spin axis, rad
    result<double> psi_bias;         // the bias model's fixed cone angle (SPEC §5)
    double noise_rad;                // detector noise per crossing, 1 sigma
    double lsb_rad;                  // telemetry quantisation step
  };

  double processing_radius_m(const vec3<double>& r_eci) const noexcept;
  /// compute() but for alt_m and lat_rad, from row k's time t and orbit state.
  void compute_from_state(double t, const orbit::orbit_state& st, row& out, std::uint64_t run,
                          std::uint64_t k) const noexcept;

  orbit::kepler_orbit orbit_;
  double step_s_ = 0;
  std::uint64_t rows_ = 0;
  earth_model earth_ = earth_model::sphere;
  forward_model model_ = forward_model::bias;
  double truth_radius_m_ = 0;  // sphere R
  double horizon_m_ = 0;
  double a_eq_m_ = 0, b_pol_m_ = 0;  // truth ellipsoid semi-axes (inflated or apparent)
  double centre_z_m_ = 0;            // its centre's offset along ECI z (seasonal shift)
  double processing_horizon_m_ = 0;
  std::uint64_t seed_ = 0;
  processing_method processing_ = processing_method::chord_phase;
  processing_radius_kind processing_kind_ = processing_radius_kind::truth;
  double processing_value_m_ = 0;
  double roll_true_ = 0, pitch_true_ = 0;
  std::vector<head_geometry> heads_;
};

}  // namespace conescan::scene

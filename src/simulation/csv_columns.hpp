// The columns of conescan-sim's output (MODEL §9) and their conversions from the simulation's SI
// and radians, written once: conescan-sim's CSV (src/cli/csv_rows.cpp) and the Python
// module's arrays (python/src/scenes.cpp) both take every number from here, so that
// conescan.simulate() holds bit for bit the doubles whose shortest text conescan-sim prints.
//
//   rows:     [sweep value] [run] [seed] t_s,nu_deg,r_km,alt_km,lat_deg,rho_deg,
//             per head K: hK_chord_deg,hK_phase_deg,hK_eta_err_deg,hK_roll_err_deg,
//             hK_pitch_err_deg,hK_status [,hK_sun_deg,hK_moon_deg], then roll_err_deg,
//             pitch_err_deg,status [,condition]
//   summary:  [sweep value] [run] [seed] source,rows,<a count per status>,roll_min_deg, ...,
//             pitch_3sigma_deg [,sun_lost_fraction,moon_lost_fraction] (one line per head and
//             the system)
//   budget:   t_s,nu_deg, per source NAME_roll_err_deg,NAME_pitch_err_deg,NAME_status, then
//             the same of the sum and of the interaction (all − sum); its summary has a line per
//             source, the sum and the interaction, without leading columns
//
// The leading columns appear when some scene of the plan has them: the swept option (named as
// the sweep names it, "e", "h1.alpha"), the run (with --runs > 1: the run, 1-based; in a summary
// the number of runs), the seed (with detector noise). `condition` follows the system's status
// with --processing horizon-vector. With --intrusions (MODEL §13) each head's columns end with
// its two bodies' angles from the cone, and each summary line with the fractions of its rows
// lost to each body (status sun, moon: a count over rows, so shards and runs merge exactly).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "conescan/scalar.hpp"
#include "scene/scene_plan.hpp"
#include "simulation/budget_run.hpp"
#include "simulation/simulation.hpp"
#include "simulation/summary.hpp"

namespace conescan::scene {

// --- Conversions (MODEL §1) -------------------------------------------------------------------

/// An angle in degrees in [0, 360) (nu_deg), from radians.
inline double degrees_0_360(double rad) noexcept {
  // Already in [0, 360): fmod would return it exactly; skip the call (docs/PERFORMANCE.md).
  const double deg = rad_to_deg(rad);
  if (deg >= 0 && deg < 360) return deg;
  double d = std::fmod(deg, 360.0);
  if (d < 0) d += 360;
  return d >= 360 ? 0 : d;
}

/// An angle in degrees in (-180, 180] (phases and errors), from radians.
inline double degrees_pm180(double rad) noexcept {
  // Already in (-180, 180] (every error column of a working sensor): remainder would return it
  // exactly, and it is the slowest call of a row (docs/PERFORMANCE.md).
  const double deg = rad_to_deg(rad);
  if (deg > -180 && deg <= 180) return deg;
  const double d = std::remainder(deg, 360.0);  // [-180, 180]
  return d <= -180 ? d + 360 : d;
}

/// A length in km, from metres.
inline double km_from_m(double m) noexcept {
  return m / 1000;
}

// --- Row columns ------------------------------------------------------------------------------

/// What a column holds: a real in the column's unit, a status, a count (run, seed, rows:
/// integers beyond a double's 2^53, written exactly), or a word (a summary's source).
enum class column_kind { real, state, count, text };

/// Which column a value of a row is, for writers that treat some alike (csv_rows.cpp reuses the
/// text of a head's error for the system's equal one).
enum class row_column {
  t_s,
  nu_deg,
  r_km,
  alt_km,
  lat_deg,
  rho_deg,
  head_chord_deg,
  head_phase_deg,
  head_eta_err_deg,
  head_roll_err_deg,
  head_pitch_err_deg,
  head_status,
  head_sun_deg,
  head_moon_deg,
  roll_err_deg,
  pitch_err_deg,
  status,
  condition,
};

struct column_name {
  std::string name;
  column_kind kind;
};

/// The leading columns of a plan's rows and summary lines (see the top of this file), and the
/// trailing `condition`.
struct leading_layout {
  std::string sweep;  ///< the swept option's name, or "" without a sweep
  bool run = false;
  bool seed = false;
  bool condition = false;   ///< rows only: --processing horizon-vector
  bool intrusions = false;  ///< --intrusions: the heads' body columns, the summary's fractions

  /// The leading columns' names and kinds, in order (condition is not one of them).
  std::vector<column_name> columns() const;
};

/// The leading columns of a plan's rows and summary lines; none for the error budget (one scene,
/// one run; its noise is a source of its own), whose summary still ends with the lost fractions
/// under --intrusions; in conescan-sim's CSV and Python alike.
leading_layout leading_layout_of(const scene_plan& plan);

/// The leading values of scene j of `plan` in run `run`: the swept value, the run (1-based; a
/// summary gives the number of runs), the seed; only those the layout has, in its order.
struct leading_value {
  double real = 0;
  std::uint64_t count = 0;
  bool is_count = false;
};
std::vector<leading_value> leading_values(const leading_layout& layout, const scene_plan& plan,
                                          std::uint64_t j, const scene_config& scene,
                                          std::uint64_t run);

/// A row's columns after the leading ones, for `heads` heads (with --intrusions: each head's
/// hK_sun_deg, hK_moon_deg after its status).
std::vector<column_name> row_columns(std::size_t heads, bool condition, bool intrusions = false);

namespace detail {
/// A system solution's three columns: roll_err_deg, pitch_err_deg, status.
template <class Writer>
void visit_errors(Writer& out, double roll_rad, double pitch_rad, status state) {
  out.real(row_column::roll_err_deg, degrees_pm180(roll_rad));
  out.real(row_column::pitch_err_deg, degrees_pm180(pitch_rad));
  out.state(row_column::status, state);
}
}  // namespace detail

/// Calls out.real(column, value) and out.state(column, status) for each of a row's columns
/// after the leading ones, in order, in the columns' units. The values are the CSV's: -0 and NaN
/// as computed (the CSV writes both "0" and "nan" for them). The body columns are degrees, not
/// wrapped: angle(A, X) - gamma lies in [-gamma, 180 - gamma].
template <class Writer>
void visit_row(const row& r, bool condition, Writer& out, bool intrusions = false) {
  out.real(row_column::t_s, r.t_s);
  out.real(row_column::nu_deg, degrees_0_360(r.true_anomaly_rad));
  out.real(row_column::r_km, km_from_m(r.r_m));
  out.real(row_column::alt_km, km_from_m(r.alt_m));
  out.real(row_column::lat_deg, rad_to_deg(r.lat_rad));
  out.real(row_column::rho_deg, rad_to_deg(r.rho_p_rad));
  for (const head_row& h : r.heads) {
    out.real(row_column::head_chord_deg, rad_to_deg(h.chord_rad));
    out.real(row_column::head_phase_deg, degrees_pm180(h.phase_rad));
    out.real(row_column::head_eta_err_deg, degrees_pm180(h.eta_err_rad));
    out.real(row_column::head_roll_err_deg, degrees_pm180(h.roll_err_rad));
    out.real(row_column::head_pitch_err_deg, degrees_pm180(h.pitch_err_rad));
    out.state(row_column::head_status, h.state);
    if (intrusions) {
      out.real(row_column::head_sun_deg, rad_to_deg(h.sun_offset_rad));
      out.real(row_column::head_moon_deg, rad_to_deg(h.moon_offset_rad));
    }
  }
  detail::visit_errors(out, r.roll_err_rad, r.pitch_err_rad, r.state);
  if (condition) out.real(row_column::condition, r.condition);
}

// --- Budget columns ---------------------------------------------------------------------------

/// The name of the budget's sum of the single sources, in its columns and summary.
inline constexpr const char* budget_sum_name = "sum";
/// The name of what `all` holds beyond that sum (all − sum), in its columns and summary.
inline constexpr const char* budget_interaction_name = "interaction";

/// A budget row's columns for these sources.
std::vector<column_name> budget_columns(const std::vector<budget_source>& sources);

/// As visit_row, for a budget row: t_s, nu_deg, then each source's, the sum's and the
/// interaction's system roll, pitch and status (row_column::roll_err_deg, pitch_err_deg, status).
template <class Writer>
void visit_budget_row(const budget_row& r, Writer& out) {
  const row& first = r.sources.front();
  out.real(row_column::t_s, first.t_s);
  // Wrapped in radians, then converted: what conescan-sim's budget has always printed (its rows'
  // nu_deg convert first, degrees_0_360; the two may differ in the last bit).
  out.real(row_column::nu_deg, rad_to_deg(wrap_two_pi(first.true_anomaly_rad)));
  for (const row& source : r.sources)
    detail::visit_errors(out, source.roll_err_rad, source.pitch_err_rad, source.state);
  detail::visit_errors(out, r.roll_sum_rad, r.pitch_sum_rad, r.sum_state);
  detail::visit_errors(out, r.roll_interaction_rad, r.pitch_interaction_rad, r.interaction_state);
}

// --- Summary columns --------------------------------------------------------------------------

/// A summary line's columns after the leading ones: source (text: "h1", ..., "system"), rows,
/// a count per status in the order of all_statuses, then the twelve statistics of
/// summary_statistics_deg, then with --intrusions summary_lost_fractions' two.
std::vector<column_name> summary_columns(bool intrusions = false);

/// With --intrusions: the fractions of a source's rows lost to the Sun and to the Moon, its
/// status counts sun and moon over its rows (NaN without rows). The system's are 0: it is never
/// blinded itself (the rows the bodies cost it are in its count of `none`).
std::array<double, 2> summary_lost_fractions(const error_statistics& s);

/// The names of the twelve statistics: roll_min_deg, roll_max_deg, roll_mean_deg, roll_rms_deg,
/// roll_std_deg, roll_3sigma_deg, then the same of pitch.
std::array<const char*, 12> summary_statistic_names();

/// The twelve statistics of a source in degrees, over its ok rows: min, max, mean (NaN without
/// ok rows), RMS (NaN without), sample standard deviation and 3 times it (NaN below two).
std::array<double, 12> summary_statistics_deg(const error_statistics& s);

/// The name of head k's summary line (0-based k: "h1", ...), and the system's ("system").
std::string summary_source_name(std::size_t head);
inline constexpr const char* summary_system_name = "system";

}  // namespace conescan::scene

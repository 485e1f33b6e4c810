// The CSV contract of MODEL §9: header and rows as text. The columns and every conversion to km
// and degrees are the simulation layer's (src/simulation/csv_columns.hpp), shared with the
// Python module.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cli/output_sink.hpp"
#include "scene/scene_plan.hpp"
#include "simulation/csv_columns.hpp"
#include "simulation/simulation.hpp"
#include "simulation/summary.hpp"

namespace conescan::cli {

/// Columns beyond MODEL §9's, each only when used: before t_s the swept option, the run and the
/// seed; after the system's status, the horizon-vector fit's `condition`
/// (scene::leading_layout_of says which a plan has).
struct leading_columns {
  /// A real (the swept value) or a count (the run, the seed: written as integers, exactly).
  using value = scene::leading_value;
  std::vector<std::string> names;
  std::vector<value> values;  ///< one per name, updated as the run goes
  bool condition = false;
  bool intrusions = false;  ///< --intrusions: per head hK_sun_deg,hK_moon_deg; summary fractions

  /// The leading columns of a plan's rows and summary lines (scene::leading_layout_of).
  static leading_columns of(const scene::scene_plan& plan);
  /// The values for scene j of `plan` in run `run` (1-based; a summary's: the number of runs).
  void set(const scene::scene_plan& plan, std::uint64_t j, const scene::scene_config& scene,
           std::uint64_t run);

  void write_names(output_sink& out) const;
  void write_values(output_sink& out) const;

 private:
  scene::leading_layout layout_;
};

/// t_s,nu_deg,r_km,alt_km,lat_deg,rho_deg, per head hk_chord_deg..hk_status, then the system's
/// roll_err_deg,pitch_err_deg,status; the leading columns first.
void write_header(output_sink& out, std::size_t heads, const leading_columns& leading);

/// One row. Angles wrapped as MODEL §1 says: nu in [0, 360), phase and errors in (-180, 180].
void write_row(output_sink& out, const scene::row& row, const leading_columns& leading);

/// --budget's header: t_s,nu_deg, each source's and the sum's roll, pitch and status.
void write_budget_csv_header(output_sink& out, const std::vector<scene::budget_source>& sources);

/// One --budget row (scene::visit_budget_row) and its '\n'; like write_row, the caller ends the
/// row (output_sink::end_row): a campaign worker's buffer (fd -1) must never flush.
void write_budget_csv_row(output_sink& out, const scene::budget_row& row);

/// --summary's header: the leading names, source,rows, a count per status, the statistics.
void write_summary_header(output_sink& out, const leading_columns& leading);

/// One --summary line: the leading values, the source ("h1", ..., "system"), the counts and the
/// statistics in degrees (scene::summary_statistics_deg), ending the row.
void write_summary_line(output_sink& out, const leading_columns& leading, const std::string& source,
                        const scene::error_statistics& statistics);

/// An angle in degrees wrapped to (-180, 180] (MODEL §1), from radians.
using scene::degrees_pm180;

}  // namespace conescan::cli

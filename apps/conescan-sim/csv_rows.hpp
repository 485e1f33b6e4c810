// The CSV contract of SPEC §9: header and rows as text. The columns and every conversion to km
// and degrees are the scene layer's (src/scene/csv_columns.hpp), shared with the Python module.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "output_sink.hpp"
#include "scene/csv_columns.hpp"
#include "scene/simulation.hpp"

namespace conescan::cli {

/// Columns beyond SPEC §9's, each only when used: before t_s the swept option, the run and the
/// seed; after the system's status, the horizon-vector fit's `condition`
/// (scene::leading_layout_of says which a plan has).
struct leading_columns {
  /// A real (the swept value) or a count (the run, the seed: written as integers, exactly).
  using value = scene::leading_value;
  std::vector<std::string> names;
  std::vector<value> values;  ///< one per name, updated as the run goes
  bool condition = false;

  void write_names(output_sink& out) const;
  void write_values(output_sink& out) const;
};

/// t_s,nu_deg,r_km,alt_km,lat_deg,rho_deg, per head hk_chord_deg..hk_status, then the system's
/// roll_err_deg,pitch_err_deg,status; the leading columns first.
void write_header(output_sink& out, std::size_t heads, const leading_columns& leading);

/// One row. Angles wrapped as SPEC §1 says: nu in [0, 360), phase and errors in (-180, 180].
void write_row(output_sink& out, const scene::row& row, const leading_columns& leading);

/// An angle in degrees wrapped to (-180, 180] (SPEC §1), from radians.
using scene::degrees_pm180;

}  // namespace conescan::cli

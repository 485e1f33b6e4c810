// The CSV contract of SPEC §9: header and rows in km, s and degrees.
#pragma once

#include <string>

#include "output_sink.hpp"
#include "scene/simulation.hpp"

namespace conescan::cli {

/// t_s,nu_deg,r_km,alt_km,lat_deg,rho_deg, per head hk_chord_deg..hk_status, then the system's
/// roll_err_deg,pitch_err_deg,status. A non-empty `sweep_name` comes first.
void write_header(output_sink& out, std::size_t heads, const std::string& sweep_name);

/// One row; with a sweep, `sweep_value` comes first. Angles wrapped as SPEC §1 says: nu in
/// [0, 360), phase and errors in (-180, 180].
void write_row(output_sink& out, const scene::row& row, const std::string& sweep_name,
               double sweep_value);

}  // namespace conescan::cli

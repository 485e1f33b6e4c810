#include "csv_rows.hpp"

#include <cmath>

#include "conescan/scalar.hpp"

namespace conescan::cli {

namespace {

// SPEC §1: nu_deg in [0, 360).
double degrees_0_360(double rad) {
  // Already in [0, 360): fmod would return it exactly; skip the call (docs/PERFORMANCE.md).
  const double deg = rad_to_deg(rad);
  if (deg >= 0 && deg < 360) return deg;
  double d = std::fmod(deg, 360.0);
  if (d < 0) d += 360;
  return d >= 360 ? 0 : d;
}

void field(output_sink& out, double value) {
  out.append(',');
  out.append_number(value);
}

/// A number written earlier in the row, and where its text is.
struct written_number {
  double value;
  std::size_t from, to;
};

written_number field_noting_text(output_sink& out, double value) {
  out.append(',');
  const std::size_t from = out.size();
  out.append_number(value);
  return {value, from, out.size()};
}

/// A field whose value may have been written already: one measuring head's errors are the
/// system's (scene/simulation.cpp), and copying their text costs a tenth of formatting it again.
void field_reusing(output_sink& out, double value, const written_number& earlier) {
  if (value != earlier.value) return field(out, value);  // also NaN: "nan" is cheap anyway
  out.append(',');
  out.append_copy(earlier.from, earlier.to);
}

}  // namespace

// SPEC §1: (-180, 180].
double degrees_pm180(double rad) {
  // Already in (-180, 180] (every error column of a working sensor): remainder would return it
  // exactly, and it is the slowest call of a row (docs/PERFORMANCE.md).
  const double deg = rad_to_deg(rad);
  if (deg > -180 && deg <= 180) return deg;
  double d = std::remainder(deg, 360.0);  // [-180, 180]
  return d <= -180 ? d + 360 : d;
}

void leading_columns::write_names(output_sink& out) const {
  for (const std::string& name : names) {
    out.append(name);
    out.append(',');
  }
}

void leading_columns::write_values(output_sink& out) const {
  for (const value& v : values) {
    if (v.is_count)
      out.append_count(v.count);
    else
      out.append_number(v.real);
    out.append(',');
  }
}

void write_header(output_sink& out, std::size_t heads, const leading_columns& leading) {
  leading.write_names(out);
  out.append("t_s,nu_deg,r_km,alt_km,lat_deg,rho_deg");
  for (std::size_t k = 1; k <= heads; ++k) {
    const std::string h = ",h" + std::to_string(k) + "_";
    for (const char* column :
         {"chord_deg", "phase_deg", "eta_err_deg", "roll_err_deg", "pitch_err_deg", "status"}) {
      out.append(h);
      out.append(column);
    }
  }
  out.append(leading.condition ? ",roll_err_deg,pitch_err_deg,status,condition\n"
                               : ",roll_err_deg,pitch_err_deg,status\n");
  out.end_row();
}

void write_row(output_sink& out, const scene::row& row, const leading_columns& leading) {
  leading.write_values(out);
  out.append_number(row.t_s);
  field(out, degrees_0_360(row.true_anomaly_rad));
  field(out, row.r_m / 1000);
  field(out, row.alt_m / 1000);
  field(out, rad_to_deg(row.lat_rad));
  field(out, rad_to_deg(row.rho_p_rad));
  const double nan = not_a_number<double>();
  written_number head_roll{nan, 0, 0}, head_pitch{nan, 0, 0};  // of the last head that measured
  for (const scene::head_row& h : row.heads) {
    field(out, rad_to_deg(h.chord_rad));
    field(out, degrees_pm180(h.phase_rad));
    field(out, degrees_pm180(h.eta_err_rad));
    if (h.state == status::ok) {
      head_roll = field_noting_text(out, degrees_pm180(h.roll_err_rad));
      head_pitch = field_noting_text(out, degrees_pm180(h.pitch_err_rad));
    } else {
      field(out, degrees_pm180(h.roll_err_rad));
      field(out, degrees_pm180(h.pitch_err_rad));
    }
    out.append(',');
    out.append(to_string(h.state));
  }
  field_reusing(out, degrees_pm180(row.roll_err_rad), head_roll);
  field_reusing(out, degrees_pm180(row.pitch_err_rad), head_pitch);
  out.append(',');
  out.append(to_string(row.state));
  if (leading.condition) field(out, row.condition);
  out.append('\n');
}

}  // namespace conescan::cli

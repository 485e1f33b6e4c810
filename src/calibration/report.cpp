#include "calibration/report.hpp"

#include <charconv>
#include <cmath>

namespace conescan::calibration {

std::string short_number(double value, int digits) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  const auto r =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, digits);
  return std::string(buffer, r.ptr);
}

namespace {

std::string padded(const std::string& text, std::size_t width, bool right = true) {
  if (text.size() >= width) return text;
  const std::string fill(width - text.size(), ' ');
  return right ? fill + text : text + fill;
}

/// A correlation with 4 decimals, "-" when withheld.
std::string fixed4(double value) {
  if (std::isnan(value)) return "-";
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, 4);
  return std::string(buffer, r.ptr);
}

std::size_t name_width(const uncertainty_report& u) {
  std::size_t width = 9;
  for (const parameter_estimate& p : u.parameters)
    if (!p.absent) width = std::max(width, p.name.size());
  return width;
}

std::string parameter_rows(const uncertainty_report& u, const char* sigma_title) {
  const std::size_t w = name_width(u);
  std::string out = padded("parameter", w, false) + "  " + padded("estimate", 14) + "  " +
                    padded(sigma_title, 12) + "  unit\n";
  for (const parameter_estimate& p : u.parameters) {
    if (p.absent) continue;
    out += padded(p.name, w, false) + "  ";
    if (!p.free)
      out += padded(short_number(p.estimate), 14) + "  " + padded("held", 12) + "  " + p.unit;
    else if (!p.determined)
      out += padded("-", 14) + "  " + padded("-", 12) + "  " + p.unit + "  " + p.withheld;
    else
      out += padded(short_number(p.estimate), 14) + "  " + padded(short_number(p.sigma), 12) +
             "  " + p.unit;
    out += "\n";
  }
  return out;
}

/// The correlation of the reported values; with drifting parameters, of the global ones only
/// (the segments' correlations are in the JSON).
std::string correlation_rows(const uncertainty_report& u) {
  std::vector<std::size_t> shown;
  for (std::size_t i = 0; i < u.reported.size(); ++i)
    if (u.reported[i].name == u.parameters[u.reported[i].index].name) shown.push_back(i);
  if (shown.size() < 2) return "";
  const std::size_t w = name_width(u);
  std::string out = std::string("\ncorrelation of the free parameters") +
                    (u.drift.empty() ? "" : " (global; with the segments: in the JSON)") + "\n" +
                    std::string(w, ' ');
  for (std::size_t j = 0; j < shown.size(); ++j) out += "  " + padded(std::to_string(j + 1), 7);
  out += "\n";
  for (std::size_t i = 0; i < shown.size(); ++i) {
    out += padded(std::to_string(i + 1) + " " + u.reported[shown[i]].name, w, false);
    for (std::size_t j : shown) out += "  " + padded(fixed4(u.correlation[shown[i]][j]), 7);
    out += "\n";
  }
  return out;
}

/// Each drifting parameter's values, one row per segment.
std::string drift_rows(const uncertainty_report& u) {
  std::string out;
  for (const drift_history& h : u.drift) {
    out += "\nhistory of " + h.name + " (one value per " + short_number(h.segment_s) +
           " s; t_s from, to, measurements, estimate, 1 sigma)\n";
    for (const drift_segment& d : h.segments) {
      out += padded(h.name + "[" + std::to_string(&d - h.segments.data()) + "]", 18, false) +
             padded(short_number(d.start_s), 12) + padded(short_number(d.end_s), 12) +
             padded(std::to_string(d.observations), 12) + "  ";
      out += d.value.determined ? padded(short_number(d.value.estimate), 14) + "  " +
                                      padded(short_number(d.value.sigma), 12) + "  " + h.unit
                                : padded("-", 14) + "  " + padded("-", 12) + "  " + h.unit + "  " +
                                      d.value.withheld;
      out += "\n";
    }
  }
  return out;
}

std::string observability_rows(const uncertainty_report& u) {
  std::string out = "condition number " + short_number(u.condition) +
                    " (of the normalised information matrix: each parameter in units of its own "
                    "1 sigma)\n";
  if (u.unobservable.empty()) return out + "unobservable combinations: none\n";
  out +=
      "unobservable combinations (the data cannot separate them; the parameters involved "
      "are not estimated):\n";
  for (const unobservable_combination& c : u.unobservable) {
    out += " ";
    for (std::size_t i = 0; i < c.components.size(); ++i) {
      const double v = c.components[i].second;
      out += (i == 0 ? (v < 0 ? " -" : " ") : (v < 0 ? " - " : " + ")) + short_number(std::abs(v)) +
             " " + c.components[i].first;
    }
    out += "   (eigenvalue ratio " + short_number(c.eigenvalue_ratio) + ")\n";
  }
  return out;
}

std::string outlier_rows(const fit_result& r) {
  std::string out = "outliers (normalised residual above " + short_number(r.outlier_threshold) +
                    "): " + std::to_string(r.outlier_count) + "\n";
  for (const outlier& o : r.worst_outliers)
    out += "  t_s " + short_number(o.sample.t_s) + "  h" + std::to_string(o.sample.head + 1) +
           "  chord " + short_number(o.chord_residual_deg) + " deg  phase " +
           short_number(o.phase_residual_deg) + " deg  (" + short_number(o.normalised) + ")\n";
  return out;
}

/// Per head the declared and the estimated noise, and what the weights used.
std::string noise_rows(const fit_result& r) {
  if (r.noise.empty()) return "";
  std::string out = "noise (deg)  " + padded("declared", 10) + "  " + padded("estimated", 11) +
                    "  " + padded("ratio", 9) + "  weights\n";
  for (std::size_t k = 0; k < r.noise.size(); ++k) {
    const head_noise_estimate& n = r.noise[k];
    out += padded("h" + std::to_string(k + 1), 11, false) + "  " +
           padded(r.unit_weights ? "none" : short_number(n.declared_deg), 10) + "  " +
           padded(short_number(n.estimated_deg), 11) + "  " + padded(short_number(n.ratio), 9) +
           "  " +
           (n.weight_ratio == 1 ? std::string(r.unit_weights ? "1 deg" : "declared")
                                : (r.unit_weights ? "1 deg" : "declared") + std::string(" x ") +
                                      short_number(n.weight_ratio)) +
           "\n";
  }
  return out;
}

/// Per head the measurements the model cannot predict at the solution.
std::string dropped_row(const fit_result& r) {
  if (r.dropped_per_head.empty()) return "";
  std::string out = "dropped (the model cannot predict them at the solution):";
  for (std::size_t k = 0; k < r.dropped_per_head.size(); ++k) {
    const double all = static_cast<double>(r.dropped_per_head[k] + r.observations_per_head[k]);
    out += "  h" + std::to_string(k + 1) + " " + std::to_string(r.dropped_per_head[k]) + " (" +
           short_number(all > 0 ? 100 * static_cast<double>(r.dropped_per_head[k]) / all : 0.0, 3) +
           " %)";
  }
  return out + "\n";
}

std::string systematic_rows(const fit_result& r) {
  std::string out;
  for (const systematic_effect& e : r.systematic)
    out += "systematic: h" + std::to_string(e.head + 1) + (e.phase ? " phase" : " chord") +
           " residuals of " + std::to_string(e.same_sign) + " of " + std::to_string(e.outliers) +
           " outliers " + (e.sign > 0 ? "positive" : "negative") + ", mean " +
           short_number(e.mean_residual_deg) + " deg (by chance: probability " +
           short_number(e.probability, 2) + ")\n";
  return out;
}

std::string warning_rows(const fit_result& r) {
  std::string out;
  for (const std::string& w : r.warnings) out += "warning: " + w + "\n";
  return out;
}

/// "left out, blinded (MODEL 13): h1 130 by the Sun, 0 by the Moon; h2 ...", or "" without
/// --intrusions.
std::string blinded_line(const blinded_rows& b) {
  if (b.sun.empty()) return "";
  std::string out = "rows left out because a body blinded the head (MODEL 13):";
  for (std::size_t k = 0; k < b.sun.size(); ++k)
    out += std::string(k ? ";" : "") + " h" + std::to_string(k + 1) + " " +
           std::to_string(b.sun[k]) + " by the Sun, " + std::to_string(b.moon[k]) + " by the Moon";
  return out + "\n";
}

std::string converged_table(const fit_result& r) {
  const uncertainty_report& u = r.uncertainty;
  std::string out = "converged in " + std::to_string(r.iterations) +
                    " iterations: " + std::to_string(r.residual_count) + " residuals, " +
                    std::to_string(u.free_parameters.size()) + " free parameters, " +
                    (u.reported.size() == u.free_parameters.size()
                         ? std::string()
                         : std::to_string(u.reported.size()) + " estimated values, ");
  out += r.loss == robust_loss::huber
             ? "Huber loss at " + short_number(r.huber_scale) + " sigma" +
                   (r.unit_weights ? " of the estimated noise (no stated noise)" : "")
             : std::string(r.unit_weights ? "no robust loss (no stated noise: heads weighted alike)"
                                          : "no robust loss");
  if (r.dropped_at_start != 0)
    out += ", " + std::to_string(r.dropped_at_start) +
           " measurements the model cannot predict at the start (" + std::to_string(r.readmitted) +
           " of them re-admitted at a solution)";
  out += "\n" + blinded_line(r.blinded) + "\n" + parameter_rows(u, "1 sigma") + drift_rows(u) +
         correlation_rows(u) + "\n";
  out += "chi2/dof " + short_number(r.chi2_dof) + " (dof " + std::to_string(r.dof) + ")\n";
  out += "residual RMS (deg):";
  for (std::size_t k = 0; k < r.residual_rms_deg.size(); ++k)
    out += "  h" + std::to_string(k + 1) + " " + short_number(r.residual_rms_deg[k]);
  out += "\n" + dropped_row(r) + noise_rows(r) + observability_rows(u) + outlier_rows(r) +
         systematic_rows(r) + warning_rows(r);
  return out + "converged: yes\n";
}

std::string unconverged_table(const unconverged_fit& u) {
  std::string out = "NOT CONVERGED after " + std::to_string(u.iterations) +
                    (u.iterations == 1 ? " iteration: " : " iterations: ") + u.solver_message +
                    "\nlast state (not an estimate; no uncertainty):\n";
  const parameter_set& s = u.last_state;
  for (std::size_t i = 0; i < s.values.size(); ++i)
    out += "  " + parameter_name(i, s.head_count) + " " + short_number(s.values[i]) + " " +
           std::string(parameter_unit(i, s.head_count)) + (s.free[i] ? "" : " (held)") + "\n";
  return out + "cost " + short_number(u.cost) + "\n" + blinded_line(u.blinded) + "converged: no\n";
}

}  // namespace

std::string fit_table(const fit_outcome& outcome) {
  if (const auto* r = std::get_if<fit_result>(&outcome)) return converged_table(*r);
  return unconverged_table(std::get<unconverged_fit>(outcome));
}

std::string design_table(const design_result& design) {
  const uncertainty_report& u = design.uncertainty;
  std::string out =
      "experiment design: " + std::to_string(design.residual_count) + " planned residuals";
  if (design.dropped != 0)
    out +=
        ", " + std::to_string(design.dropped) + " measurements the model cannot predict left out";
  out += "\n" + blinded_line(design.blinded) +
         "1 sigma from the Fisher information alone (the stated noise, no data)\n\n";
  return out + parameter_rows(u, "predicted 1 sigma") + drift_rows(u) + correlation_rows(u) + "\n" +
         observability_rows(u);
}

}  // namespace conescan::calibration

#include "calibration/fit_json.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>

#include "calibration/json.hpp"
#include "calibration/layout.hpp"
#include "text/json_document.hpp"
#include "text/number_text.hpp"
#include "text/text_lines.hpp"

namespace conescan::calibration {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// ---- writing -------------------------------------------------------------------------------

std::string number_list(const std::vector<double>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + json_number(values[i]);
  return out + "]";
}

std::string matrix(const std::vector<std::vector<double>>& rows, const std::string& indent) {
  if (rows.empty()) return "[]";
  std::string out = "[\n";
  for (std::size_t i = 0; i < rows.size(); ++i)
    out += indent + "  " + number_list(rows[i]) + (i + 1 < rows.size() ? ",\n" : "\n");
  return out + indent + "]";
}

std::string head_key(std::size_t head) {
  return json_string("h" + std::to_string(head + 1));
}

std::string per_head(const std::vector<double>& values) {
  std::string out = "{";
  for (std::size_t k = 0; k < values.size(); ++k)
    out += (k ? ", " : "") + head_key(k) + ": " + json_number(values[k]);
  return out + "}";
}

std::string parameters_member(const uncertainty_report& u) {
  std::string out = "  \"parameters\": {\n";
  std::size_t last = 0;  // the last one written
  for (std::size_t i = 0; i < u.parameters.size(); ++i)
    if (!u.parameters[i].absent) last = i;
  for (std::size_t i = 0; i < u.parameters.size(); ++i) {
    const parameter_estimate& p = u.parameters[i];
    if (p.absent) continue;
    out += "    " + json_string(p.name) + ": {\"estimate\": " + json_number(p.estimate) +
           ", \"sigma\": " + json_number(p.sigma) + ", \"unit\": " + json_string(p.unit) +
           ", \"free\": " + (p.free ? "true" : "false");
    if (!p.determined) out += ", \"withheld\": " + json_string(p.withheld);
    out += i < last ? "},\n" : "}\n";
  }
  return out + "  },\n";
}

std::string observability_members(const uncertainty_report& u) {
  std::string order = "[";
  for (std::size_t i = 0; i < u.reported.size(); ++i)
    order += (i ? ", " : "") + json_string(u.reported[i].name);
  std::string out = "  \"parameter_order\": " + order + "],\n";
  out += "  \"correlation\": " + matrix(u.correlation, "  ") + ",\n";
  out += "  \"condition\": " + json_number(u.condition) + ",\n";
  out += "  \"unobservable\": [";
  for (std::size_t c = 0; c < u.unobservable.size(); ++c) {
    out += c ? ",\n    {\"combination\": {" : "\n    {\"combination\": {";
    const auto& components = u.unobservable[c].components;
    for (std::size_t i = 0; i < components.size(); ++i)
      out += (i ? ", " : "") + json_string(components[i].first) + ": " +
             json_number(components[i].second);
    out += "}, \"eigenvalue_ratio\": " + json_number(u.unobservable[c].eigenvalue_ratio) + "}";
  }
  out += u.unobservable.empty() ? "],\n" : "\n  ],\n";
  out += "  \"rank\": " + std::to_string(u.rank) + ",\n";
  return out;
}

/// The drifting parameters' histories (only when there are any).
std::string drift_member(const uncertainty_report& u) {
  if (u.drift.empty()) return "";
  std::string out = "  \"drift\": {";
  for (std::size_t i = 0; i < u.drift.size(); ++i) {
    const drift_history& h = u.drift[i];
    out += std::string(i ? "," : "") + "\n    " + json_string(h.name) +
           ": {\"unit\": " + json_string(h.unit) + ", \"segment_s\": " + json_number(h.segment_s) +
           ", \"segments\": [";
    for (std::size_t k = 0; k < h.segments.size(); ++k) {
      const drift_segment& d = h.segments[k];
      out += std::string(k ? "," : "") + "\n      {\"start_s\": " + json_number(d.start_s) +
             ", \"end_s\": " + json_number(d.end_s) +
             ", \"observations\": " + std::to_string(d.observations) +
             ", \"estimate\": " + json_number(d.value.estimate) +
             ", \"sigma\": " + json_number(d.value.sigma);
      if (!d.value.determined) out += ", \"withheld\": " + json_string(d.value.withheld);
      out += "}";
    }
    out += "\n    ]}";
  }
  return out + "\n  },\n";
}

std::string coordinates_member(const uncertainty_report& u) {
  std::string names = "[";
  for (std::size_t i = 0; i < u.coordinate_names.size(); ++i)
    names += (i ? ", " : "") + json_string(u.coordinate_names[i]);
  return "  \"coordinates\": {\n    \"names\": " + names +
         "],\n    \"estimate\": " + number_list(u.coordinate_values) +
         ",\n    \"covariance\": " + matrix(u.coordinate_covariance, "    ") + "\n  }\n";
}

std::string outliers_member(const fit_result& r) {
  std::string out = "  \"outliers\": {\"count\": " + std::to_string(r.outlier_count) +
                    ", \"threshold\": " + json_number(r.outlier_threshold) + ", \"worst\": [";
  for (std::size_t i = 0; i < r.worst_outliers.size(); ++i) {
    const outlier& o = r.worst_outliers[i];
    out += std::string(i ? "," : "") + "\n    {\"t_s\": " + json_number(o.sample.t_s) +
           ", \"row\": " + std::to_string(o.sample.row) +
           ", \"head\": " + std::to_string(o.sample.head + 1) +
           ", \"chord_residual_deg\": " + json_number(o.chord_residual_deg) +
           ", \"phase_residual_deg\": " + json_number(o.phase_residual_deg) +
           ", \"normalised\": " + json_number(o.normalised) + "}";
  }
  return out + (r.worst_outliers.empty() ? "]},\n" : "\n  ]},\n");
}

/// The noise per head as declared and as estimated, and the warnings.
std::string noise_members(const fit_result& r) {
  if (r.noise.empty()) return "";  // read from a file written before the noise was estimated
  std::string out =
      "  \"noise_scaling\": " + json_string(noise_scaling_name(r.scaling)) + ",\n  \"noise\": {";
  for (std::size_t k = 0; k < r.noise.size(); ++k) {
    const head_noise_estimate& n = r.noise[k];
    out += std::string(k ? "," : "") + "\n    " + head_key(k) +
           ": {\"declared_deg\": " + json_number(n.declared_deg) +
           ", \"ratio\": " + json_number(n.ratio) +
           ", \"estimated_deg\": " + json_number(n.estimated_deg) +
           ", \"weight_ratio\": " + json_number(n.weight_ratio) + "}";
  }
  out += "\n  },\n";
  out += "  \"readmitted\": " + std::to_string(r.readmitted) + ",\n  \"dropped\": {";
  for (std::size_t k = 0; k < r.dropped_per_head.size(); ++k) {
    const std::size_t all = r.dropped_per_head[k] + r.observations_per_head[k];
    out += std::string(k ? ", " : "") + head_key(k) +
           ": {\"count\": " + std::to_string(r.dropped_per_head[k]) + ", \"fraction\": " +
           json_number(all ? static_cast<double>(r.dropped_per_head[k]) / static_cast<double>(all)
                           : 0.0) +
           "}";
  }
  out += "},\n  \"systematic\": [";
  for (std::size_t i = 0; i < r.systematic.size(); ++i) {
    const systematic_effect& e = r.systematic[i];
    out += std::string(i ? "," : "") + "\n    {\"head\": " + std::to_string(e.head + 1) +
           ", \"residual\": " + (e.phase ? "\"phase\"" : "\"chord\"") +
           ", \"outliers\": " + std::to_string(e.outliers) +
           ", \"same_sign\": " + std::to_string(e.same_sign) +
           ", \"sign\": " + std::to_string(e.sign) +
           ", \"mean_residual_deg\": " + json_number(e.mean_residual_deg) +
           ", \"probability\": " + json_number(e.probability) + "}";
  }
  out += r.systematic.empty() ? "],\n" : "\n  ],\n";
  out += "  \"warnings\": [";
  for (std::size_t i = 0; i < r.warnings.size(); ++i)
    out += std::string(i ? "," : "") + "\n    " + json_string(r.warnings[i]);
  return out + (r.warnings.empty() ? "],\n" : "\n  ],\n");
}

/// "  \"blinded\": {\"sun\": [..], \"moon\": [..]},\n" per head, or "" without --intrusions.
std::string blinded_member(const blinded_rows& b) {
  if (b.sun.empty()) return "";
  const auto list = [](const std::vector<std::size_t>& counts) {
    std::string out = "[";
    for (std::size_t k = 0; k < counts.size(); ++k)
      out += (k ? ", " : "") + std::to_string(counts[k]);
    return out + "]";
  };
  return "  \"blinded\": {\"sun\": " + list(b.sun) + ", \"moon\": " + list(b.moon) + "},\n";
}

std::string converged_json(const fit_result& r) {
  const uncertainty_report& u = r.uncertainty;
  std::string out = "{\n  \"kind\": \"fit\",\n  \"converged\": true,\n";
  out += parameters_member(u);
  out += observability_members(u);
  out += "  \"chi2_dof\": " + json_number(r.chi2_dof) + ",\n";
  out += "  \"dof\": " + std::to_string(r.dof) + ",\n";
  out += "  \"residual_count\": " + std::to_string(r.residual_count) + ",\n";
  out += "  \"residual_rms_deg\": " + per_head(r.residual_rms_deg) + ",\n";
  std::vector<double> counts(r.observations_per_head.begin(), r.observations_per_head.end());
  out += "  \"observations\": " + per_head(counts) + ",\n";
  out += outliers_member(r);
  out += "  \"robust_loss\": {\"kind\": " +
         std::string(r.loss == robust_loss::huber
                         ? "\"huber\", \"scale\": " + json_number(r.huber_scale)
                         : "\"none\"") +
         "},\n";
  out += "  \"unit_weights\": " + std::string(r.unit_weights ? "true" : "false") + ",\n";
  out += "  \"dropped_at_start\": " + std::to_string(r.dropped_at_start) + ",\n";
  out += noise_members(r);
  out += blinded_member(r.blinded);
  out += "  \"iterations\": " + std::to_string(r.iterations) + ",\n";
  out += "  \"solver_message\": " + json_string(r.solver_message) + ",\n";
  return out + drift_member(u) + coordinates_member(u) + "}\n";
}

std::string unconverged_json(const unconverged_fit& u) {
  std::string out = "{\n  \"kind\": \"fit\",\n  \"converged\": false,\n";
  out += "  \"iterations\": " + std::to_string(u.iterations) + ",\n";
  out += "  \"cost\": " + json_number(u.cost) + ",\n";
  out += "  \"solver_message\": " + json_string(u.solver_message) + ",\n";
  out += blinded_member(u.blinded);
  out += "  \"last_state\": {\n";
  const parameter_set& s = u.last_state;
  for (std::size_t i = 0; i < s.values.size(); ++i)
    out += "    " + json_string(parameter_name(i, s.head_count)) +
           ": {\"value\": " + json_number(s.values[i]) +
           ", \"unit\": " + json_string(parameter_unit(i, s.head_count)) +
           ", \"free\": " + (s.free[i] ? "true" : "false") +
           (i + 1 < s.values.size() ? "},\n" : "}\n");
  return out + "  }\n}\n";
}

}  // namespace

std::string fit_json(const fit_outcome& outcome) {
  if (const auto* r = std::get_if<fit_result>(&outcome)) return converged_json(*r);
  return unconverged_json(std::get<unconverged_fit>(outcome));
}

std::string design_json(const design_result& design) {
  const uncertainty_report& u = design.uncertainty;
  std::string out = "{\n  \"kind\": \"design\",\n";
  out += parameters_member(u);
  out += observability_members(u);
  out += "  \"residual_count\": " + std::to_string(design.residual_count) + ",\n";
  out += "  \"dropped\": " + std::to_string(design.dropped) + ",\n";
  out += blinded_member(design.blinded);
  return out + drift_member(u) + coordinates_member(u) + "}\n";
}

// ---- reading -------------------------------------------------------------------------------

namespace {

using json = nlohmann::ordered_json;

/// A JSON shape error, thrown inside the reader and returned as its checked<> error.
struct shape_error {
  diagnostic error;
};

/// Reads the fit's object, naming each member's JSON path in errors (nlohmann's document keeps
/// no positions: text/json_document.hpp).

class fit_reader {
 public:
  explicit fit_reader(const std::string& file) : file_(file) {}

  // The path holds the file's own member names: shown with quote()'s escapes (no raw control
  // byte or broken UTF-8 reaches a terminal), without its quotes.
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    const std::string shown = quote(path.empty() ? "the top level" : path);
    throw shape_error{
        diagnostic::in_file(file_, 0, shown.substr(1, shown.size() - 2) + ": " + what)};
  }

  static std::string path_of(const std::string& path, std::string_view key) {
    return text::json_path(path, key);
  }

  const json& member(const json& object, const std::string& path, std::string_view key) const {
    const auto it = object.find(std::string(key));
    if (it == object.end()) fail(path, "missing member \"" + std::string(key) + "\"");
    return *it;
  }

  const json& typed(const json& object, const std::string& path, std::string_view key,
                    bool (json::*is)() const noexcept, const char* what) const {
    const json& v = member(object, path, key);
    if (!(v.*is)())
      fail(path_of(path, key),
           std::string("expected ") + what + ", found " + std::string(text::json_kind(v)));
    return v;
  }
  const json& object(const json& o, const std::string& path, std::string_view key) const {
    return typed(o, path, key, &json::is_object, "an object");
  }
  const json& array(const json& o, const std::string& path, std::string_view key) const {
    return typed(o, path, key, &json::is_array, "an array");
  }
  std::string text(const json& o, const std::string& path, std::string_view key) const {
    return typed(o, path, key, &json::is_string, "a string").get<std::string>();
  }
  bool boolean(const json& o, const std::string& path, std::string_view key) const {
    return typed(o, path, key, &json::is_boolean, "true or false").get<bool>();
  }
  double number_value(const json& v, const std::string& path, bool null_allowed) const {
    if (v.is_number()) return v.get<double>();
    if (null_allowed && v.is_null()) return nan;
    fail(path, null_allowed ? "expected a number or null" : "expected a number");
  }
  double number(const json& o, const std::string& path, std::string_view key,
                bool null_allowed = false) const {
    return number_value(member(o, path, key), path_of(path, key), null_allowed);
  }
  /// A number no fit writes outside [low, high] (a negative sigma, a correlation of 2, a chi2
  /// per degree of freedom of -1): refused, though the correction may not use it. NaN (null,
  /// where allowed) passes.
  double number_in(const json& o, const std::string& path, std::string_view key, double low,
                   double high, bool null_allowed = false) const {
    const double v = number(o, path, key, null_allowed);
    check_in(v, path_of(path, key), low, high);
    return v;
  }
  void check_in(double v, const std::string& path, double low, double high) const {
    if (std::isnan(v) || (v >= low && v <= high)) return;
    fail(path, text::shortest_text(v) + " is outside [" + text::shortest_text(low) + ", " +
                   text::shortest_text(high) + "]: no fit writes it");
  }

  std::size_t count(const json& o, const std::string& path, std::string_view key) const {
    const double v = number(o, path, key);
    if (!(v >= 0 && v <= 9007199254740992.0 && v == std::floor(v)))
      fail(path_of(path, key), "expected a whole number >= 0");
    return static_cast<std::size_t>(v);
  }
  std::vector<double> numbers(const json& array_value, const std::string& path, std::size_t size,
                              bool null_allowed) const {
    if (!array_value.is_array()) fail(path, "expected an array");
    if (array_value.size() != size) fail(path, "expected " + std::to_string(size) + " numbers");
    std::vector<double> out;
    for (std::size_t i = 0; i < size; ++i)
      out.push_back(number_value(array_value[i], text::json_path(path, i), null_allowed));
    return out;
  }
  std::vector<std::vector<double>> square(const json& o, const std::string& path,
                                          std::string_view key, std::size_t size) const {
    const json& rows = array(o, path, key);
    const std::string here = path_of(path, key);
    if (rows.size() != size)
      fail(here, "expected " + std::to_string(size) + " rows (one per free parameter)");
    std::vector<std::vector<double>> out;
    for (std::size_t i = 0; i < size; ++i)
      out.push_back(numbers(rows[i], text::json_path(here, i), size, true));
    return out;
  }

  /// The parameters, every one of a scene's, in parameter-index order.
  uncertainty_report parameters(const json& root) const {
    const json& members = object(root, "", "parameters");
    std::size_t head_count = 0;
    for (const auto& [name, value] : members.items()) {
      checked<parsed_name> parsed = parse_parameter_name(name);
      if (!parsed.ok()) fail(".parameters", parsed.error().message);
      if (parsed.value().is_head) head_count = std::max(head_count, parsed.value().head + 1);
    }
    uncertainty_report u;
    // A fit without the sensor physics leaves the physics' parameters out (parameters.hpp).
    std::size_t present = 0;
    for (std::size_t i = 0; i < parameter_count(head_count); ++i)
      if (members.contains(parameter_name(i, head_count)) || !is_physics_parameter(i, head_count))
        ++present;
    if (members.size() != present)
      fail(".parameters", "expected the " + std::to_string(present) + " parameters of " +
                              std::to_string(head_count) + " heads and the Earth, found " +
                              std::to_string(members.size()));
    for (std::size_t i = 0; i < parameter_count(head_count); ++i) {
      const std::string name = parameter_name(i, head_count);
      if (is_physics_parameter(i, head_count) && !members.contains(name)) {
        u.parameters.push_back({name, std::string(parameter_unit(i, head_count)), false, true,
                                std::numeric_limits<double>::quiet_NaN(), 0.0, "", i, true});
        continue;
      }
      u.parameters.push_back(parameter(members, i, head_count));
      u.parameters.back().index = i;
      if (u.parameters.back().free) {
        u.free_parameters.push_back(i);
        u.reported.push_back(u.parameters.back());
      }
    }
    return u;
  }

  parameter_estimate parameter(const json& members, std::size_t i, std::size_t head_count) const {
    const std::string name = parameter_name(i, head_count);
    const json& p = object(members, ".parameters", name);
    const std::string path = path_of(".parameters", name);
    parameter_estimate e;
    e.name = name;
    e.unit = text(p, path, "unit");
    if (e.unit != parameter_unit(i, head_count))
      fail(path_of(path, "unit"),
           "expected \"" + std::string(parameter_unit(i, head_count)) + "\"");
    e.free = boolean(p, path, "free");
    e.determined = !p.contains("withheld");
    if (!e.determined) e.withheld = text(p, path, "withheld");
    if (!e.free && !e.determined) fail(path, "a held parameter cannot be withheld");
    e.estimate = number(p, path, "estimate", !e.determined);
    e.sigma = number_in(p, path, "sigma", 0, HUGE_VAL, !e.determined);
    if (!e.determined && !(std::isnan(e.estimate) && std::isnan(e.sigma)))
      fail(path, "a withheld parameter has a null estimate and sigma");
    return e;
  }

  void order_and_observability(const json& root, uncertainty_report& u) const {
    const json& order = array(root, "", "parameter_order");
    if (order.size() != u.free_parameters.size())
      fail(".parameter_order", "expected the " + std::to_string(u.free_parameters.size()) +
                                   " free parameters in parameter order");
    for (std::size_t i = 0; i < order.size(); ++i) {
      const std::string& expected = u.parameters[u.free_parameters[i]].name;
      if (!order[i].is_string() || order[i].get<std::string>() != expected)
        fail(text::json_path(".parameter_order", i), "expected \"" + expected + "\"");
    }
    u.correlation = square(root, "", "correlation", u.free_parameters.size());
    // Correlations as computed from a covariance: within rounding of [-1, 1].
    for (std::size_t i = 0; i < u.correlation.size(); ++i)
      for (std::size_t j = 0; j < u.correlation[i].size(); ++j)
        check_in(u.correlation[i][j], text::json_path(text::json_path(".correlation", i), j),
                 -1 - 1e-9, 1 + 1e-9);
    u.condition = number_in(root, "", "condition", 1 - 1e-9, HUGE_VAL, true);
    if (std::isnan(u.condition)) u.condition = std::numeric_limits<double>::infinity();
    const json& unobservable = array(root, "", "unobservable");
    for (std::size_t k = 0; k < unobservable.size(); ++k) {
      const std::string path = text::json_path(".unobservable", k);
      const json& c = unobservable[k];
      if (!c.is_object()) fail(path, "expected an object");
      unobservable_combination combination;
      for (const auto& [name, value] : object(c, path, "combination").items())
        combination.components.emplace_back(
            name, number_value(value, path_of(path_of(path, "combination"), name), false));
      combination.eigenvalue_ratio = number_in(c, path, "eigenvalue_ratio", 0, 1);
      u.unobservable.push_back(std::move(combination));
    }
    u.rank = count(root, "", "rank");
  }

  void coordinates(const json& root, uncertainty_report& u) const {
    const json& c = object(root, "", "coordinates");
    parameter_set set = parameter_set::nominal((u.parameters.size() - earth_parameter_count) /
                                               head_parameter_count);
    for (std::size_t index : u.free_parameters) set.free[index] = true;
    const estimation_layout layout = estimation_layout::of(set);
    const json& names = array(c, ".coordinates", "names");
    if (names.size() != layout.coordinates.size())
      fail(".coordinates.names", "expected one name per free parameter");
    for (std::size_t i = 0; i < names.size(); ++i) {
      const std::string expected = slot_name(layout, layout.coordinates[i]);
      if (!names[i].is_string() || names[i].get<std::string>() != expected)
        fail(text::json_path(".coordinates.names", i), "expected \"" + expected + "\"");
      u.coordinate_names.push_back(expected);
      u.coordinate_keys.push_back(coordinate_key_of(layout, i));
    }
    u.coordinate_values = numbers(member(c, ".coordinates", "estimate"), ".coordinates.estimate",
                                  layout.coordinates.size(), true);
    u.coordinate_covariance = square(c, ".coordinates", "covariance", layout.coordinates.size());
  }

  void outliers(const json& root, fit_result& r) const {
    const json& o = object(root, "", "outliers");
    r.outlier_count = count(o, ".outliers", "count");
    r.outlier_threshold = number_in(o, ".outliers", "threshold", 0, HUGE_VAL);
    const json& worst = array(o, ".outliers", "worst");
    for (std::size_t k = 0; k < worst.size(); ++k) {
      const std::string path = text::json_path(".outliers.worst", k);
      const json& w = worst[k];
      if (!w.is_object()) fail(path, "expected an object");
      outlier x;
      x.sample.t_s = number(w, path, "t_s");
      x.sample.row = count(w, path, "row");
      const std::size_t head = count(w, path, "head");
      if (head == 0 || head > r.residual_rms_deg.size())
        fail(path_of(path, "head"), "expected a head number of the fit");
      x.sample.head = head - 1;
      x.chord_residual_deg = number(w, path, "chord_residual_deg");
      x.phase_residual_deg = number(w, path, "phase_residual_deg");
      x.normalised = number(w, path, "normalised");
      r.worst_outliers.push_back(x);
    }
  }

  std::vector<double> per_head(const json& root, std::string_view key, std::size_t heads,
                               bool null_allowed) const {
    const json& o = object(root, "", key);
    const std::string path = path_of("", key);
    if (o.size() != heads) fail(path, "expected one value per head");
    std::vector<double> out;
    for (std::size_t k = 0; k < heads; ++k)
      out.push_back(number(o, path, "h" + std::to_string(k + 1), null_allowed));
    return out;
  }

  void loss(const json& root, fit_result& r) const {
    const json& loss = object(root, "", "robust_loss");
    const std::string kind = text(loss, ".robust_loss", "kind");
    if (kind == "huber") {
      r.loss = robust_loss::huber;
      r.huber_scale = number_in(loss, ".robust_loss", "scale", 0, HUGE_VAL);
    } else if (kind != "none") {
      fail(".robust_loss.kind", "expected \"huber\" or \"none\"");
    }
  }

  /// Optional: a fit written before the noise was estimated has none of these members.
  void noise(const json& root, std::size_t heads, fit_result& r) const {
    if (!root.contains("noise_scaling")) return;
    const std::string scaling = text(root, "", "noise_scaling");
    bool known = false;
    for (noise_scaling s :
         {noise_scaling::estimated, noise_scaling::larger, noise_scaling::declared})
      if (scaling == noise_scaling_name(s)) {
        r.scaling = s;
        known = true;
      }
    if (!known) fail(".noise_scaling", "expected \"estimated\", \"larger\" or \"declared\"");
    const json& per_head = object(root, "", "noise");
    if (per_head.size() != heads) fail(".noise", "expected one value per head");
    for (std::size_t k = 0; k < heads; ++k) {
      const std::string key = "h" + std::to_string(k + 1);
      const json& n = object(per_head, ".noise", key);
      const std::string path = path_of(".noise", key);
      r.noise.push_back({number_in(n, path, "declared_deg", 0, HUGE_VAL),
                         number_in(n, path, "ratio", 0, HUGE_VAL, true),
                         number_in(n, path, "estimated_deg", 0, HUGE_VAL, true),
                         number_in(n, path, "weight_ratio", 0, HUGE_VAL)});
    }
    r.readmitted = count(root, "", "readmitted");
    const json& dropped = object(root, "", "dropped");
    if (dropped.size() != heads) fail(".dropped", "expected one value per head");
    for (std::size_t k = 0; k < heads; ++k) {
      const std::string key = "h" + std::to_string(k + 1);
      r.dropped_per_head.push_back(
          count(object(dropped, ".dropped", key), path_of(".dropped", key), "count"));
    }
    systematic(root, heads, r);
    const json& warnings = array(root, "", "warnings");
    for (std::size_t i = 0; i < warnings.size(); ++i) {
      if (!warnings[i].is_string()) fail(text::json_path(".warnings", i), "expected a string");
      r.warnings.push_back(warnings[i].get<std::string>());
    }
  }

  void systematic(const json& root, std::size_t heads, fit_result& r) const {
    const json& effects = array(root, "", "systematic");
    for (std::size_t i = 0; i < effects.size(); ++i) {
      const json& e = effects[i];
      const std::string path = text::json_path(".systematic", i);
      if (!e.is_object()) fail(path, "expected an object");
      systematic_effect x;
      x.head = count(e, path, "head");
      if (x.head == 0 || x.head > heads)
        fail(path_of(path, "head"), "expected a head number of the fit");
      --x.head;
      const std::string residual = text(e, path, "residual");
      if (residual != "chord" && residual != "phase")
        fail(path_of(path, "residual"), "expected \"chord\" or \"phase\"");
      x.phase = residual == "phase";
      x.outliers = count(e, path, "outliers");
      x.same_sign = count(e, path, "same_sign");
      const double sign = number(e, path, "sign");
      if (sign != 1 && sign != -1) fail(path_of(path, "sign"), "expected 1 or -1");
      x.sign = sign > 0 ? 1 : -1;
      x.mean_residual_deg = number(e, path, "mean_residual_deg");
      x.probability = number_in(e, path, "probability", 0, 1);
      r.systematic.push_back(x);
    }
  }

  fit_result read(const json& root) const {
    if (!root.is_object())
      fail("", "expected a JSON object, found " + std::string(text::json_kind(root)));
    if (text(root, "", "kind") != "fit")
      fail(".kind", "expected \"fit\": this is not a fit's result");
    if (root.contains("drift"))
      fail(".drift",
           "a fit with drifting parameters holds no one value to correct with: refit them "
           "global");
    if (!boolean(root, "", "converged"))
      fail(".converged", "the fit did not converge: it holds no estimate");
    fit_result r;
    r.uncertainty = parameters(root);
    order_and_observability(root, r.uncertainty);
    coordinates(root, r.uncertainty);
    const std::size_t heads =
        (r.uncertainty.parameters.size() - earth_parameter_count) / head_parameter_count;
    r.chi2_dof = number_in(root, "", "chi2_dof", 0, HUGE_VAL);
    r.dof = count(root, "", "dof");
    r.residual_count = count(root, "", "residual_count");
    r.residual_rms_deg = per_head(root, "residual_rms_deg", heads, true);
    for (std::size_t k = 0; k < heads; ++k)
      check_in(r.residual_rms_deg[k], path_of(".residual_rms_deg", "h" + std::to_string(k + 1)), 0,
               HUGE_VAL);
    for (double n : per_head(root, "observations", heads, false)) {
      if (!(n >= 0 && n == std::floor(n))) fail(".observations", "expected whole numbers");
      r.observations_per_head.push_back(static_cast<std::size_t>(n));
    }
    outliers(root, r);
    loss(root, r);
    r.unit_weights = boolean(root, "", "unit_weights");
    r.dropped_at_start = count(root, "", "dropped_at_start");
    r.iterations = static_cast<int>(count(root, "", "iterations"));
    r.solver_message = text(root, "", "solver_message");
    noise(root, heads, r);
    return r;
  }

 private:
  const std::string& file_;
};

}  // namespace

checked<fit_result> read_fit_json(std::string_view text, const std::string& file_name) {
  checked<json> root = text::parse_json_document(text, file_name);
  if (!root.ok()) return root.error();
  try {
    return fit_reader(file_name).read(root.value());
  } catch (const shape_error& e) {
    return e.error;
  }
}

checked<fit_result> read_fit_json_file(const std::string& path) {
  // A JSON object starts with '{' after any blanks: a file that does not is refused at its start.
  const auto json_object = [](std::string_view start) -> checked<void> {
    const std::size_t first = start.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos || start[first] == '{') return success();
    return diagnostic{{}, "not a fit's JSON (it does not start with '{')"};
  };
  checked<std::string> text =
      text::read_bounded_file(path, fit_json_max_bytes, "a fit's JSON", json_object);
  checked<fit_result> read = text.ok() ? read_fit_json(text.value(), path) : text.error();
  // Every refusal names the option that gave the file (conescan-sim --apply).
  if (!read.ok()) read.error().option = "apply";
  return read;
}

}  // namespace conescan::calibration

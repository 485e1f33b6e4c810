#include "scene/sweep.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace conescan::scene {

namespace {

constexpr const char* sweep_names =
    "a-km, e, i-deg, raan-deg, argp-deg, m0-deg, step-s, orbits, duration-s, radius-km, "
    "horizon-km, processing-radius, roll-deg, pitch-deg, yaw-deg, hK.alpha, hK.beta, hK.gamma, "
    "hK.sigma, hK.phase (K = 1, 2, ...)";

bool read_number(std::string_view text, double& value, int& decimals) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() ||
      !std::isfinite(value))
    return false;
  const std::size_t dot = text.find('.');
  const std::size_t exponent = text.find_first_of("eE");
  // With an exponent the typed decimals say nothing simple: keep full precision (17 digits).
  if (exponent != std::string_view::npos)
    decimals = 17;
  else if (dot != std::string_view::npos)
    decimals = static_cast<int>(text.size() - dot - 1);
  else
    decimals = 0;
  return true;
}

}  // namespace

std::variant<sweep_spec, std::string> parse_sweep(std::string_view text) {
  const std::string usage = "expected NAME=FROM:TO:STEP, e.g. e=0:0.1:0.025";
  const std::size_t equals = text.find('=');
  if (equals == std::string_view::npos || equals == 0)
    return "'" + std::string(text) + "': " + usage;
  sweep_spec spec{std::string(text.substr(0, equals)), 0, 0, 0, 0};
  std::string_view range = text.substr(equals + 1);
  const std::size_t c1 = range.find(':');
  const std::size_t c2 = c1 == std::string_view::npos ? c1 : range.find(':', c1 + 1);
  if (c2 == std::string_view::npos || range.find(':', c2 + 1) != std::string_view::npos)
    return "'" + std::string(text) + "': " + usage;
  int d_from = 0, d_to = 0, d_step = 0;
  if (!read_number(range.substr(0, c1), spec.from, d_from) ||
      !read_number(range.substr(c1 + 1, c2 - c1 - 1), spec.to, d_to) ||
      !read_number(range.substr(c2 + 1), spec.step, d_step))
    return "'" + std::string(text) + "': FROM, TO and STEP must be finite numbers; " + usage;
  if (!(spec.step > 0)) return "'" + std::string(text) + "': STEP must be > 0";
  if (!(spec.to >= spec.from)) return "'" + std::string(text) + "': TO must be >= FROM";
  spec.decimals = std::max(d_from, d_step);
  return spec;
}

std::vector<double> sweep_values(const sweep_spec& spec) {
  std::vector<double> values;
  for (long j = 0;; ++j) {
    const double exact = spec.from + static_cast<double>(j) * spec.step;
    if (exact > spec.to + 1e-9 * spec.step) break;
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", spec.decimals, exact);
    double rounded = exact;
    std::from_chars(text, text + std::char_traits<char>::length(text), rounded);
    values.push_back(spec.decimals >= 17 ? exact : rounded);
  }
  return values;
}

std::string apply_sweep_value(scene_config& s, const std::string& name, double value) {
  const struct {
    const char* name;
    double* field;
  } scalars[] = {{"a-km", &s.a_km},
                 {"e", &s.e},
                 {"i-deg", &s.i_deg},
                 {"raan-deg", &s.raan_deg},
                 {"argp-deg", &s.argp_deg},
                 {"m0-deg", &s.m0_deg},
                 {"step-s", &s.step_s},
                 {"orbits", &s.orbits},
                 {"horizon-km", &s.horizon_km},
                 {"roll-deg", &s.roll_deg},
                 {"pitch-deg", &s.pitch_deg},
                 {"yaw-deg", &s.yaw_deg}};
  for (const auto& f : scalars)
    if (name == f.name) {
      *f.field = value;
      return {};
    }
  if (name == "duration-s") {
    s.duration_s = value;
    return {};
  }
  if (name == "radius-km") {
    s.radius_km = value;
    return {};
  }
  if (name == "processing-radius") {
    s.processing_radius = processing_radius_kind::value;
    s.processing_radius_km = value;
    return {};
  }
  // hK.key
  if (name.size() > 3 && name[0] == 'h') {
    const std::size_t dot = name.find('.');
    std::size_t k = 0;
    const auto [end, ec] = std::from_chars(name.data() + 1, name.data() + name.size(), k);
    if (ec == std::errc() && end == name.data() + dot && k >= 1) {
      if (k > s.heads.size())
        return "sweep " + name + ": the scene has " + std::to_string(s.heads.size()) + " head(s)";
      head_config& h = s.heads[k - 1];
      const std::string key = name.substr(dot + 1);
      const struct {
        const char* key;
        double* field;
      } head_keys[] = {{"alpha", &h.alpha_deg},
                       {"beta", &h.beta_deg},
                       {"gamma", &h.gamma_deg},
                       {"sigma", &h.sigma_deg},
                       {"phase", &h.phase_deg}};
      for (const auto& f : head_keys)
        if (key == f.key) {
          *f.field = value;
          return {};
        }
    }
  }
  return "cannot sweep '" + name + "'; numeric options: " + sweep_names;
}

}  // namespace conescan::scene

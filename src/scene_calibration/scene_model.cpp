#include "scene_calibration/scene_model.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

#include "conescan/orbital_frame.hpp"
#include "conescan/scan_frame.hpp"
#include "orbit/wgs84.hpp"
#include "scene/degrees.hpp"
#include "scene/scene_earth.hpp"
#include "scene/scene_physics.hpp"

namespace conescan::calibration {

checked<scene_model> scene_model::of(const scene::loaded_scene& loaded,
                                     std::span<const double> times_s, int threads) {
  const scene::scene_config& scene = loaded.config;
  if (scene.model == scene::forward_model::bias)
    return diagnostic{"model",
                      "the calibration fits the scan model (MODEL §11): give --model scan (and "
                      "simulate the telemetry with it)"};
  scene_model m;
  m.ellipsoid_ = scene.earth == scene::earth_model::wgs84;
  m.sphere_radius_m_ = scene::truth_radius_m(scene);
  m.equatorial_m_ = orbit::wgs84().a_m;
  // horizon_polar_radius_m without the horizon terms, which the parameters supply.
  m.polar_m_ =
      scene::horizon_polar_radius_m(scene) - (scene.horizon_km + scene.horizon_pole_km) * 1000;
  m.sphere_polar_ = !m.ellipsoid_ && scene.radiance_season != 0 && scene::any_physics(scene);
  std::vector<scan_frame<double>> frames;
  for (const scene::head_config& h : scene.heads) {
    m.gamma_rad_.push_back(deg_to_rad(h.gamma_deg));
    m.physics_.push_back({scene::physics_on(scene, h), scene::physics_settings_of(scene, h)});
    frames.push_back(
        scan_frame_from_mounting(deg_to_rad(h.alpha_deg), scene::deg_to_rad_reduced(h.beta_deg)));
  }
  const std::size_t heads = frames.size(), size = m.view_size();
  m.rows_.resize(times_s.size());
  m.latitude_deg_.resize(times_s.size());
  m.views_.resize(times_s.size() * heads * size);
  checked<void> done =
      scene_truth_each(loaded, times_s, threads, [&](std::size_t i, const row_truth& t) {
        const double r_m = norm(t.r_eci_m);
        m.rows_[i] = {r_m, std::sin(t.sun_declination_rad)};
        m.latitude_deg_[i] = static_cast<float>(std::asin(t.r_eci_m.z / r_m) / radians_per_degree);
        // Body axes from ECI through the orbital frame (MODEL §2) and the reference attitude.
        const mat3<double> eci_from_orbit = dcm_eci_from_orbit(t.r_eci_m, t.v_eci_m_s);
        auto to_body = [&](const vec3<double>& v) {
          return apply(t.body_from_orbit, apply_transpose(eci_from_orbit, v));
        };
        const vec3<double> nadir_body = apply(t.body_from_orbit, vec3<double>(0, 0, 1));
        const vec3<double> position_body = to_body(t.r_eci_m);
        const vec3<double> polar_body = to_body(vec3<double>(0, 0, 1));
        for (std::size_t h = 0; h < heads; ++h) {
          const scan_frame<double>& f = frames[h];
          double* view = &m.views_[(i * heads + h) * size];
          auto put = [&](double* at, const vec3<double>& v) {
            at[0] = dot(f.e1, v);
            at[1] = dot(f.e2, v);
            at[2] = dot(f.e3, v);
          };
          if (m.ellipsoid_) {
            put(view, position_body);
            put(view + 3, polar_body);
          } else {
            put(view, nadir_body);
            if (m.sphere_polar_) put(view + 3, polar_body);
          }
        }
      });
  if (!done.ok()) return std::move(done).error();
  m.times_s_.assign(times_s.begin(), times_s.end());
  m.use_physics_series(physics_series_least_rows);
  return m;
}

void scene_model::use_physics_series(std::size_t least_rows,
                                     physics_time_series_settings settings) {
  series_.assign(head_count(), nullptr);
  if (row_count() < least_rows || !series_times_usable(times_s_)) return;
  for (std::size_t k = 0; k < head_count(); ++k)
    if (physics_[k].on) series_[k] = std::make_shared<physics_time_series>(times_s_, settings);
}

std::size_t scene_model::physics_series_evaluations() const noexcept {
  std::size_t n = 0;
  for (const auto& s : series_)
    if (s) n += s->evaluations();
  return n;
}

std::size_t scene_model::physics_series_served() const noexcept {
  std::size_t n = 0;
  for (const auto& s : series_)
    if (s) n += s->served();
  return n;
}

namespace {

/// The series' sample of the chain's crossings from the geometric ones, the gradients of the
/// inputs in `slots` read from their Jet slots.
template <class T>
series_sample chain_sample(const crossings<T>& geometric, const crossings<T>& chain,
                           const input_slots& slots) {
  series_sample s;
  s.chord_rad = value_of(geometric.chord());
  if (geometric.state != status::ok || chain.state != status::ok) return s;
  s.ok = true;
  const T shift[2] = {T(chain.phi_in - geometric.phi_in), T(chain.phi_out - geometric.phi_out)};
  for (std::size_t c = 0; c < 2; ++c) {
    s.shift[c] = value_of(shift[c]);
    if constexpr (!std::is_same_v<T, double>)
      for (std::size_t i = 0; i < series_input_count; ++i)
        if (slots.slot[i] >= 0) s.gradient[c][i] = shift[c].v[slots.slot[i]];
  }
  return s;
}

}  // namespace

// Every input has a slot of its own in the fit's Jet.
static_assert(series_input_count <= static_cast<std::size_t>(jet_size));

input_slots input_slots_of(series_mask mask) noexcept {
  input_slots s{};
  int next = 0;
  for (std::size_t i = 0; i < series_input_count; ++i) s.slot[i] = mask >> i & 1u ? next++ : -1;
  s.count = next;
  return s;
}

/// Calls run with a scalar of the kind the inputs in `slots` need: double where none carries a
/// derivative, the compact Jet where they fit in it, the fit's Jet otherwise.
template <class F>
auto with_slots_scalar(const input_slots& slots, F&& run) {
  if (slots.count == 0) return run(0.0);
  return slots.count <= compact_jet_size ? run(compact_jet{}) : run(parameter_jet{});
}

series_sample scene_model::series_sample_at(std::size_t row, std::size_t k,
                                            const series_inputs& key, series_mask gradient) const {
  const input_slots slots = input_slots_of(gradient);
  auto at = [&](auto scalar) {
    using T = decltype(scalar);
    head_geometry<T> head{};
    earth_geometry<T> earth{};
    seed_inputs(key, slots, head, earth);
    const crossings<T> geometric = geometric_crossings(row, k, head, earth);
    if (geometric.state != status::ok) return chain_sample(geometric, geometric, slots);
    return chain_sample(geometric, physics_crossings(row, k, head, earth), slots);
  };
  return with_slots_scalar(slots, at);
}

crossings<parameter_jet> scene_model::compact_physics_crossings(
    std::size_t row, std::size_t k, const head_geometry<parameter_jet>& head,
    const earth_geometry<parameter_jet>& earth) const {
  const input_slots slots = input_slots_of(derivative_inputs(head, earth));
  const auto fields = series_fields(head, earth);
  series_inputs values{};
  for (std::size_t i = 0; i < series_input_count; ++i) values[i] = fields[i]->a;
  // The chain rule back to the fit's slots: d/dp = sum over the inputs of d/d(input) d(input)/dp
  // (a double's crossings carry none).
  auto expanded = [&](const auto& x) {
    parameter_jet y(value_of(x));
    if constexpr (!std::is_same_v<std::decay_t<decltype(x)>, double>)
      for (std::size_t i = 0; i < series_input_count; ++i)
        if (slots.slot[i] >= 0) y.v += x.v[slots.slot[i]] * fields[i]->v;
    return y;
  };
  return with_slots_scalar(slots, [&](auto scalar) {
    using T = decltype(scalar);
    head_geometry<T> seeded_head{};
    earth_geometry<T> seeded_earth{};
    seed_inputs(values, slots, seeded_head, seeded_earth);
    const crossings<T> c = physics_crossings(row, k, seeded_head, seeded_earth);
    return crossings<parameter_jet>{expanded(c.phi_in), expanded(c.phi_out), c.state, c.iterations};
  });
}

checked<scene_model> scene_model::of_telemetry(const scene::loaded_scene& scene,
                                               const telemetry& data, int threads) {
  // The rows that hold a measurement (a row where every head wrote nan has none): their times
  // in order, and a map from the telemetry's row when some are missing.
  std::vector<double> times;
  std::vector<std::size_t> data_rows;  // each time's row in the file (0-based, after the header)
  std::size_t last_row = static_cast<std::size_t>(-1);
  for (const observation& o : data.observations)
    if (o.sample.row != last_row) {
      last_row = o.sample.row;
      times.push_back(o.sample.t_s);
      data_rows.push_back(o.sample.row);
    }
  checked<scene_model> model = of(scene, times, threads);
  if (!model.ok()) {
    diagnostic e = std::move(model).error();
    // scene_truth_at names a time by its index among `times`: name the file's line instead
    // (line 1 is the header).
    if (e.option == "telemetry" && e.where.line > 0 && e.where.line <= data_rows.size()) {
      e.where.file = data.file;
      e.where.line = data_rows[e.where.line - 1] + 2;
    }
    return e;
  }
  scene_model& m = model.value();
  if (!data_rows.empty() && data_rows.back() + 1 != data_rows.size()) {
    m.row_map_.assign(data_rows.back() + 1, 0);
    for (std::size_t i = 0; i < data_rows.size(); ++i)
      m.row_map_[data_rows[i]] = static_cast<std::uint32_t>(i);
  }
  return model;
}

crossings<double> scene_model::corrected(const telemetry_sample& sample,
                                         const head_geometry<double>& head, double bias_in_deg,
                                         double bias_out_deg, const earth_geometry<double>& earth,
                                         const crossings<double>& measured) const {
  if (measured.state != status::ok) return measured;
  const std::size_t row = row_of(sample.row), k = sample.head;
  const bool physics = physics_[k].on && !std::isnan(head.tau_ms);
  const double gamma = gamma_rad_[k];
  const cone_calibration<double> ideal_cone{0, 0, 0};
  if (!physics) {
    const head_calibration<double> calibration{head, bias_in_deg, bias_out_deg};
    if (ellipsoid_)
      return calibrated_crossings(measured, gamma, calibration,
                                  ellipsoid_seen(row, k, earth).horizon);
    const sphere_view<double> v = sphere_seen(row, k, earth);
    return calibrated_crossings(measured, gamma, calibration, v.nadir, v.disk);
  }
  const chord_phase_deg<double> modelled =
      with_crossing_biases(predict(sample, head, earth), bias_in_deg, bias_out_deg);
  // The ideal head sees the limb at its 50 % height: the limb is the Earth's, not the head's
  // error (fit_correction.hpp's decision), and a pencil without lag at the normalised 1/2 level
  // crosses there (MODEL §12).
  earth_geometry<double> limb = earth;
  limb.horizon_km += earth.radiance_offset_km;
  if (ellipsoid_)
    return corrected_crossings(
        measured, modelled,
        predicted_chord_phase(gamma, ideal_cone, ellipsoid_seen(row, k, limb).horizon));
  const sphere_view<double> v = sphere_seen(row, k, limb);
  return corrected_crossings(measured, modelled,
                             predicted_chord_phase(gamma, ideal_cone, v.nadir, v.disk));
}

const scene::head_key& head_parameter_key(head_parameter p) {
  // test_calibration_scene checks that each is a number key.
  return *scene::find_head_key(head_parameter_specs[static_cast<std::size_t>(p)].key);
}

parameter_set scene_parameters(const scene::scene_config& scene) {
  const double absent = std::numeric_limits<double>::quiet_NaN();
  parameter_set p = parameter_set::nominal(scene.heads.size());
  for (std::size_t k = 0; k < scene.heads.size(); ++k) {
    const scene::head_config& h = scene.heads[k];
    // The physics' parameters exist where the chain runs (parameters.hpp).
    const bool physics = scene::physics_on(scene, h);
    for (std::size_t i = 0; i < head_parameter_count; ++i) {
      const scene::head_key& key = head_parameter_key(head_parameter(i));
      p.value(k, head_parameter(i)) =
          key.group == scene::head_key_group::physics && !physics ? absent : h.*key.field;
    }
  }
  p.value(earth_parameter::horizon) = scene.horizon_km;
  p.value(earth_parameter::horizon_pole) = scene.horizon_pole_km;
  p.value(earth_parameter::horizon_shift) = scene.horizon_shift_km;
  const bool limb = scene::any_physics(scene);
  p.value(earth_parameter::radiance_offset) = limb ? scene.radiance_offset_km : absent;
  p.value(earth_parameter::radiance_scale) = limb ? scene.radiance_scale_km : absent;
  return p;
}

std::vector<head_noise> scene_noise(const scene::scene_config& scene) {
  std::vector<head_noise> out;
  for (const scene::head_config& h : scene.heads) out.push_back({h.noise_deg, h.lsb_deg});
  return out;
}

}  // namespace conescan::calibration

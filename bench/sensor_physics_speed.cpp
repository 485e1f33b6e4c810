// conescan-sensor-physics-speed: time per head-row of MODEL §5's geometric scan crossings and of
// MODEL §12's sensor physics chain (include/conescan/sensor_physics.hpp), and each one's
// difference from the brute-force reference (tests/support/sensor_physics_reference.hpp).
//
// Usage: conescan-sensor-physics-speed [--rows N] [--reference-rows M] [--h-deg H] [--fov-deg F]
//                                      [--tau-ms T] [--circle] [--ellipsoid] [--csv]
// --csv prints instead, for the first row's Earth-in crossing, every 0.005 deg over its window:
// the central line's tangent height, its radiance (the pencil's signal), the field's mean s, the
// detector's output y and the locator's level (the material for a picture), and nothing else.
// Defaults: the paper's head (alpha 0, beta 90, gamma 45, sigma 0.02 deg) along one orbit of the
// paper's ellipse (a = 7280 km, e = 0.1, rows at equal true anomaly), a horizon 40 km up; the
// physics of the brief: a 1.5 deg square field, 1 ms of lag at 1 rev/s, the normalised locator
// at 1/2, H = 7 km, delta50 = 40 km. The reference runs on M rows spread over the orbit (each
// takes seconds). Timings: median of 15 runs (bench/timing.hpp); the machine's load moves them,
// the ratio less.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include "support/sensor_physics_scene.hpp"
#include "timing.hpp"

using namespace conescan;

namespace {

struct options {
  int rows = 360;
  int reference_rows = 3;
  double h_deg = 0.02;
  double fov_deg = 1.5;
  double tau_ms = 1.0;
  bool circle = false;
  bool ellipsoid = false;
  bool csv = false;
};

options parse(int argc, char** argv) {
  options o;
  for (int i = 1; i < argc; ++i) {
    auto next = [&]() { return i + 1 < argc ? std::atof(argv[++i]) : 0.0; };
    if (!std::strcmp(argv[i], "--rows"))
      o.rows = static_cast<int>(next());
    else if (!std::strcmp(argv[i], "--reference-rows"))
      o.reference_rows = static_cast<int>(next());
    else if (!std::strcmp(argv[i], "--h-deg"))
      o.h_deg = next();
    else if (!std::strcmp(argv[i], "--fov-deg"))
      o.fov_deg = next();
    else if (!std::strcmp(argv[i], "--tau-ms"))
      o.tau_ms = next();
    else if (!std::strcmp(argv[i], "--circle"))
      o.circle = true;
    else if (!std::strcmp(argv[i], "--ellipsoid"))
      o.ellipsoid = true;
    else if (!std::strcmp(argv[i], "--csv"))
      o.csv = true;
    else {
      std::fprintf(stderr, "unknown option %s\n", argv[i]);
      std::exit(2);
    }
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const options opt = parse(argc, argv);
  // The rows: the satellite along the paper's ellipse, zero attitude, the pole turning with it.
  std::vector<conescan_test::physics_scene<double>> scenes;
  const double a = 7280000, e = 0.1;
  for (int i = 0; i < opt.rows; ++i) {
    const double nu = 2 * pi<double>() * i / opt.rows;
    conescan_test::physics_scene_options o;
    o.distance_m = a * (1 - e * e) / (1 + e * std::cos(nu));
    o.ellipsoid = opt.ellipsoid;
    o.b_m = 6356752.314245L + 40000;
    o.polar_x = std::cos(nu);  // a polar orbit: the pole in the orbit plane, turning
    o.polar_y = 0;
    o.polar_z = std::sin(nu);
    scenes.push_back(conescan_test::make_physics_scene<double>(o));
  }
  sensor_physics_settings<double> s;
  s.field = {deg_to_rad(opt.fov_deg), opt.circle ? field_shape::circle : field_shape::square};
  s.spin_hz = 1;
  s.tau_s = opt.tau_ms * 1e-3;
  s.offset_m = 40000;
  const sensor_physics_head<double> head = sensor_physics_head_of(s);
  auto work = std::make_unique<sensor_physics_workspace<double>>();

  if (opt.csv) {
    // The first row's Earth-in window, sampled.
    const auto& sc = scenes[0];
    const crossings<double> c = sc.physics(head, 0.0, *work);
    const auto& w = work->window[0];
    const auto peak = std::max(physics_detail::evaluate_window(w, head, w.root_hi).output,
                               physics_detail::evaluate_window(w, head, w.hi).output);
    std::printf("phi_deg,height_km,radiance,field_mean,output,level,crossing_deg\n");
    const double step = deg_to_rad(0.005);
    for (double phi = w.root_lo; phi <= w.root_hi; phi += step) {
      const double height = sc.height_at(phi).height_m;
      const auto v = physics_detail::evaluate_window(w, head, phi);
      std::printf("%.6f,%.6f,%.9f,%.9f,%.9f,%.9f,%.9f\n", rad_to_deg(phi), height / 1000,
                  radiance(head.profile, s.plateau, height), v.mean, v.output, 0.5 * peak,
                  rad_to_deg(c.phi_in));
    }
    return 0;
  }

  const std::size_t n = scenes.size();
  std::vector<crossings<double>> geometric(n), physics(n);
  const bench::sample_time t_geometric = bench::time_per_sample(n, [&] {
    for (std::size_t i = 0; i < n; ++i) {
      const auto& sc = scenes[i];
      geometric[i] = opt.ellipsoid ? sc.head.scan_crossings(sc.horizon)
                                   : sc.head.scan_crossings(
                                         sc.nadir_scan,
                                         disk_trig_of(static_cast<double>(sc.options.a_m),
                                                      static_cast<double>(sc.options.distance_m)));
      bench::keep(geometric[i]);
    }
  });
  const bench::sample_time t_physics = bench::time_per_sample(
      n,
      [&] {
        for (std::size_t i = 0; i < n; ++i) {
          physics[i] = scenes[i].physics(head, 0.0, *work);
          bench::keep(physics[i]);
        }
      },
      7);
  int ok = 0;
  for (const auto& c : physics) ok += c.state == status::ok;
  std::printf("rows %zu (%d ok), %s field %.2f deg, lag %.2f ms at 1 rev/s, normalised 1/2, %s\n",
              n, ok, opt.circle ? "circle" : "square", opt.fov_deg, opt.tau_ms,
              opt.ellipsoid ? "ellipsoid" : "sphere");
  std::printf("geometric scan crossings   %10.1f ns/row (min %.1f, max %.1f)\n",
              t_geometric.median_ns, t_geometric.min_ns, t_geometric.max_ns);
  std::printf("physics chain              %10.1f ns/row (min %.1f, max %.1f)\n",
              t_physics.median_ns, t_physics.min_ns, t_physics.max_ns);
  std::printf("ratio physics / geometric  %10.1f (median), %.1f (min / min)\n",
              t_physics.median_ns / t_geometric.median_ns, t_physics.min_ns / t_geometric.min_ns);

  // Against the reference, on rows spread over the orbit.
  double worst_fast = 0, worst_geometric = 0;
  const long double to_deg = 180 / 3.14159265358979323846264338327950288L;
  for (int k = 0; k < opt.reference_rows; ++k) {
    const std::size_t i = n * k / std::max(1, opt.reference_rows);
    const auto& sc = scenes[i];
    if (physics[i].state != status::ok) continue;
    const auto clock_start = std::chrono::steady_clock::now();
    const auto r = conescan_test::reference_crossings(
        sc.reference(0), conescan_test::reference_settings_of(s),
        (sc.geometric.phi_in + sc.geometric.phi_out) / 2, deg_to_rad(opt.h_deg));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
    if (r.crossings.state != status::ok) continue;
    const double fast = static_cast<double>(
        std::max(std::fabs((physics[i].phi_in - r.crossings.phi_in) * to_deg),
                 std::fabs((physics[i].phi_out - r.crossings.phi_out) * to_deg)));
    const double geom = static_cast<double>(
        std::max(std::fabs((geometric[i].phi_in - r.crossings.phi_in) * to_deg),
                 std::fabs((geometric[i].phi_out - r.crossings.phi_out) * to_deg)));
    worst_fast = std::max(worst_fast, fast);
    worst_geometric = std::max(worst_geometric, geom);
    std::printf(
        "row %4zu r %.0f km: reference (h %.3f deg, %.1f s): fast %.2e deg, geometric "
        "%.4f deg\n",
        i, static_cast<double>(sc.options.distance_m) / 1000, opt.h_deg, seconds, fast, geom);
  }
  if (opt.reference_rows > 0)
    std::printf(
        "worst against the reference: fast %.2e deg, geometric %.4f deg (the physics "
        "itself)\n",
        worst_fast, worst_geometric);
  return 0;
}

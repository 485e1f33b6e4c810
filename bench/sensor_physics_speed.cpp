// conescan-sensor-physics-speed: time per head-row of MODEL §5's geometric scan crossings and of
// MODEL §12's sensor physics by each method (the chain of include/conescan/sensor_physics/ and
// the table of its shifts, src/simulation/physics_table.hpp), and each one's worst difference from
// the brute-force reference (tests/support/sensor_physics_reference.hpp) over the reference rows:
// the speed-accuracy chart (docs/SENSOR_PHYSICS.md, "Cost"; drawn by
// scripts/sensor-physics-chart.sh).
//
// Usage: conescan-sensor-physics-speed [--rows N] [--reference-rows M] [--h-deg H] [--fov-deg F]
//                                      [--tau-ms T] [--attitude-deg A] [--circle] [--ellipsoid]
//                                      [--season A] [--sun-deg D] [--csv]
//                                      [--chart-csv FILE]
// --csv prints instead, for the first row's Earth-in crossing, every 0.005 deg over its window:
// the central line's tangent height, its radiance (the pencil's signal), the field's mean s, the
// detector's output y and the locator's level (the material for a picture), and nothing else.
// --chart-csv also writes one line per method: its time per row, its ratio to the geometric row,
// its worst error against the reference and the share of rows the table served. The table's
// line counts every row (the chain's where it does not serve); "table (served)" times the rows
// it serves alone.
// Defaults: the paper's head (alpha 0, beta 90, gamma 45, sigma 0.02 deg) along one orbit of the
// paper's ellipse (a = 7280 km, e = 0.1, rows at equal true anomaly; --attitude-deg: roll and pitch
// wander over +-A, A sin 3 nu and A cos 2 nu, else zero), a horizon 40 km up; the physics: a
// 1.5 deg square field, 1 ms of lag at 1 rev/s, the normalised locator at 1/2, H = 7 km,
// delta50 = 40 km. --ellipsoid: WGS84's apparent horizon 40 km up (a, b + 40 km); --season A: the
// season term with amplitude A and the Sun's declination --sun-deg (default 20 deg). The
// reference runs on M rows spread over the orbit (each takes seconds).
// Timings: median of 7 runs of each method, 15 of the geometry (bench/timing.hpp); the machine's
// load moves them, the ratios less.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include "conescan/sensor_physics.hpp"
#include "simulation/physics_table.hpp"
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
  double attitude_deg = 0;
  bool circle = false;
  bool ellipsoid = false;
  double season = 0;
  double sun_deg = 20;
  bool csv = false;
  const char* chart_csv = nullptr;
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
    else if (!std::strcmp(argv[i], "--attitude-deg"))
      o.attitude_deg = next();
    else if (!std::strcmp(argv[i], "--circle"))
      o.circle = true;
    else if (!std::strcmp(argv[i], "--ellipsoid"))
      o.ellipsoid = true;
    else if (!std::strcmp(argv[i], "--season"))
      o.season = next();
    else if (!std::strcmp(argv[i], "--sun-deg"))
      o.sun_deg = next();
    else if (!std::strcmp(argv[i], "--csv"))
      o.csv = true;
    else if (!std::strcmp(argv[i], "--chart-csv") && i + 1 < argc)
      o.chart_csv = argv[++i];
    else {
      std::fprintf(stderr, "unknown option %s\n", argv[i]);
      std::exit(2);
    }
  }
  return o;
}

/// The table method (src/simulation/physics_table.hpp) on the rows: built once over their box with
/// the budget of a day's scene at 1 s, then timed per row as a scene runs it: the table's
/// variables, the geometric crossings and the series.
struct table_run {
  bool built = false;
  long evaluations = 0;
  int nodes[6] = {1, 1, 1, 1, 1, 1};
  int pieces = 0;
  long table_rows = 0;  ///< rows the table served (the others ran the chain)
  int chain_cells = 0;  ///< the ellipsoid's cells left to the chain
  double build_ms = 0, worst_check_deg = 0;
  bench::sample_time time{};
  bench::sample_time served_time{};  ///< the served rows alone (the chain's left out)
  std::vector<crossings<double>> result;
};

/// Times the table's rows (the chain's where it does not serve) once built: `row(i, out)` is a
/// scene's row by table, false where the chain runs it.
template <class Table, class Row>
void time_table(table_run& run, const Table& table,
                const std::vector<conescan_test::physics_scene<double>>& scenes,
                const sensor_physics_head<double>& head, double sin_sun, Row row) {
  run.built = true;
  const auto& nodes = table.report().nodes;
  for (std::size_t d = 0; d < nodes.size(); ++d) run.nodes[d] = nodes[d];
  run.pieces = static_cast<int>(table.pieces());
  run.worst_check_deg = rad_to_deg(table.report().worst_check);
  const std::size_t n = scenes.size();
  run.result.assign(n, crossings<double>::failed(status::invalid));
  auto work = std::make_unique<sensor_physics_workspace<double>>();
  run.time = bench::time_per_sample(
      n,
      [&] {
        for (std::size_t i = 0; i < n; ++i) {
          crossings<double> g;
          if (!row(i, g, run.result[i]))  // the chain's row, as a scene
            run.result[i] = scenes[i].physics(head, sin_sun, *work);
          bench::keep(run.result[i]);
        }
      },
      15);
  std::vector<std::size_t> served;
  for (std::size_t i = 0; i < n; ++i) {
    crossings<double> g, unused;
    if (row(i, g, unused)) served.push_back(i);
  }
  run.table_rows = static_cast<long>(served.size());
  if (served.empty()) return;
  run.served_time = bench::time_per_sample(
      served.size(),
      [&] {
        for (std::size_t i : served) {
          crossings<double> g;
          bench::keep(row(i, g, run.result[i]));
        }
      },
      15);
}

template <class Build>
auto timed_build(table_run& run, Build build) {
  const auto start = std::chrono::steady_clock::now();
  auto table = build();
  run.build_ms =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e3;
  return table;
}

table_run run_table(const std::vector<conescan_test::physics_scene<double>>& scenes,
                    const sensor_physics_settings<double>& s) {
  table_run run;
  const auto& first = scenes.front();
  const double radius_m = static_cast<double>(first.options.a_m);
  auto point = [](const conescan_test::physics_scene<double>& sc) {
    const vec3<double>& n = sc.nadir_scan;
    return scene::physics_table_point{static_cast<double>(sc.options.distance_m), std::acos(n.z),
                                      std::atan2(n.y, n.x)};
  };
  scene::physics_table_range range;
  for (const auto& sc : scenes) range.add(point(sc));
  const sensor_physics_head<double> fast_head = sensor_physics_head_of(s);
  const auto table = timed_build(run, [&] {
    return scene::physics_table::of(fast_head, first.head, radius_m, range, 86400,
                                    &run.evaluations);
  });
  if (!table) return run;
  time_table(run, *table, scenes, fast_head, 0.0,
             [&](std::size_t i, crossings<double>& g, crossings<double>& out) {
               const auto& sc = scenes[i];
               g = sc.head.scan_crossings(
                   sc.nadir_scan,
                   disk_trig_of(radius_m, static_cast<double>(sc.options.distance_m)));
               return g.state == status::ok && table->crossings_at(point(sc), g, out);
             });
  return run;
}

/// The same on the ellipsoid, with the season term's Sun.
table_run run_ellipsoid_table(const std::vector<conescan_test::physics_scene<double>>& scenes,
                              const sensor_physics_settings<double>& s, double sin_sun) {
  table_run run;
  const auto& first = scenes.front();
  const double a_m = static_cast<double>(first.options.a_m);
  const double b_m = static_cast<double>(first.options.b_m);
  scene::ellipsoid_axes_finder finder;
  for (const auto& sc : scenes) finder.add(sc.horizon.polar);
  const scene::ellipsoid_table_axes axes = finder.axes();
  scene::ellipsoid_table_range range;
  for (const auto& sc : scenes)
    range.add(scene::ellipsoid_table_point_of(sc.horizon, a_m, axes, sin_sun));
  // The cells of a day at 1 s over these rows (a day's rows visit the same ones, each row here
  // standing for 86400 / rows of the day's: the cells count the day's rows).
  scene::physics_table_cells<6> cells = scene::ellipsoid_physics_table::cells_for(range, 86400);
  const long day_rows_each = std::max(1L, 86400 / static_cast<long>(scenes.size()));
  for (const auto& sc : scenes)
    cells.add(scene::ellipsoid_table_point_of(sc.horizon, a_m, axes, sin_sun), day_rows_each);
  for (const auto& sc : scenes)
    cells.add_along(scene::ellipsoid_table_point_of(sc.horizon, a_m, axes, sin_sun));
  const sensor_physics_head<double> fast_head = sensor_physics_head_of(s);
  const auto table = timed_build(run, [&] {
    return scene::ellipsoid_physics_table::of(fast_head, first.head, a_m, b_m, axes, cells, 86400,
                                              &run.evaluations);
  });
  if (table) run.chain_cells = table->chain_cells();
  if (!table) return run;
  time_table(run, *table, scenes, fast_head, sin_sun,
             [&](std::size_t i, crossings<double>& g, crossings<double>& out) {
               const auto& sc = scenes[i];
               g = sc.head.scan_crossings(sc.horizon);
               return g.state == status::ok &&
                      table->crossings_at(
                          scene::ellipsoid_table_point_of(sc.horizon, a_m, axes, sin_sun), g, out);
             });
  return run;
}

/// The rows: the satellite along the paper's ellipse, zero attitude (or --attitude-deg's
/// wander), the pole turning with it.
std::vector<conescan_test::physics_scene<double>> benchmark_rows(const options& opt) {
  std::vector<conescan_test::physics_scene<double>> scenes;
  const double a = 7280000, e = 0.1;
  for (int i = 0; i < opt.rows; ++i) {
    const double nu = 2 * pi<double>() * i / opt.rows;
    conescan_test::physics_scene_options o;
    o.distance_m = a * (1 - e * e) / (1 + e * std::cos(nu));
    o.roll_deg = opt.attitude_deg * std::sin(3 * nu);
    o.pitch_deg = opt.attitude_deg * std::cos(2 * nu);
    o.ellipsoid = opt.ellipsoid;
    o.b_m = 6356752.314245L + 40000;
    o.polar_x = std::cos(nu);  // a polar orbit: the pole in the orbit plane, turning
    o.polar_y = 0;
    o.polar_z = std::sin(nu);
    scenes.push_back(conescan_test::make_physics_scene<double>(o));
  }
  return scenes;
}

sensor_physics_settings<double> benchmark_settings(const options& opt) {
  sensor_physics_settings<double> s;
  s.field = {deg_to_rad(opt.fov_deg), opt.circle ? field_shape::circle : field_shape::square};
  s.spin_hz = 1;
  s.tau_s = opt.tau_ms * 1e-3;
  s.offset_m = 40000;
  s.season_amplitude = opt.season;
  return s;
}

/// --csv: the first row's Earth-in window, sampled every 0.005 deg.
void print_window_csv(const conescan_test::physics_scene<double>& sc,
                      const sensor_physics_settings<double>& s, double sin_sun) {
  const sensor_physics_head<double> head = sensor_physics_head_of(s);
  auto work = std::make_unique<sensor_physics_workspace<double>>();
  const crossings<double> c = sc.physics(head, sin_sun, *work);
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
}

/// The geometric scan crossings of every row, timed.
bench::sample_time time_geometric(const std::vector<conescan_test::physics_scene<double>>& scenes,
                                  bool ellipsoid, std::vector<crossings<double>>& geometric) {
  const std::size_t n = scenes.size();
  geometric.assign(n, crossings<double>::failed(status::invalid));
  return bench::time_per_sample(n, [&] {
    for (std::size_t i = 0; i < n; ++i) {
      const auto& sc = scenes[i];
      geometric[i] =
          ellipsoid ? sc.head.scan_crossings(sc.horizon)
                    : sc.head.scan_crossings(
                          sc.nadir_scan, disk_trig_of(static_cast<double>(sc.options.a_m),
                                                      static_cast<double>(sc.options.distance_m)));
      bench::keep(geometric[i]);
    }
  });
}

/// A method's crossings of every row, its time per row, its worst error against the reference,
/// and the rows it served itself (the table's; the others ran the chain).
struct method {
  const char* label;
  std::vector<crossings<double>> result;
  bench::sample_time time;
  double worst_deg = 0;
  long fast_rows = 0, exact_rows = 0;
};

/// The chain (sensor_physics/chain.hpp) at its default resolution on every row, timed.
method time_chain(const std::vector<conescan_test::physics_scene<double>>& scenes,
                  const sensor_physics_settings<double>& s, double sin_sun) {
  const std::size_t n = scenes.size();
  method m{
      "chain", std::vector<crossings<double>>(n, crossings<double>::failed(status::invalid)), {}};
  const sensor_physics_head<double> head = sensor_physics_head_of(s);
  auto work = std::make_unique<sensor_physics_workspace<double>>();
  m.time = bench::time_per_sample(
      n,
      [&] {
        for (std::size_t i = 0; i < n; ++i) {
          m.result[i] = scenes[i].physics(head, sin_sun, *work);
          bench::keep(m.result[i]);
        }
      },
      3);
  m.exact_rows = static_cast<long>(n);
  return m;
}

/// The table's line: its pieces, nodes, evaluations and build, and its time per row over a day
/// at 1 s with the build (what scripts/sensor-physics-chart.sh reads).
void print_table_build(const table_run& table, bool ellipsoid) {
  const double day_ns = table.time.median_ns + table.build_ms * 1e6 / 86400;
  if (!table.built)
    std::printf("table: not built (%ld evaluations)\n", table.evaluations);
  else if (!ellipsoid)
    std::printf(
        "table: %d piece(s) of up to %d x %d x %d nodes, %ld evaluations of the chain in "
        "%.1f ms (worst check %.2e deg); over a day at 1 s (86 400 rows) %.1f ns/row with the "
        "build\n",
        table.pieces, table.nodes[0], table.nodes[1], table.nodes[2], table.evaluations,
        table.build_ms, table.worst_check_deg, day_ns);
  else
    std::printf(
        "table: %d piece(s) of up to %d x %d x %d x %d x %d x %d nodes, %d cell(s) left to the "
        "chain, %ld evaluations of the chain in %.1f ms (worst check %.2e deg); over a day at 1 s "
        "(86 400 rows) %.1f ns/row with the build\n",
        table.pieces, table.nodes[0], table.nodes[1], table.nodes[2], table.nodes[3],
        table.nodes[4], table.nodes[5], table.chain_cells, table.evaluations, table.build_ms,
        table.worst_check_deg, day_ns);
}

/// Every method against the brute-force reference on `reference_rows` rows spread over the orbit
/// (each method's worst_deg); the geometric crossings' worst error, and the rows compared.
int compare_with_reference(const std::vector<conescan_test::physics_scene<double>>& scenes,
                           const sensor_physics_settings<double>& s, double sin_sun,
                           const options& opt, const std::vector<crossings<double>>& geometric,
                           std::vector<method>& methods, double& worst_geometric) {
  const long double to_deg = 180 / 3.14159265358979323846264338327950288L;
  const std::size_t n = scenes.size();
  worst_geometric = 0;
  int compared = 0;
  for (int k = 0; k < opt.reference_rows; ++k) {
    const std::size_t i =
        n * static_cast<std::size_t>(k) / static_cast<std::size_t>(std::max(1, opt.reference_rows));
    const auto& sc = scenes[i];
    const auto clock_start = std::chrono::steady_clock::now();
    const auto r = conescan_test::reference_crossings_of(sc, s, sin_sun, opt.h_deg);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
    if (r.crossings.state != status::ok) continue;
    ++compared;
    auto error = [&](const crossings<double>& c) {
      if (c.state != status::ok) return std::numeric_limits<double>::infinity();
      return static_cast<double>(std::max(std::fabs((c.phi_in - r.crossings.phi_in) * to_deg),
                                          std::fabs((c.phi_out - r.crossings.phi_out) * to_deg)));
    };
    std::printf("row %4zu r %.0f km: reference (h %.3f deg, %.1f s):", i,
                static_cast<double>(sc.options.distance_m) / 1000, opt.h_deg, seconds);
    for (method& m : methods) {
      const double difference = error(m.result[i]);
      m.worst_deg = std::max(m.worst_deg, difference);
      std::printf(" %s %.1e", m.label, difference);
    }
    const double g = error(geometric[i]);
    worst_geometric = std::max(worst_geometric, g);
    std::printf(" geometric %.4f\n", g);
  }
  return compared;
}

/// The summary: each method's time per row, its ratio to the geometric row, its worst error.
void print_summary(const bench::sample_time& t_geometric, double worst_geometric, int compared,
                   const std::vector<method>& methods, const table_run& table) {
  std::printf("%-16s %12s %10s %12s %12s\n", "method", "ns/row", "x geom", "worst deg",
              "fast rows");
  std::printf("%-16s %12.1f %10.1f %12.4f %12s\n", "geometric", t_geometric.median_ns, 1.0,
              compared > 0 ? worst_geometric : NAN, "-");
  for (const method& m : methods)
    std::printf("%-16s %12.1f %10.1f %12.2e %7ld/%ld\n", m.label, m.time.median_ns,
                m.time.median_ns / t_geometric.median_ns, compared > 0 ? m.worst_deg : NAN,
                m.fast_rows, m.fast_rows + m.exact_rows);
  if (table.built && table.table_rows > 0)
    std::printf("%-16s %12.1f %10.1f %12s %7ld/%ld\n", "table (served)",
                table.served_time.median_ns, table.served_time.median_ns / t_geometric.median_ns,
                "-", table.table_rows, table.table_rows);
}

/// --chart-csv: one line per method (scripts/sensor-physics-chart.sh); false where it cannot be
/// written.
bool write_chart_csv(const char* path, const bench::sample_time& t_geometric,
                     double worst_geometric, int compared, const options& opt, std::size_t n,
                     const std::vector<method>& methods) {
  std::FILE* f = std::fopen(path, "w");
  if (f == nullptr) {
    std::fprintf(stderr, "cannot write %s\n", path);
    return false;
  }
  std::fprintf(f,
               "method,ns_per_row,ns_min,ns_max,ratio_to_geometric,worst_error_deg,"
               "reference_rows,reference_h_deg,fast_rows,rows\n");
  std::fprintf(f, "geometric,%.1f,%.1f,%.1f,1,%.6g,%d,%g,0,%zu\n", t_geometric.median_ns,
               t_geometric.min_ns, t_geometric.max_ns, worst_geometric, compared, opt.h_deg, n);
  for (const method& m : methods)
    std::fprintf(f, "%s,%.1f,%.1f,%.1f,%.2f,%.3g,%d,%g,%ld,%zu\n", m.label, m.time.median_ns,
                 m.time.min_ns, m.time.max_ns, m.time.median_ns / t_geometric.median_ns,
                 m.worst_deg, compared, opt.h_deg, m.fast_rows, n);
  return std::fclose(f) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  const options opt = parse(argc, argv);
  const std::vector<conescan_test::physics_scene<double>> scenes = benchmark_rows(opt);
  const sensor_physics_settings<double> s = benchmark_settings(opt);
  const double sin_sun = std::sin(deg_to_rad(opt.sun_deg));
  if (opt.csv) {
    print_window_csv(scenes[0], s, sin_sun);
    return 0;
  }
  const std::size_t n = scenes.size();
  std::vector<crossings<double>> geometric;
  const bench::sample_time t_geometric = time_geometric(scenes, opt.ellipsoid, geometric);
  // The methods: the chain at its default resolution, and the table of its shifts.
  std::vector<method> methods{time_chain(scenes, s, sin_sun)};
  const table_run table =
      opt.ellipsoid ? run_ellipsoid_table(scenes, s, sin_sun) : run_table(scenes, s);
  if (table.built)  // the fast rows: those the table served
    methods.push_back({"table", table.result, table.time, 0, table.table_rows,
                       static_cast<long>(n) - table.table_rows});
  int ok = 0;
  for (const auto& c : methods[0].result) ok += c.state == status::ok;
  std::printf(
      "rows %zu (%d ok), %s field %.2f deg, lag %.2f ms at 1 rev/s, normalised 1/2, %s, season "
      "A = %g (Sun at %g deg)\n",
      n, ok, opt.circle ? "circle" : "square", opt.fov_deg, opt.tau_ms,
      opt.ellipsoid ? "WGS84's apparent horizon" : "sphere", opt.season, opt.sun_deg);
  std::printf("geometric scan crossings   %10.1f ns/row (min %.1f, max %.1f)\n",
              t_geometric.median_ns, t_geometric.min_ns, t_geometric.max_ns);
  print_table_build(table, opt.ellipsoid);
  double worst_geometric = 0;
  const int compared =
      compare_with_reference(scenes, s, sin_sun, opt, geometric, methods, worst_geometric);
  print_summary(t_geometric, worst_geometric, compared, methods, table);
  if (opt.chart_csv != nullptr &&
      !write_chart_csv(opt.chart_csv, t_geometric, worst_geometric, compared, opt, n, methods))
    return 1;
  return 0;
}

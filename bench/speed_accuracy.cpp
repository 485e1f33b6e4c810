// conescan-speed-accuracy: time per head sample and error against a cpp_bin_float_50 reference,
// for each method (accuracy/method.hpp) and each precision (float, double, long double), over
// the scene grid of accuracy/scene_grid.hpp. Writes a CSV (the data of the speed-accuracy chart
// and of docs/PERFORMANCE.md) and prints a table.
//
// Usage: conescan-speed-accuracy [--quick] [--threads N] [--csv FILE] [--bands-csv FILE]
//                                [--scenes-csv FILE]
//   --quick       the tests' coarser grid (seconds instead of minutes)
//   --csv         the summary, one row per method and precision (docs/data/speed-accuracy.csv)
//   --bands-csv   max error per band of the chord inversion's amplification |d eta / d Phi|
//                 (docs/data/error-by-amplification.csv)
//   --scenes-csv  every scene: its inputs, conditioning, and each method's status and error
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "accuracy/conditioning.hpp"
#include "accuracy/error_stats.hpp"
#include "accuracy/floor_kernel.hpp"
#include "accuracy/methods.hpp"
#include "accuracy/outcomes.hpp"
#include "accuracy/wgs84_figure.hpp"
#include "bench_options.hpp"
#include "timing.hpp"

namespace {

using namespace conescan;
using namespace conescan::accuracy;

struct options {
  bool quick = false;
  unsigned threads = 0;  // 0: all cores
  std::string csv_path;
  std::string bands_csv_path;
  std::string scenes_csv_path;
};

struct measurement {
  std::string method;
  std::string precision;
  bench::sample_time time{};
  double ratio_to_floor = 0;
  error_stats errors{};
  std::size_t wrong_root = 0;
  bool has_errors = true;
  std::vector<status> states{};       ///< per scene
  std::vector<double> eta_err_deg{};  ///< per scene, NaN unless both statuses are ok
};

using reference_outcomes = std::vector<std::vector<head_outcome<reference_scalar>>>;

/// Where the paper's '+' root is not the root nearest eta0: the reference of the quadratic
/// pipeline disagrees with that of the stable one although both are ok. The error of such a
/// scene against its own method's reference is small, and the answer is still wrong.
std::size_t wrong_root_count(const reference_outcomes& reference) {
  const auto& quadratic = reference[static_cast<std::size_t>(method::paper_quadratic)];
  const auto& stable = reference[static_cast<std::size_t>(method::stable_closed_form)];
  std::size_t count = 0;
  for (std::size_t i = 0; i < quadratic.size(); ++i)
    if (quadratic[i].state == status::ok && stable[i].state == status::ok &&
        error_deg(quadratic[i].eta_err, stable[i].eta_err) > 1e-9)
      ++count;
  return count;
}

template <class Head, class T>
bench::sample_time time_method(const Head& head, const std::vector<head_sample<T>>& timed) {
  return bench::time_per_sample(timed.size(), [&] {
    for (const head_sample<T>& s : timed) {
      const head_outcome<T> o = head(s);
      bench::keep(o);
    }
  });
}

template <class T>
bench::sample_time time_method(method m, const std::vector<head_sample<T>>& timed) {
  switch (m) {
    case method::paper_quadratic:
      return time_method(paper_quadratic_head<T>, timed);
    case method::stable_closed_form:
      return time_method(stable_closed_form_head<T>, timed);
    case method::scan_sphere:
      return time_method(scan_sphere_head<T>, timed);
    case method::scan_sphere_iterative:
      return time_method(scan_sphere_iterative_head<T>, timed);
    case method::scan_ellipsoid:
      return time_method(scan_ellipsoid_head<T>, timed);
    case method::scan_ellipsoid_iterative:
      return time_method(scan_ellipsoid_iterative_head<T>, timed);
    case method::scan_ellipsoid_quartic:
      return time_method(scan_ellipsoid_quartic_head<T>, timed);
  }
  return {};
}

/// Runs method m on a sample of any scalar.
auto runner(method m) {
  return [m](const auto& sample) { return run_method(m, sample); };
}

template <class T>
void measure_precision(const char* precision, const std::vector<scene_point>& scenes,
                       const std::vector<std::size_t>& timed_scenes,
                       const reference_outcomes& reference, std::size_t wrong_root,
                       unsigned threads, std::vector<measurement>& out) {
  const std::vector<head_sample<T>> samples = samples_of<T>(scenes, wgs84_figure());
  std::vector<head_sample<T>> timed;
  for (std::size_t i : timed_scenes) timed.push_back(samples[i]);

  measurement floor{"floor", precision};
  floor.has_errors = false;
  floor.time = bench::time_per_sample(timed.size(), [&] {
    for (const head_sample<T>& s : timed) {
      const T v = floor_kernel(s);
      bench::keep(v);
    }
  });
  floor.ratio_to_floor = 1;
  out.push_back(floor);

  for (method m : all_methods) {
    measurement row{std::string(method_name(m)), precision};
    const std::vector<head_outcome<T>> tested = outcomes_of(runner(m), samples, threads);
    const auto& ref = reference[static_cast<std::size_t>(m)];
    for (std::size_t i = 0; i < samples.size(); ++i) {
      row.errors.add(i, tested[i], ref[i]);
      row.states.push_back(tested[i].state);
      const bool both_ok = tested[i].state == status::ok && ref[i].state == status::ok;
      row.eta_err_deg.push_back(both_ok ? error_deg(tested[i].eta_err, ref[i].eta_err)
                                        : std::numeric_limits<double>::quiet_NaN());
    }
    row.time = time_method(m, timed);
    row.ratio_to_floor = row.time.median_ns / floor.time.median_ns;
    if (m == method::paper_quadratic) row.wrong_root = wrong_root;
    out.push_back(row);
  }
}

void write_csv(std::FILE* f, const std::vector<measurement>& rows,
               const std::vector<scene_point>& scenes) {
  std::fprintf(f,
               "method,precision,ns_per_sample,ns_min,ns_max,ratio_to_floor,max_eta_err_deg,"
               "rms_eta_err_deg,max_attitude_err_deg,compared,false_ok,false_refusal,wrong_root,"
               "worst_alpha_deg,worst_alt_km,worst_gamma_deg,worst_sigma_deg,worst_phi_a_deg,"
               "worst_lat_deg\n");
  for (const measurement& m : rows) {
    std::fprintf(f, "%s,%s,%.4g,%.4g,%.4g,%.4g,", m.method.c_str(), m.precision.c_str(),
                 m.time.median_ns, m.time.min_ns, m.time.max_ns, m.ratio_to_floor);
    if (!m.has_errors) {
      std::fprintf(f, "NaN,NaN,NaN,0,0,0,0,NaN,NaN,NaN,NaN,NaN,NaN\n");
      continue;
    }
    const scene_point& w = scenes[m.errors.worst_scene];
    std::fprintf(f, "%.3e,%.3e,%.3e,%zu,%zu,%zu,%zu,%g,%g,%g,%g,%g,%g\n", m.errors.max_eta_deg,
                 m.errors.rms_eta_deg(), m.errors.max_attitude_deg, m.errors.compared,
                 m.errors.false_ok, m.errors.false_refusal, m.wrong_root, w.alpha_deg, w.alt_km,
                 w.gamma_deg, w.sigma_deg, w.phi_a_deg, w.lat_deg);
  }
}

void write_scenes_csv(std::FILE* f, const std::vector<measurement>& rows,
                      const std::vector<scene_point>& scenes, const reference_outcomes& reference,
                      const std::vector<chord_conditioning<double>>& conditioning) {
  std::fprintf(f,
               "alpha_deg,alt_km,gamma_deg,sigma_deg,phi_a_deg,lat_deg,half_chord_deg,"
               "amplification");
  for (method m : all_methods)
    std::fprintf(f, ",%s_reference_status", std::string(method_name(m)).c_str());
  for (const measurement& m : rows)
    if (m.has_errors)
      std::fprintf(f, ",%s_%s_status,%s_%s_eta_err_deg", m.method.c_str(), m.precision.c_str(),
                   m.method.c_str(), m.precision.c_str());
  std::fprintf(f, "\n");
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const scene_point& s = scenes[i];
    std::fprintf(f, "%g,%g,%g,%g,%g,%g,%.9g,%.6g", s.alpha_deg, s.alt_km, s.gamma_deg, s.sigma_deg,
                 s.phi_a_deg, s.lat_deg, rad_to_deg(conditioning[i].half_chord),
                 conditioning[i].amplification);
    for (const auto& r : reference) std::fprintf(f, ",%s", to_string(r[i].state));
    for (const measurement& m : rows)
      if (m.has_errors) std::fprintf(f, ",%s,%.3e", to_string(m.states[i]), m.eta_err_deg[i]);
    std::fprintf(f, "\n");
  }
}

/// The largest error of each method and precision per band of the amplification that the
/// stable processing sees (accuracy/conditioning.hpp): the error grows with it, and the bands
/// say how much of the domain meets a given bound. "none": the bias model has no crossing on
/// the sphere (only the ellipsoid method can be ok there); "fold": above the fold limit, where
/// only the paper's quadratic forms still return numbers.
void write_bands_csv(std::FILE* f, const std::vector<measurement>& rows,
                     const std::vector<chord_conditioning<double>>& conditioning) {
  struct band {
    const char* name;
    double low, high;
  };
  const band bands[] = {{"0-1", 0, 1},       {"1-10", 1, 10},         {"10-30", 10, 30},
                        {"30-100", 30, 100}, {"fold", 100, INFINITY}, {"none", NAN, NAN}};
  std::fprintf(f, "method,precision,amplification,scenes,max_eta_err_deg\n");
  for (const measurement& m : rows) {
    if (!m.has_errors) continue;
    for (const band& b : bands) {
      std::size_t count = 0;
      double worst = 0;
      for (std::size_t i = 0; i < conditioning.size(); ++i) {
        const double a = conditioning[i].amplification;
        const bool in_band = std::isnan(b.low) ? std::isnan(a) : a >= b.low && a < b.high;
        if (!in_band || std::isnan(m.eta_err_deg[i])) continue;
        ++count;
        if (m.eta_err_deg[i] > worst) worst = m.eta_err_deg[i];
      }
      std::fprintf(f, "%s,%s,%s,%zu,%.3e\n", m.method.c_str(), m.precision.c_str(), b.name, count,
                   worst);
    }
  }
}

void print_table(const std::vector<measurement>& rows) {
  std::printf("%-19s %-12s %10s %8s %12s %12s %12s %8s %6s %6s %6s\n", "method", "precision",
              "ns/sample", "x floor", "max eta err", "rms eta err", "max att err", "compared",
              "f.ok", "f.ref", "wrong");
  for (const measurement& m : rows) {
    std::printf("%-19s %-12s %10.1f %8.2f", m.method.c_str(), m.precision.c_str(), m.time.median_ns,
                m.ratio_to_floor);
    if (!m.has_errors) {
      std::printf("\n");
      continue;
    }
    std::printf(" %12.3e %12.3e %12.3e %8zu %6zu %6zu %6zu\n", m.errors.max_eta_deg,
                m.errors.rms_eta_deg(), m.errors.max_attitude_deg, m.errors.compared,
                m.errors.false_ok, m.errors.false_refusal, m.wrong_root);
  }
}

options parse(int argc, char** argv) {
  options o;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      o.quick = true;
    } else if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) {
      o.threads = static_cast<unsigned>(std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--csv") == 0 && i + 1 < argc) {
      o.csv_path = argv[++i];
    } else if (std::strcmp(argv[i], "--bands-csv") == 0 && i + 1 < argc) {
      o.bands_csv_path = argv[++i];
    } else if (std::strcmp(argv[i], "--scenes-csv") == 0 && i + 1 < argc) {
      o.scenes_csv_path = argv[++i];
    } else {
      bench::exit_with_usage(
          argv[0], "[--quick] [--threads N] [--csv FILE] [--bands-csv FILE] [--scenes-csv FILE]");
    }
  }
  o.threads = bench::threads_or_all(o.threads);
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const options opts = parse(argc, argv);
  const std::vector<scene_point> scenes =
      scene_grid(opts.quick ? test_grid_axes() : benchmark_grid_axes());
  std::fprintf(stderr, "speed-accuracy: %zu scenes; reference (cpp_bin_float_50) on %u threads\n",
               scenes.size(), opts.threads);

  const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  const std::vector<head_sample<reference_scalar>> reference_samples =
      samples_of<reference_scalar>(scenes, wgs84_figure());
  reference_outcomes reference;
  for (method m : all_methods) {
    reference.push_back(outcomes_of(runner(m), reference_samples, opts.threads));
    std::fprintf(stderr, "speed-accuracy: reference of %s done after %.0f s\n",
                 std::string(method_name(m)).c_str(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }

  // Timed: the scenes where every method's reference is ok, the same set for all methods.
  std::vector<std::size_t> timed_scenes;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    bool all_ok = true;
    for (const auto& r : reference) all_ok = all_ok && r[i].state == status::ok;
    if (all_ok) timed_scenes.push_back(i);
  }
  std::fprintf(stderr, "speed-accuracy: timing on the %zu scenes where every method is ok\n",
               timed_scenes.size());

  const std::size_t wrong_root = wrong_root_count(reference);
  std::vector<measurement> rows;
  measure_precision<float>("float", scenes, timed_scenes, reference, wrong_root, opts.threads,
                           rows);
  measure_precision<double>("double", scenes, timed_scenes, reference, wrong_root, opts.threads,
                            rows);
  measure_precision<long double>("long-double", scenes, timed_scenes, reference, wrong_root,
                                 opts.threads, rows);

  print_table(rows);
  auto write_file = [](const std::string& path, const auto& writer) {
    if (path.empty()) return true;
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (f == nullptr) {
      std::fprintf(stderr, "speed-accuracy: cannot write %s\n", path.c_str());
      return false;
    }
    writer(f);
    return std::fclose(f) == 0;
  };
  bool written = write_file(opts.csv_path, [&](std::FILE* f) { write_csv(f, rows, scenes); });
  if (!opts.scenes_csv_path.empty() || !opts.bands_csv_path.empty()) {
    const std::vector<head_sample<double>> samples = samples_of<double>(scenes, wgs84_figure());
    std::vector<chord_conditioning<double>> conditioning;
    for (const head_sample<double>& s : samples)
      conditioning.push_back(aligned_chord_conditioning(s));
    written = write_file(opts.bands_csv_path,
                         [&](std::FILE* f) { write_bands_csv(f, rows, conditioning); }) &&
              written;
    written = write_file(opts.scenes_csv_path,
                         [&](std::FILE* f) {
                           write_scenes_csv(f, rows, scenes, reference, conditioning);
                         }) &&
              written;
  }
  return written ? 0 : 1;
}

// conescan-stability-map: where the methods fail, over the plane of the true nadir angle eta of
// the spin axis and the Earth's angular radius rho, for one cone. Per cell: the error
// amplification |d eta / d Phi| of the chord inversion, each method's status in double (the
// head's nominal eta0 is the true eta, and MODEL §7's default attitude envelope of 10 deg
// applies), and the float and double error of each method against its cpp_bin_float_50
// reference. Methods: the stable closed form (bias model), the paper's printed forms, the scan
// model's closed form and the bracketed solver it replaced. The data of
// docs/stability-map.png. Defaults: gamma 45 deg (the paper's), sigma 0.2 deg at phi_A 180 deg: the
// cone is narrower than the processing assumes, so measured chords pass the peak of the assumed
// chord curve and the fold (no root) shows as a band; with the paper's sigma 0.02 deg at phi_A 0 it
// never appears.
//
// Usage: conescan-stability-map [--gamma-deg G] [--sigma-deg S] [--phi-a-deg P] [--step-deg D]
//                               [--threads N] > stability-map.csv
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "accuracy/conditioning.hpp"
#include "accuracy/error_stats.hpp"
#include "accuracy/methods.hpp"
#include "accuracy/outcomes.hpp"
#include "accuracy/wgs84_figure.hpp"
#include "bench_options.hpp"

namespace {

using namespace conescan;
using namespace conescan::accuracy;

struct options {
  double gamma_deg = 45;
  double sigma_deg = 0.2;
  double phi_a_deg = 180;
  double step_deg = 0.5;
  unsigned threads = 0;
};

/// Status codes of the map's categorical panels (status_index); wrong_root, after the last
/// status, marks an ok status of the paper's '+' root where the root nearest eta0 is the other.
constexpr int wrong_root_code = static_cast<int>(status_count);

int status_code(status s) {
  return static_cast<int>(status_index(s));
}

/// log10 of an error in degrees, NaN where there is none to show. An error of exactly 0 is
/// shown at the chart's floor, 1e-19 deg.
double log10_error(double error_deg) {
  if (std::isnan(error_deg)) return error_deg;
  return std::log10(error_deg > 1e-19 ? error_deg : 1e-19);
}

options parse(int argc, char** argv) {
  options o;
  for (int i = 1; i < argc; ++i) {
    auto value = [&] {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s: %s needs a value\n", argv[0], argv[i]);
        std::exit(2);
      }
      return std::atof(argv[++i]);
    };
    if (std::strcmp(argv[i], "--gamma-deg") == 0) {
      o.gamma_deg = value();
    } else if (std::strcmp(argv[i], "--sigma-deg") == 0) {
      o.sigma_deg = value();
    } else if (std::strcmp(argv[i], "--phi-a-deg") == 0) {
      o.phi_a_deg = value();
    } else if (std::strcmp(argv[i], "--step-deg") == 0) {
      o.step_deg = value();
    } else if (std::strcmp(argv[i], "--threads") == 0) {
      o.threads = static_cast<unsigned>(value());
    } else {
      bench::exit_with_usage(
          argv[0], "[--gamma-deg G] [--sigma-deg S] [--phi-a-deg P] [--step-deg D] [--threads N]");
    }
  }
  o.threads = bench::threads_or_all(o.threads);
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const options opts = parse(argc, argv);
  const earth_figure earth = wgs84_figure();

  // Cell centres: eta in (0, 180), rho in (0, 90). The head is mounted at alpha = 90 - eta with
  // zero attitude, so its nominal eta0 is the true eta; rho comes from the altitude
  // R / sin(rho) - R.
  std::vector<scene_point> cells;
  const int eta_cells = static_cast<int>(std::lround(180 / opts.step_deg));
  const int rho_cells = static_cast<int>(std::lround(90 / opts.step_deg));
  for (int i = 0; i < eta_cells; ++i)
    for (int j = 0; j < rho_cells; ++j) {
      const double eta_deg = (i + 0.5) * opts.step_deg;
      const double rho_deg = (j + 0.5) * opts.step_deg;
      const double r_m = earth.sphere_radius_m / std::sin(rho_deg * (pi<double>() / 180));
      cells.push_back({90 - eta_deg, (r_m - earth.sphere_radius_m) / 1000, opts.gamma_deg,
                       opts.sigma_deg, opts.phi_a_deg, 0});
    }
  std::fprintf(stderr, "stability-map: %zu cells, reference on %u threads\n", cells.size(),
               opts.threads);

  const std::vector<method> mapped{method::stable_closed_form, method::paper_quadratic,
                                   method::scan_sphere, method::scan_sphere_iterative};
  const auto reference_samples = samples_of<reference_scalar>(cells, earth);
  const auto float_samples = samples_of<float>(cells, earth);
  const auto double_samples = samples_of<double>(cells, earth);
  std::vector<std::vector<head_outcome<reference_scalar>>> reference;
  std::vector<std::vector<head_outcome<float>>> in_float;
  std::vector<std::vector<head_outcome<double>>> in_double;
  for (method m : mapped) {
    auto run = [m](const auto& sample) { return run_method(m, sample); };
    reference.push_back(outcomes_of(run, reference_samples, opts.threads));
    in_float.push_back(outcomes_of(run, float_samples, opts.threads));
    in_double.push_back(outcomes_of(run, double_samples, opts.threads));
  }

  std::printf("eta_deg,rho_deg,half_chord_deg,log10_amplification");
  for (method m : mapped) {
    const char* name = method_name(m).data();
    std::printf(",%s_status,%s_reference_status,%s_double_log10_err_deg,%s_float_log10_err_deg",
                name, name, name, name);
  }
  std::printf("\n");
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const double eta_deg = 90 - cells[c].alpha_deg;
    const double rho_deg =
        std::asin(earth.sphere_radius_m / (earth.sphere_radius_m + cells[c].alt_km * 1000)) *
        (180 / pi<double>());
    if (c > 0 && cells[c].alpha_deg != cells[c - 1].alpha_deg) std::printf("\n");
    const chord_conditioning<double> k = aligned_chord_conditioning(double_samples[c]);
    std::printf("%.6g,%.6g,%.6g,%.4g", eta_deg, rho_deg, rad_to_deg(k.half_chord),
                std::log10(k.amplification));
    for (std::size_t m = 0; m < mapped.size(); ++m) {
      const head_outcome<reference_scalar>& ref = reference[m][c];
      int code = status_code(in_double[m][c].state);
      // The paper's '+' root against the stable root nearest eta0, both in the reference.
      if (mapped[m] == method::paper_quadratic && ref.state == status::ok &&
          reference[0][c].state == status::ok &&
          error_deg(ref.eta_err, reference[0][c].eta_err) > 1e-9)
        code = wrong_root_code;
      auto error = [&](const auto& tested) {
        return tested.state == status::ok && ref.state == status::ok
                   ? log10_error(error_deg(tested.eta_err, ref.eta_err))
                   : std::nan("");
      };
      std::printf(",%d,%d,%.4g,%.4g", code, status_code(ref.state), error(in_double[m][c]),
                  error(in_float[m][c]));
    }
    std::printf("\n");
  }
  return 0;
}

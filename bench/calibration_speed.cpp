// conescan-calibration-speed: the calibration's fit on a day and on a month of 1 Hz telemetry
// from two heads (docs/CALIBRATION.md, "A month"). The scene is the README's recovery scene
// (the paper's orbit, e = 0.1, two heads of the scan model at beta = 90 and -90 deg, the horizon
// at 42 km, 0.01 deg crossing noise) with 8 free parameters: both heads' sigma, phi_A and
// dgamma, head 1's bias-in and the horizon height, from sigma = 0, no bias and 40 km. The
// telemetry is the scene layer's simulation, held in memory as the reader would hold it.
//
// Prints for the day and the month, on 1 and 2 threads: the fit's wall and CPU time (the
// model's geometry and the fit, scene_fit.hpp's fit_scene: the telemetry's reading is not in
// it), its passes over the data, the ratios the issue asks for (month over day CPU time, one
// thread over two), and the peak resident memory after each part. Also the forward model alone,
// ns per measurement in double and in Jets, on the analytic model and the real one, and the real
// one of a head with the sensor physics (a pencil with lag, a field with lag).
//
// Usage: conescan-calibration-speed [DAYS] (default 30; 0: the day only)
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "calibration/estimator.hpp"
#include "scene/scene_plan.hpp"
#include "scene_calibration/scene_fit.hpp"
#include "scene_calibration/scene_model.hpp"
#include "simulation/simulation.hpp"
#include "support/scene_telemetry.hpp"
#include "support/synthetic_model.hpp"
#include "timing.hpp"

namespace cal = conescan::calibration;
namespace sc = conescan::scene;

namespace {

double wall_since(const std::chrono::steady_clock::time_point& start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double peak_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024;
}

/// ns per measurement of a model alone over `data`, for scalar T: the Earth's horizon at 40 km,
/// or with `physics` the limb's 50 % point 40 km above the surface and 1 ms of lag; Jets carry
/// the derivatives of the inputs in `free` (scene_model.hpp's order), as the fit's do of its
/// free parameters.
template <class T, class Model>
double model_ns(const Model& model, const std::vector<cal::observation>& data, bool physics = false,
                cal::series_mask free = cal::all_series_inputs) {
  const cal::series_inputs values{0.01,
                                  0.02,
                                  0.0,
                                  physics ? 1.0 : 0.0,
                                  0.5,
                                  physics ? 0.0 : 40.0,
                                  0.0,
                                  0.0,
                                  physics ? 40.0 : 0.0,
                                  7.0};
  cal::head_geometry<T> head{};
  cal::earth_geometry<T> earth{};
  cal::seed_inputs(values, cal::input_slots_of(free), head, earth);
  return conescan::bench::time_per_sample(
             data.size(),
             [&] {
               for (const cal::observation& o : data) {
                 const cal::predicted_measurement<T> p =
                     model.template predict<T>(o.sample, head, earth);
                 conescan::bench::keep(p);
               }
             },
             3, 0.2)
      .median_ns;
}

sc::loaded_scene scene_of(double days, const std::string& head1, const std::string& head2,
                          const std::string& horizon_km) {
  const std::vector<sc::option_value> entries{
      {"model", "scan", {}},
      {"step-s", "1", {}},
      {"duration-s", std::to_string(static_cast<long>(days * 86400) - 1), {}},
      {"horizon-km", horizon_km, {}},
      {"head", head1, {}},
      {"head", head2, {}}};
  return sc::build_scene_plan(entries).value().scene(0);
}

sc::loaded_scene truth_scene(double days) {
  return scene_of(days, "sigma=0.05,phase=60,dgamma=0.02,bias-in=0.005,noise=0.01",
                  "beta=-90,sigma=0.03,phase=200,dgamma=-0.01,noise=0.01", "42");
}

sc::loaded_scene start_scene(double days) {
  return scene_of(days, "sigma=0,noise=0.01", "beta=-90,sigma=0,noise=0.01", "40");
}

const char* const free_list =
    "h1.sigma,h1.phase,h1.dgamma,h1.bias-in,h2.sigma,h2.phase,h2.dgamma,horizon-km";

struct timed_fit {
  double wall_s = 0;
  double cpu_s = 0;
};

timed_fit fit_once(const char* label, double days, const cal::telemetry& data, int threads) {
  cal::fit_options options;
  options.threads = threads;
  const auto free = cal::parse_free_list(free_list, 2).value();
  const double cpu_start = cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  const auto outcome = cal::fit_scene(start_scene(days), data, free, options);
  timed_fit t{wall_since(start), cpu_seconds() - cpu_start};
  if (!outcome.ok() || !std::holds_alternative<cal::fit_result>(outcome.value())) {
    std::printf("%s: the fit failed: %s\n", label,
                outcome.ok() ? "not converged" : outcome.error().text().c_str());
    std::exit(1);
  }
  const cal::fit_result& r = std::get<cal::fit_result>(outcome.value());
  const cal::fit_timing& f = r.timing;
  std::printf(
      "%s, %d thread%s: wall %.2f s, CPU %.2f s; %d iterations, %d linearisations, %d value "
      "passes (setup %.2f s, rounds %.2f s, of which linear solver %.4f s, uncertainty %.2f s), "
      "chi2/dof %.4f, %zu residuals, %zu warnings; peak memory so far %.0f MiB\n",
      label, threads, threads == 1 ? "" : "s", t.wall_s, t.cpu_s, r.iterations, f.linearizations,
      f.value_passes, f.setup_s, f.solve_s, f.linear_solver_s, f.uncertainty_s, r.chi2_dof,
      r.residual_count, r.warnings.size(), peak_mib());
  std::fflush(stdout);
  return t;
}

void model_costs() {
  const cal::forward_model_of<cal::synthetic_model> analytic{cal::synthetic_model({})};
  const std::vector<cal::observation> data =
      cal::simulate_observations(analytic.model(), cal::recovery_truth(), 0, 1, 20000, 0.01, 1, 0);
  std::printf("model alone, analytic: %.0f ns per measurement in double, %.0f ns in Jets\n",
              model_ns<double>(analytic.model(), data),
              model_ns<cal::parameter_jet>(analytic.model(), data));
  const cal::telemetry real_data = conescan_test::simulated_telemetry(truth_scene(20000.0 / 86400));
  const auto real = cal::scene_model::of_telemetry(start_scene(20000.0 / 86400), real_data);
  std::printf("model alone, real (scan model, sphere): %.0f ns in double, %.0f ns in Jets\n",
              model_ns<double>(real.value(), real_data.observations),
              model_ns<cal::parameter_jet>(real.value(), real_data.observations));
}

// The real model of a head that runs MODEL §12's chain (the README's lag loop: 1 ms of lag at
// 1 rev/s, the limb's 50 % point 40 km up), on `rows` rows at 10 s: a pencil, or a field.
void physics_model_costs(const char* label, const std::string& head, long rows) {
  const std::vector<sc::option_value> entries{{"model", "scan", {}},
                                              {"step-s", "10", {}},
                                              {"duration-s", std::to_string(10 * (rows - 1)), {}},
                                              {"radiance-offset-km", "40", {}},
                                              {"head", head, {}}};
  const sc::loaded_scene scene = sc::build_scene_plan(entries).value().scene(0);
  const cal::telemetry data = conescan_test::simulated_telemetry(scene);
  const auto model = cal::scene_model::of_telemetry(scene, data);
  // Jets of all ten inputs (the fit's 12 slots), and of tau and the limb's height alone (the
  // chain on the compact Jet, scene_model.hpp).
  const cal::series_mask tau_and_limb = 1u << 3 | 1u << 8;
  std::printf(
      "model alone, real with physics (%s): %.0f ns in double, %.0f ns in Jets (all ten inputs "
      "free), %.0f ns (tau and the limb's height free)\n",
      label, model_ns<double>(model.value(), data.observations, true),
      model_ns<cal::parameter_jet>(model.value(), data.observations, true),
      model_ns<cal::parameter_jet>(model.value(), data.observations, true, tau_and_limb));
  std::fflush(stdout);
}

// The fit's time series of the chain (physics_time_series.hpp) on WGS84 with the season term (A
// = 0.2), 1 Hz rows over `minutes`: a linearisation's build (tau and the limb's height free,
// Jets at the gradient nodes) and a value pass's (double, at the next step's inputs), their chain
// evaluations and CPU seconds per 20-minute block.
void series_build_costs(const char* label, const std::string& head, int minutes) {
  const std::vector<sc::option_value> entries{{"model", "scan", {}},
                                              {"earth", "wgs84", {}},
                                              {"step-s", "1", {}},
                                              {"duration-s", std::to_string(minutes * 60 - 1), {}},
                                              {"radiance-offset-km", "40", {}},
                                              {"radiance-season", "0.2", {}},
                                              {"head", head, {}}};
  const sc::loaded_scene scene = sc::build_scene_plan(entries).value().scene(0);
  std::vector<double> times(static_cast<std::size_t>(minutes) * 60);
  for (std::size_t i = 0; i < times.size(); ++i) times[i] = static_cast<double>(i);
  auto model = cal::scene_model::of(scene, times);
  model.value().use_physics_series(0);
  const cal::series_inputs values{0.0, 0.0, 0.0, 1.0, 0.5, 0.0, 0.0, 0.0, 40.0, 7.0};
  auto pass = [&](auto scalar, double offset_km) {
    using T = decltype(scalar);
    cal::head_geometry<T> h{};
    cal::earth_geometry<T> e{};
    cal::series_inputs at = values;
    at[8] = offset_km;
    cal::seed_inputs(at, cal::input_slots_of(1u << 3 | 1u << 8), h, e);
    const std::size_t before = model.value().physics_series_evaluations();
    const double start = cpu_seconds();
    for (std::size_t row = 0; row < times.size(); ++row)
      conescan::bench::keep(model.value().template predict<T>({row, times[row], 0}, h, e));
    return std::pair{cpu_seconds() - start, model.value().physics_series_evaluations() - before};
  };
  const double blocks = minutes / 20.0;
  const auto [jet_s, jet_evaluations] = pass(cal::parameter_jet{}, 40.0);
  const auto [value_s, value_evaluations] = pass(0.0, 40.001);
  std::printf(
      "time series, %s, %d min at 1 Hz on WGS84: per 20-minute block, a linearisation's build "
      "%.3f s CPU (%.1f evaluations), a value pass's %.3f s (%.1f); rows served %zu of %zu\n",
      label, minutes, jet_s / blocks, static_cast<double>(jet_evaluations) / blocks,
      value_s / blocks, static_cast<double>(value_evaluations) / blocks,
      model.value().physics_series_served(), 2 * times.size());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const double days = argc > 1 ? std::strtod(argv[1], nullptr) : 30;
  model_costs();
  physics_model_costs("a pencil with 1 ms of lag", "sigma=0,spin-hz=1,tau-ms=1", 400);
  physics_model_costs("a 1.5 deg square field with 1 ms of lag",
                      "sigma=0,spin-hz=1,tau-ms=1,fov=1.5", 4);
  series_build_costs("a pencil with 1 ms of lag", "sigma=0,spin-hz=1,tau-ms=1", 120);
  series_build_costs("a 1.5 deg square field with 1 ms of lag",
                     "sigma=0,spin-hz=1,tau-ms=1,fov=1.5", 60);
  const cal::telemetry day = conescan_test::simulated_telemetry(truth_scene(1));
  std::printf("a day: %zu measurements, %s\n", day.observations.size(), free_list);
  const timed_fit day1 = fit_once("day", 1, day, 1);
  const timed_fit day2 = fit_once("day", 1, day, 2);
  std::printf("day: one thread over two %.2f (wall)\n", day1.wall_s / day2.wall_s);
  if (days <= 0) return 0;
  const auto simulate_start = std::chrono::steady_clock::now();
  const cal::telemetry month = conescan_test::simulated_telemetry(truth_scene(days));
  std::printf(
      "%g days: %zu measurements (%.0f MiB of telemetry), simulated in %.1f s; peak "
      "memory %.0f MiB\n",
      days, month.observations.size(),
      static_cast<double>(month.observations.capacity() * sizeof(cal::observation)) / (1 << 20),
      wall_since(simulate_start), peak_mib());
  std::fflush(stdout);
  const timed_fit month2 = fit_once("month", days, month, 2);
  const timed_fit month1 = fit_once("month", days, month, 1);
  std::printf(
      "month over day, CPU time: %.1f (1 thread), %.1f (2 threads); one thread over two (wall): "
      "day %.2f, month %.2f; peak resident memory %.0f MiB\n",
      month1.cpu_s / day1.cpu_s, month2.cpu_s / day2.cpu_s, day1.wall_s / day2.wall_s,
      month1.wall_s / month2.wall_s, peak_mib());
  return 0;
}

// Time per SGP4/SDP4 state (src/orbit/sgp4.hpp), ns, for orbits of each branch: 1000 times
// spread over one day and over 30 days from epoch, one state_at call each or one states_at
// call for all (where the resonance integration goes on from the previous time instead of
// restarting from epoch); the construction (sgp4init); the two-body Kepler state of the orbit
// layer as the yardstick. docs/SGP4.md quotes the output.
//
//   build/bench/conescan-sgp4-speed
#include <cstdio>
#include <variant>
#include <vector>

#include "orbit/kepler.hpp"
#include "orbit/sgp4.hpp"
#include "orbit/tle.hpp"
#include "timing.hpp"

using namespace conescan::orbit;

namespace {

struct bench_case {
  const char* name;
  const char* line1;
  const char* line2;
};

// From Vallado's SGP4-VER.TLE, one per branch of the model.
const bench_case cases[] = {
    {"near earth, full drag (CBERS 2)",
     "1 28057U 03049A   06177.78615833  .00000060  00000-0  35940-4 0  1836",
     "2 28057  98.4283 247.6961 0000884  88.1964 271.9322 14.35478080140550"},
    {"near earth, perigee < 220 km (SL-12 DEB)",
     "1 29238U 06022G   06177.28732010  .00766286  10823-4  13334-2 0   101",
     "2 29238  51.5595 213.7903 0202579  95.2503 267.9010 15.73823839  1061"},
    {"deep space, no resonance (NAVSTAR 53)",
     "1 28129U 03058A   06175.57071136 -.00000104  00000-0  10000-3 0   459",
     "2 28129  54.7298 324.8098 0048506 266.2640  93.1663  2.00562768 18443"},
    {"deep space, 12 h resonance (MOLNIYA 2-14)",
     "1 08195U 75081A   06176.33215444  .00000099  00000-0  11873-3 0   813",
     "2 08195  64.1586 279.0717 6877146 264.7651  20.2257  2.00491383225656"},
    {"deep space, 24 h resonance (ITALSAT 2)",
     "1 24208U 96044A   06177.04061740 -.00000094  00000-0  10000-3 0  1600",
     "2 24208   3.8536  80.0121 0026640 311.0977  48.3000  1.00778054 36119"},
};

/// `count` times spread over [0, span_min).
std::vector<double> times(double span_min, std::size_t count) {
  std::vector<double> t(count);
  for (std::size_t i = 0; i < count; ++i)
    t[i] = span_min * static_cast<double>(i) / static_cast<double>(count);
  return t;
}

double ns_per_state(const sgp4_propagator& model, const std::vector<double>& t) {
  const auto pass = [&] {
    for (double ti : t) conescan::bench::keep(model.state_at(ti));
  };
  return conescan::bench::time_per_sample(t.size(), pass).median_ns;
}

/// The same times in one states_at call (in order: the resonance integration goes on).
double ns_per_state_batch(const sgp4_propagator& model, const std::vector<double>& t) {
  std::vector<teme_state> out(t.size());
  const auto pass = [&] {
    model.states_at(t.data(), out.data(), t.size());
    conescan::bench::keep(out.back());
  };
  return conescan::bench::time_per_sample(t.size(), pass).median_ns;
}

}  // namespace

int main() {
  const std::size_t count = 1000;
  const std::vector<double> day = times(1440.0, count), month = times(30 * 1440.0, count);
  // The yardstick: a two-body state of the orbit layer (one Kepler solve), same orbit as CBERS.
  const elements cbers{7.18e6, 0.0000884, 1.7179, 4.3231, 1.5393, 4.7461};
  const kepler_orbit kepler(cbers, two_body_rates(cbers, 3.986004418e14), 3.986004418e14);
  const double kepler_ns = conescan::bench::time_per_sample(count, [&] {
                             for (double ti : day) conescan::bench::keep(kepler.state_at(ti * 60));
                           }).median_ns;
  std::printf("%-44s %10s %10s %10s %10s %8s\n", "orbit", "1 d", "30 d", "1 d batch", "30 d batch",
              "init");
  for (const bench_case& c : cases) {
    const tle set = (parse_tle(c.line1, c.line2)).value();
    const sgp4_propagator model(set);
    const double init_ns = conescan::bench::time_per_sample(1, [&] {
                             conescan::bench::keep(sgp4_propagator(set));
                           }).median_ns;
    std::printf("%-44s %10.0f %10.0f %10.0f %10.0f %8.0f\n", c.name, ns_per_state(model, day),
                ns_per_state(model, month), ns_per_state_batch(model, day),
                ns_per_state_batch(model, month), init_ns);
  }
  std::printf("%-44s %10.0f\n", "two-body Kepler state (orbit/kepler.hpp)", kepler_ns);
  const double parse_ns = conescan::bench::time_per_sample(1, [&] {
                            conescan::bench::keep(parse_tle(cases[0].line1, cases[0].line2));
                          }).median_ns;
  std::printf("%-44s %10.0f\n", "parse_tle (one set)", parse_ns);
}

// conescan-format-speed: the time per number of conescan-sim's formatter
// (src/text/shortest_double.hpp) against std::to_chars, on the numbers conescan-sim writes for
// the paper's scene (MODEL §8, --step-s 0.01), in one run so that the ratio holds whatever the
// machine's load (docs/PERFORMANCE.md). Checks on the way that the two texts are the same.
//
// Usage: conescan-format-speed [STEP_S]   (default 0.01 s: ~8 million numbers)
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "conescan/scalar.hpp"
#include "simulation/simulation.hpp"
#include "text/shortest_double.hpp"
#include "timing.hpp"

namespace {

// A row's numbers as conescan-sim writes them (src/cli/csv_rows.cpp), in column order;
// the two system columns repeat the head's, as they do for one healthy head.
void append_numbers(const conescan::scene::row& r, std::vector<double>& out) {
  using conescan::rad_to_deg;
  out.insert(out.end(), {r.t_s, rad_to_deg(r.true_anomaly_rad), r.r_m / 1000, r.alt_m / 1000,
                         rad_to_deg(r.lat_rad), rad_to_deg(r.rho_p_rad)});
  for (const conescan::scene::head_row& h : r.heads)
    out.insert(out.end(),
               {rad_to_deg(h.chord_rad), rad_to_deg(h.phase_rad), rad_to_deg(h.eta_err_rad),
                rad_to_deg(h.roll_err_rad), rad_to_deg(h.pitch_err_rad)});
  out.insert(out.end(), {rad_to_deg(r.roll_err_rad), rad_to_deg(r.pitch_err_rad)});
}

}  // namespace

int main(int argc, char** argv) {
  conescan::scene::scene_config scene;  // the paper's scene
  scene.step_s = argc > 1 ? std::atof(argv[1]) : 0.01;
  const conescan::scene::simulation sim = conescan::scene::simulation::of(scene).value();
  std::vector<double> values;
  conescan::scene::row r = sim.make_row();
  for (std::uint64_t k = 0; k < sim.rows(); ++k) {
    sim.compute(k, r);
    append_numbers(r, values);
  }

  // Each pass writes every number and a separator into a 64 KiB buffer that it reuses, as the
  // CLI's sink does (its text stays in the cache; a buffer of the whole text would time memory).
  std::vector<char> buffer(1 << 16);
  const std::size_t wrap_at = buffer.size() - 64;
  auto pass_with = [&](auto write) {
    return [&, write] {
      char* at = buffer.data();
      for (double v : values) {
        at = write(at, v);
        *at++ = ',';
        if (static_cast<std::size_t>(at - buffer.data()) > wrap_at) at = buffer.data();
      }
      conescan::bench::keep(*at);
    };
  };
  const auto ours = conescan::bench::time_per_sample(
      values.size(),
      pass_with([](char* at, double v) { return conescan::text::write_shortest_double(at, v); }),
      7);
  const auto standard = conescan::bench::time_per_sample(
      values.size(), pass_with([](char* at, double v) {
        return std::to_chars(at, at + conescan::text::shortest_double_room, v).ptr;
      }),
      7);

  std::size_t mismatches = 0;
  for (double v : values) {
    char a[conescan::text::shortest_double_room], b[conescan::text::shortest_double_room];
    const char* end_a = conescan::text::write_shortest_double(a, v);
    const char* end_b = std::to_chars(b, b + sizeof b, v).ptr;
    if (std::string_view(a, static_cast<std::size_t>(end_a - a)) !=
        std::string_view(b, static_cast<std::size_t>(end_b - b)))
      ++mismatches;
  }
  std::printf("numbers: %zu (paper scene, %zu rows)\n", values.size(),
              static_cast<std::size_t>(sim.rows()));
  std::printf("%-24s %10s\n", "formatter", "ns/number");
  std::printf("%-24s %10.2f\n", "write_shortest_double", ours.median_ns);
  std::printf("%-24s %10.2f\n", "std::to_chars", standard.median_ns);
  std::printf("ratio: %.2f of std::to_chars' time; texts differ on %zu numbers\n",
              ours.median_ns / standard.median_ns, mismatches);
  return mismatches == 0 ? 0 : 1;
}

// conescan-half-chord-loop: the yardstick of the Python module's vectorised half chord
// (bench/python_half_chord.py): a plain C++ loop of conescan::half_chord over arrays psi, eta,
// rho, writing the values and the statuses into arrays as the module does.
//
// Usage: conescan-half-chord-loop INPUT OUTPUT RUNS
//   INPUT: 3 N float64 (psi, then eta, then rho, native byte order); OUTPUT: N float64 values,
//   then N uint8 statuses. Prints the median, min and max ns per element over RUNS runs of one
//   pass each (bench/timing.hpp).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "conescan/half_chord.hpp"
#include "timing.hpp"

namespace {

std::vector<double> read_all(const char* path) {
  std::vector<double> data;
  std::FILE* in = std::fopen(path, "rb");
  if (in == nullptr) return data;
  double chunk[4096];
  for (std::size_t got; (got = std::fread(chunk, sizeof(double), 4096, in)) > 0;)
    data.insert(data.end(), chunk, chunk + got);
  std::fclose(in);
  return data;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: conescan-half-chord-loop INPUT OUTPUT RUNS\n");
    return 2;
  }
  const std::vector<double> input = read_all(argv[1]);
  const std::size_t n = input.size() / 3;
  if (n == 0 || input.size() != 3 * n) {
    std::fprintf(stderr, "conescan-half-chord-loop: %s does not hold 3 N doubles\n", argv[1]);
    return 2;
  }
  const double* psi = input.data();
  const double* eta = psi + n;
  const double* rho = eta + n;
  std::vector<double> value(n);
  std::vector<std::uint8_t> state(n);
  auto pass = [&] {
    for (std::size_t i = 0; i < n; ++i) {
      const conescan::result<double> r = conescan::half_chord(psi[i], eta[i], rho[i]);
      value[i] = r.value;
      state[i] = static_cast<std::uint8_t>(r.state);
    }
    conescan::bench::keep(value.back());
  };
  const conescan::bench::sample_time t =
      conescan::bench::time_per_sample(n, pass, std::atoi(argv[3]), 0.0);

  std::FILE* out = std::fopen(argv[2], "wb");
  if (out == nullptr || std::fwrite(value.data(), sizeof(double), n, out) != n ||
      std::fwrite(state.data(), 1, n, out) != n || std::fclose(out) != 0) {
    std::fprintf(stderr, "conescan-half-chord-loop: cannot write %s\n", argv[2]);
    return 1;
  }
  std::printf("%.4f %.4f %.4f\n", t.median_ns, t.min_ns, t.max_ns);
  return 0;
}

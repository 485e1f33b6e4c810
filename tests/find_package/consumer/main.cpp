// A consumer of the installed core: the paper's first row, in double.
#include <conescan/conescan.hpp>
#include <cstdio>

int main() {
  using namespace conescan;
  const double deg = pi<double>() / 180;
  const head_optics<double> optics{45 * deg, 0.02 * deg, 0};
  const double rho = disk_angular_radius(6378137.0, 6552000.0).value;
  const crossings<double> c = bias_model_crossings(optics, 90 * deg, 0.0, rho);
  const double chord_deg = c.chord() / deg;
  std::printf("chord %.15g deg\n", chord_deg);
  // Reference: tests/data/reference/paper-scene-60s.csv, row t = 0.
  return c.state == status::ok && chord_deg > 142.24871185 && chord_deg < 142.24871186 ? 0 : 1;
}

// Built with -fno-exceptions -fno-rtti: the core needs neither. Also a smoke test of float.
#include "conescan/conescan.hpp"

int main() {
  using namespace conescan;
  const float deg = pi<float>() / 180;
  const scan_frame<float> frame = scan_frame_from_mounting(0.f, 90 * deg);
  const head_optics<float> optics{45 * deg, 0.02f * deg, 0};
  const float rho = disk_angular_radius(6378.137f, 6552.f).value;
  const crossings<float> c = bias_model_crossings(optics, 90 * deg, 0.f, rho);
  const head_estimate<float> e = process_head(frame, optics.gamma, rho, c);
  const float roll_deg = roll_pitch_from_nadir(e.nadir).roll / deg;
  // The paper's first row: roll error 0.00647 deg; float keeps ~1e-4 deg here.
  return e.state == status::ok && roll_deg > 0.006f && roll_deg < 0.007f ? 0 : 1;
}

// conescan-cli-floor: the least work that produces conescan-sim's columns for the paper's scene
// (MODEL §8, §9), the yardstick of bench/cli_speed.sh. One loop: Kepler's equation by Newton, the
// bias model's closed form, std::to_chars, one buffered write(2). No geodetic conversion
// (latitude is geocentric, altitude is r - a), no statuses, no wrapping, no checks; everything
// that does not change along the orbit is computed once before the loop.
//
// Usage: conescan-cli-floor [STEP_S [ORBITS [FORMATTER]]] > /dev/null
//   defaults: 10 s, 1 orbit, FORMATTER to_chars (the floor); FORMATTER conescan writes
//   the numbers with conescan-sim's formatter instead (src/text/shortest_double.hpp), to show
//   how much of conescan-sim's rate is the formatter (docs/PERFORMANCE.md).
#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>
#include <vector>

#include "text/shortest_double.hpp"

namespace {

// The paper's scene (MODEL §8) and WGS84 (MODEL §3).
constexpr double a_m = 7280e3, e = 0.1, i_deg = 97.7;
constexpr double earth_a_m = 6378137, gm_m3_s2 = 3.986004418e14;
constexpr double gamma_deg = 45, sigma_deg = 0.02;  // alpha 0, beta 90, phi_A 0
constexpr double pi = 3.14159265358979323846;
constexpr double deg = pi / 180;

class buffered_stdout {
 public:
  explicit buffered_stdout(bool conescan_format)
      : buffer_(1 << 16), conescan_format_(conescan_format) {}
  ~buffered_stdout() { flush(); }
  void number(double v) {
    char* const text_end = conescan_format_ ? conescan::text::write_shortest_double(at(), v)
                                            : std::to_chars(at(), end(), v).ptr;
    used_ = static_cast<std::size_t>(text_end - buffer_.data());
  }
  void text(const char* s, std::size_t n) {
    std::memcpy(at(), s, n);
    used_ += n;
  }
  void end_row() {
    if (used_ > buffer_.size() - 1024) flush();
  }
  void flush() {
    for (std::size_t done = 0; done < used_;) {
      const ssize_t n = ::write(STDOUT_FILENO, buffer_.data() + done, used_ - done);
      if (n <= 0) std::exit(1);
      done += static_cast<std::size_t>(n);
    }
    used_ = 0;
  }

 private:
  char* at() { return buffer_.data() + used_; }
  char* end() { return buffer_.data() + buffer_.size(); }
  std::vector<char> buffer_;
  std::size_t used_ = 0;
  bool conescan_format_;
};

}  // namespace

int main(int argc, char** argv) {
  const double step_s = argc > 1 ? std::atof(argv[1]) : 10;
  const double orbits = argc > 2 ? std::atof(argv[2]) : 1;
  const double mean_motion = std::sqrt(gm_m3_s2 / (a_m * a_m * a_m));
  const double duration_s = orbits * 2 * pi / mean_motion;
  const double sin_i = std::sin(i_deg * deg), root_1_e2 = std::sqrt(1 - e * e);
  // The head's constants: psi at the reference pulse (Eq. (1), phi_A = 0: psi = gamma + sigma),
  // eta = 90 deg, and the assumed gamma.
  const double cos_psi = std::cos((gamma_deg + sigma_deg) * deg);
  const double sin_psi = std::sin((gamma_deg + sigma_deg) * deg);
  const double eta = 90 * deg, cos_eta = std::cos(eta), sin_eta = std::sin(eta);
  const double cos_gamma = std::cos(gamma_deg * deg), sin_gamma = std::sin(gamma_deg * deg);

  buffered_stdout out(argc > 3 && std::string_view(argv[3]) == "conescan");
  static const char header[] =
      "t_s,nu_deg,r_km,alt_km,lat_deg,rho_deg,h1_chord_deg,h1_phase_deg,h1_eta_err_deg,"
      "h1_roll_err_deg,h1_pitch_err_deg,h1_status,roll_err_deg,pitch_err_deg,status\n";
  out.text(header, sizeof header - 1);
  for (std::uint64_t k = 0; static_cast<double>(k) * step_s <= duration_s; ++k) {
    const double t = static_cast<double>(k) * step_s;
    // Kepler: E - e sin E = M by Newton from E = M.
    const double m = std::remainder(mean_motion * t, 2 * pi);
    double ecc = m;
    for (int it = 0; it < 8; ++it) {
      const double d = (ecc - e * std::sin(ecc) - m) / (1 - e * std::cos(ecc));
      ecc -= d;
      if (std::abs(d) < 1e-15) break;
    }
    const double cos_e = std::cos(ecc), sin_e = std::sin(ecc);
    const double r = a_m * (1 - e * cos_e);
    const double nu = std::atan2(root_1_e2 * sin_e, cos_e - e);  // omega = 0: u = nu
    const double lat = std::asin(std::sin(nu) * sin_i);
    const double sin_rho = earth_a_m / r, cos_rho = std::sqrt(1 - sin_rho * sin_rho);
    // Bias model, Eq. (3), then the inversion, Eq. (6) ('+' root).
    const double cos_half_chord = (cos_rho - cos_psi * cos_eta) / (sin_psi * sin_eta);
    const double kk = sin_gamma * cos_half_chord;
    const double q2 = cos_gamma * cos_gamma + kk * kk;
    const double cos_eta_s = (cos_gamma * cos_rho - kk * std::sqrt(q2 - cos_rho * cos_rho)) / q2;
    const double eta_s = std::acos(cos_eta_s);
    // Sensed nadir at phase 0 in body axes (e3 = +y, e1 = +z): (0, cos eta_s, sin eta_s).
    const double roll = std::atan2(cos_eta_s, std::sin(eta_s)), pitch = 0;
    out.number(t);
    out.text(",", 1);
    out.number((nu < 0 ? nu + 2 * pi : nu) / deg);
    out.text(",", 1);
    out.number(r / 1000);
    out.text(",", 1);
    out.number((r - earth_a_m) / 1000);
    out.text(",", 1);
    out.number(lat / deg);
    out.text(",", 1);
    out.number(std::asin(sin_rho) / deg);
    out.text(",", 1);
    out.number(2 * std::acos(cos_half_chord) / deg);
    out.text(",0,", 3);
    out.number((eta_s - eta) / deg);
    out.text(",", 1);
    out.number(roll / deg);
    out.text(",", 1);
    out.number(pitch / deg);
    out.text(",ok,", 4);
    out.number(roll / deg);
    out.text(",", 1);
    out.number(pitch / deg);
    out.text(",ok\n", 4);
    out.end_row();
  }
  return 0;
}

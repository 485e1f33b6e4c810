// The core called from plain C++, one row at a time: what tests/python/test_agreement.py holds
// the Python bindings to, bit for bit. No pybind11, no NumPy, no broadcasting.
//
//   conescan_python_reference FUNCTION < rows     each line one call, each result one line
//   conescan_python_reference status_names        to_string of every status code, one a line
//
// A row lists the Python function's arguments in order: reals as text strtod reads (Python's
// float.hex(), nan, inf), vectors as 3 reals, frames as 9 (rows e1, e2, e3), statuses as
// integers. A result line lists the fields of the Python result in order: reals as %a, statuses
// and counts as integers, vectors and matrices row by row.
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

#include "conescan/conescan.hpp"

namespace {

using namespace conescan;

/// One input line. Each call reads the next argument; several reads in one declaration
/// (double a = r.real(), b = r.real();) happen in order.
class row {
 public:
  explicit row(const std::string& line) : in_(line) {}
  double real() {
    std::string token;
    in_ >> token;
    return std::strtod(token.c_str(), nullptr);
  }
  vec3<double> vec() {
    const double x = real(), y = real(), z = real();
    return vec3<double>(x, y, z);
  }
  scan_frame<double> frame() {
    const vec3<double> e1 = vec(), e2 = vec(), e3 = vec();
    return {e1, e2, e3, status::ok};
  }
  status code() {
    long value = 0;
    in_ >> value;
    return static_cast<status>(value);
  }
  crossings<double> measured() {  // phi_in, phi_out; the status comes last in Python
    const double phi_in = real(), phi_out = real();
    return {phi_in, phi_out, status::ok, 0};
  }

 private:
  std::istringstream in_;
};

void put(double x) {
  std::printf(" %a", x);
}
void put(status s) {
  std::printf(" %d", static_cast<int>(s));
}
void put(int n) {
  std::printf(" %d", n);
}
void put(const vec3<double>& v) {
  put(v.x);
  put(v.y);
  put(v.z);
}
void put(const mat3<double>& c) {  // row by row: c[col][row]
  for (int r = 0; r < 3; ++r)
    for (int col = 0; col < 3; ++col) put(c[col][r]);
}
void put(const result<double>& r) {
  put(r.value);
  put(r.state);
}
void put(const crossings<double>& c) {
  put(c.phi_in);
  put(c.phi_out);
  put(c.state);
  put(c.iterations);
}
void put(const nadir_angle_roots<double>& r) {
  put(r.plus);
  put(r.minus);
  put(r.half_separation);
  put(r.state);
}
void put(const scan_frame<double>& f) {
  put(f.e1);
  put(f.e2);
  put(f.e3);
  put(f.state);
}
void put(const scan_angles<double>& a) {
  put(a.polar);
  put(a.azimuth);
}
void put(const head_estimate<double>& e) {
  put(e.eta_s);
  put(e.nadir);
  put(e.state);
}
void put(const roll_pitch<double>& rp) {
  put(rp.roll);
  put(rp.pitch);
}

head_optics<double> optics(row& r) {
  const double gamma = r.real(), sigma = r.real(), phi_a = r.real();
  return {gamma, sigma, phi_a};
}

const std::map<std::string, std::function<void(row&)>> functions = {
    {"misaligned_cone_angle",
     [](row& r) {
       const double gamma = r.real(), sigma = r.real(), phi_b = r.real();
       put(misaligned_cone_angle(gamma, sigma, phi_b));
     }},
    {"disk_angular_radius",
     [](row& r) {
       const double radius = r.real(), orbit_radius = r.real();
       put(disk_angular_radius(radius, orbit_radius));
     }},
    {"half_chord",
     [](row& r) {
       const double psi = r.real(), eta = r.real(), rho = r.real();
       put(half_chord(psi, eta, rho));
     }},
    {"scan_frame_from_mounting",
     [](row& r) {
       const double alpha = r.real(), beta = r.real();
       put(scan_frame_from_mounting(alpha, beta));
     }},
    {"direction_in_scan_frame",
     [](row& r) {
       const scan_frame<double> f = r.frame();
       const double psi = r.real(), phi = r.real();
       put(direction_in_scan_frame(f, psi, phi));
     }},
    {"scan_angles_of",
     [](row& r) {
       const scan_frame<double> f = r.frame();
       const vec3<double> v = r.vec();
       put(scan_angles_of(f, v));
     }},
    {"nominal_nadir_angle", [](row& r) { put(nominal_nadir_angle(r.frame())); }},
    {"bias_model_crossings",
     [](row& r) {
       const head_optics<double> o = optics(r);
       const double eta = r.real(), phi_n = r.real(), rho = r.real();
       put(bias_model_crossings(o, eta, phi_n, rho));
     }},
    {"scan_model_crossings_sphere",
     [](row& r) {
       const head_optics<double> o = optics(r);
       const double eta = r.real(), phi_n = r.real(), rho = r.real();
       put(scan_model_crossings_sphere(o, eta, phi_n, rho));
     }},
    {"scan_model_crossings_ellipsoid",
     [](row& r) {
       const head_optics<double> o = optics(r);
       const scan_frame<double> frame_eci = r.frame();
       const vec3<double> p_eci = r.vec();
       const double a_eq = r.real(), b_pol = r.real();
       put(scan_model_crossings_ellipsoid(o, frame_eci, p_eci, a_eq, b_pol));
     }},
    {"with_crossing_noise",
     [](row& r) {
       crossings<double> c = r.measured();
       const double noise_in = r.real(), noise_out = r.real();
       c.state = r.code();
       put(with_crossing_noise(c, noise_in, noise_out));
     }},
    {"quantised",
     [](row& r) {
       crossings<double> c = r.measured();
       const double lsb = r.real();
       c.state = r.code();
       put(quantised(c, lsb));
     }},
    {"nadir_angle_roots_from_chord",
     [](row& r) {
       const double gamma = r.real(), rho_p = r.real(), half = r.real();
       put(nadir_angle_roots_from_chord(gamma, rho_p, half));
     }},
    {"nadir_angle_from_chord",
     [](row& r) {
       const double gamma = r.real(), rho_p = r.real(), half = r.real(), eta0 = r.real();
       put(nadir_angle_from_chord(gamma, rho_p, half, eta0));
     }},
    {"process_head",
     [](row& r) {
       const scan_frame<double> f = r.frame();
       const double gamma = r.real(), rho_p = r.real();
       crossings<double> c = r.measured();
       c.state = r.code();
       put(process_head(f, gamma, rho_p, c));
     }},
    {"roll_pitch_from_nadir", [](row& r) { put(roll_pitch_from_nadir(r.vec())); }},
    {"nadir_in_body",
     [](row& r) {
       const double roll = r.real(), pitch = r.real();
       put(nadir_in_body(roll, pitch));
     }},
    {"dcm_body_from_orbit",
     [](row& r) {
       const double roll = r.real(), pitch = r.real(), yaw = r.real();
       put(dcm_body_from_orbit(roll, pitch, yaw));
     }},
    {"dcm_eci_from_orbit",
     [](row& r) {
       const vec3<double> r_eci = r.vec(), v_eci = r.vec();
       put(dcm_eci_from_orbit(r_eci, v_eci));
     }},
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: conescan_python_reference FUNCTION|status_names < rows\n");
    return 2;
  }
  const std::string name = argv[1];
  if (name == "status_names") {
    for (int code = 0; code <= static_cast<int>(status::none); ++code)
      std::printf("%s\n", to_string(static_cast<status>(code)));
    return 0;
  }
  const auto function = functions.find(name);
  if (function == functions.end()) {
    std::fprintf(stderr, "conescan_python_reference: unknown function %s\n", name.c_str());
    return 2;
  }
  std::string line;
  while (std::getline(std::cin, line)) {
    row r(line);
    function->second(r);
    std::printf("\n");
  }
  return 0;
}

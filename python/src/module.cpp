// conescan._conescan: the core's functions over NumPy arrays (python/conescan/__init__.py
// re-exports them as the module conescan). Each binding is one lambda over one element calling
// the core; vectorize.hpp broadcasts it and results.hpp names the result's fields. Angles in rad,
// lengths in one unit per call (the simulation's metres), as in docs/API.md, which documents
// every function's domain and statuses.
#include <pybind11/pybind11.h>

#include "conescan/conescan.hpp"
#include "results.hpp"
#include "vectorize.hpp"
#ifdef CONESCAN_PYTHON_SCENES
#include "scenes.hpp"
#endif

namespace conescan::python {
namespace {

using frame = scan_frame<double>;
using vec = vec3<double>;

void def_geometry(py::module_& m) {
  def_vectorized(
      m, "misaligned_cone_angle",
      "psi: the angle from the spin axis S of the line of sight at scan azimuth offset phi_b = "
      "phi - phi_a, for a cone of half-angle gamma whose optical axis is tilted sigma from S (rad;"
      " MODEL §4, paper Eq. (1) corrected).\nReturns result(value, status); invalid outside gamma "
      "in"
      " (0, pi/2), sigma in [0, gamma), finite phi_b.",
      [](double gamma, double sigma, double phi_b) {
        return misaligned_cone_angle(gamma, sigma, phi_b);
      },
      py::arg("gamma"), py::arg("sigma"), py::arg("phi_b"));
  def_vectorized(
      m, "disk_angular_radius",
      "rho with sin rho = radius / r: the Earth disk's angular radius seen from orbit radius r "
      "(same length unit; MODEL §3).\nReturns result(value, status); invalid unless 0 < radius < "
      "r.",
      [](double radius, double r) { return disk_angular_radius(radius, r); }, py::arg("radius"),
      py::arg("r"));
  def_vectorized(
      m, "half_chord",
      "Phi: half the scan azimuth a cone of half-angle psi about S spends on a disk of angular "
      "radius rho centred eta from S (rad; MODEL §5, paper Eq. (3), half-angle form).\nReturns "
      "result(value, status); statuses invalid, miss, engulfed, grazing.",
      [](double psi, double eta, double rho) { return half_chord(psi, eta, rho); }, py::arg("psi"),
      py::arg("eta"), py::arg("rho"));
  def_vectorized(
      m, "scan_frame_from_mounting",
      "The scan frame of a head mounted at elevation alpha and azimuth beta (rad; MODEL §4).\n"
      "Returns scan_frame(frame, status): frame (..., 3, 3) holds the rows e1, e2, e3 (the spin "
      "axis) in body axes; invalid for |alpha| >= pi/2.",
      [](double alpha, double beta) { return scan_frame_from_mounting(alpha, beta); },
      py::arg("alpha"), py::arg("beta"));
  def_vectorized(
      m, "direction_in_scan_frame",
      "The unit vector at angle psi from e3 and scan azimuth phi in a frame (..., 3, 3) of rows e1,"
      " e2, e3: cos psi e3 + sin psi (cos phi e1 + sin phi e2), in the frame's axes (..., 3).",
      [](const frame& f, double psi, double phi) { return direction_in_scan_frame(f, psi, phi); },
      py::arg("frame"), py::arg("psi"), py::arg("phi"));
  def_vectorized(
      m, "scan_angles_of",
      "Polar angle from e3 and azimuth about it of a vector v (..., 3) in a frame (..., 3, 3) of "
      "rows e1, e2, e3 (same axes).\nReturns scan_angles(polar, azimuth): the eta, phi_n the "
      "forward models take for v = the nadir.",
      [](const frame& f, const vec& v) { return scan_angles_of(f, v); }, py::arg("frame"),
      py::arg("v"));
  def_vectorized(
      m, "nominal_nadir_angle",
      "eta0: the angle between a frame's spin axis e3 and body +z (= pi/2 - alpha when mounted by "
      "scan_frame_from_mounting). frame (..., 3, 3), rows e1, e2, e3 in body axes.",
      [](const frame& f) { return nominal_nadir_angle(f); }, py::arg("frame"));
}

void def_forward_models(py::module_& m) {
  def_vectorized(
      m, "bias_model_crossings",
      "Crossings of the paper's bias model (MODEL §5): a head of optics gamma, sigma, phi_a, the "
      "true nadir eta from S at azimuth phi_n, a sphere of angular radius rho (rad).\nReturns "
      "crossings(phi_in, phi_out, status, iterations); statuses invalid, miss, engulfed, grazing.",
      [](double gamma, double sigma, double phi_a, double eta, double phi_n, double rho) {
        return bias_model_crossings(head_optics<double>{gamma, sigma, phi_a}, eta, phi_n, rho);
      },
      py::arg("gamma"), py::arg("sigma"), py::arg("phi_a"), py::arg("eta"), py::arg("phi_n"),
      py::arg("rho"));
  def_vectorized(
      m, "scan_model_crossings_sphere",
      "Crossings of the exact scan model on a sphere (MODEL §5): arguments as "
      "bias_model_crossings.\nReturns crossings(phi_in, phi_out, status, iterations).",
      [](double gamma, double sigma, double phi_a, double eta, double phi_n, double rho) {
        return scan_model_crossings_sphere(head_optics<double>{gamma, sigma, phi_a}, eta, phi_n,
                                           rho);
      },
      py::arg("gamma"), py::arg("sigma"), py::arg("phi_a"), py::arg("eta"), py::arg("phi_n"),
      py::arg("rho"));
  def_vectorized(
      m, "scan_model_crossings_ellipsoid",
      "Crossings of the exact scan model on an ellipsoid of revolution about ECI z (MODEL §3, §5):"
      " the head's frame_eci (..., 3, 3), rows e1, e2, e3 in ECI; the satellite at p_eci (..., 3),"
      " m; semi-axes a_eq, b_pol, m.\nReturns crossings(phi_in, phi_out, status, iterations); "
      "frame_eci is not checked (pass a rotated scan frame).",
      [](double gamma, double sigma, double phi_a, const frame& frame_eci, const vec& p_eci,
         double a_eq, double b_pol) {
        return scan_model_crossings_ellipsoid(head_optics<double>{gamma, sigma, phi_a}, frame_eci,
                                              p_eci, a_eq, b_pol);
      },
      py::arg("gamma"), py::arg("sigma"), py::arg("phi_a"), py::arg("frame_eci"), py::arg("p_eci"),
      py::arg("a_eq"), py::arg("b_pol"));
  def_vectorized(
      m, "with_crossing_noise",
      "Measured crossings with detector noise: phi_in + noise_in, phi_out + noise_out (rad). "
      "Crossings whose status is not ok stay as they are.\nReturns crossings (iterations 0).",
      [](double phi_in, double phi_out, double noise_in, double noise_out, status state) {
        return with_crossing_noise(crossings<double>{phi_in, phi_out, state, 0}, noise_in,
                                   noise_out);
      },
      py::arg("phi_in"), py::arg("phi_out"), py::arg("noise_in"), py::arg("noise_out"),
      py::arg("status") = 0);
  def_vectorized(
      m, "quantised",
      "Crossings as telemetry reports them: chord and phase each rounded to a multiple of lsb "
      "(rad).\nReturns crossings (iterations 0).",
      [](double phi_in, double phi_out, double lsb, status state) {
        return quantised(crossings<double>{phi_in, phi_out, state, 0}, lsb);
      },
      py::arg("phi_in"), py::arg("phi_out"), py::arg("lsb"), py::arg("status") = 0);
}

void def_processing(py::module_& m) {
  def_vectorized(
      m, "nadir_angle_roots_from_chord",
      "Both roots eta of a half chord on an assumed disk (MODEL §6, paper Eq. (6) corrected): "
      "nominal cone angle gamma, disk radius rho_p, half chord half_chord (rad).\nReturns "
      "nadir_angle_roots(plus, minus, half_separation, status); statuses invalid, fold.",
      [](double gamma, double rho_p, double half) {
        return nadir_angle_roots_from_chord(gamma, rho_p, half);
      },
      py::arg("gamma"), py::arg("rho_p"), py::arg("half_chord"));
  def_vectorized(
      m, "nadir_angle_from_chord",
      "eta_s: the root of the chord inversion nearest eta0 (rad; MODEL §6).\nReturns result(value,"
      " status); statuses invalid, grazing, fold.",
      [](double gamma, double rho_p, double half, double eta0) {
        return nadir_angle_from_chord(gamma, rho_p, half, eta0);
      },
      py::arg("gamma"), py::arg("rho_p"), py::arg("half_chord"), py::arg("eta0"));
  def_vectorized(
      m, "process_head",
      "One head's processing (MODEL §6): the measured crossings phi_in, phi_out (and their status)"
      " inverted on the assumed disk rho_p with the nominal gamma, the sensed nadir built in the "
      "head's frame (..., 3, 3), rows e1, e2, e3 in body axes.\nReturns head_estimate(eta_s, "
      "nadir, status): nadir (..., 3) unit in body axes; the crossings' status if not ok, else "
      "those of nadir_angle_from_chord.",
      [](const frame& f, double gamma, double rho_p, double phi_in, double phi_out, status state) {
        return process_head(f, gamma, rho_p, crossings<double>{phi_in, phi_out, state, 0});
      },
      py::arg("frame"), py::arg("gamma"), py::arg("rho_p"), py::arg("phi_in"), py::arg("phi_out"),
      py::arg("status") = 0);
}

void def_attitude(py::module_& m) {
  def_vectorized(
      m, "roll_pitch_from_nadir",
      "Roll and pitch (rad) of a nadir estimate n (..., 3) in body axes (MODEL §2): roll = "
      "atan2(n_y, n_z), pitch = atan2(-n_x, hypot(n_y, n_z)).\nReturns roll_pitch(roll, pitch).",
      [](const vec& n) { return roll_pitch_from_nadir(n); }, py::arg("n"));
  def_vectorized(
      m, "nadir_in_body",
      "The orbital nadir in body axes (..., 3) for a true roll and pitch (rad; MODEL §2).",
      [](double roll, double pitch) { return nadir_in_body(roll, pitch); }, py::arg("roll"),
      py::arg("pitch"));
  def_vectorized(
      m, "dcm_body_from_orbit",
      "Direction cosine matrix body <- orbital (..., 3, 3) of the 3-2-1 Euler angles roll, pitch,"
      " yaw (rad; MODEL §2): v_body = C @ v_orbit.",
      [](double roll, double pitch, double yaw) {
        return rows_of(dcm_body_from_orbit(roll, pitch, yaw));
      },
      py::arg("roll"), py::arg("pitch"), py::arg("yaw"));
  def_vectorized(
      m, "dcm_eci_from_orbit",
      "Direction cosine matrix ECI <- orbital (..., 3, 3) from position r_eci and velocity v_eci "
      "(..., 3) (MODEL §2): columns x_o, y_o, z_o in ECI; NaN for parallel or non-finite r, v.",
      [](const vec& r_eci, const vec& v_eci) { return rows_of(dcm_eci_from_orbit(r_eci, v_eci)); },
      py::arg("r_eci"), py::arg("v_eci"));
}

}  // namespace
}  // namespace conescan::python

PYBIND11_MODULE(_conescan, m) {
  using namespace conescan::python;
  m.doc() =
      "The conescan core over NumPy arrays: angles in rad, results as named tuples of arrays "
      "with an integer status array (names in status_names). See the package conescan.";
  m.attr("__version__") = CONESCAN_VERSION;
  m.attr("status_names") = status_names();
  def_geometry(m);
  def_forward_models(m);
  def_processing(m);
  def_attitude(m);
#ifdef CONESCAN_PYTHON_SCENES
  def_scenes(m);  // conescan.simulate, conescan.summary (python/conescan/_scenes.py)
  def_fit(m);     // conescan.fit, conescan.predict (python/conescan/_fit.py)
#endif
}

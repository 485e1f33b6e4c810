// The detector's lag (include/conescan/sensor_physics/detector.hpp), the Gauss-Legendre pieces
// (gauss_panels.hpp) and the locators on sampled signals (sensor_physics/locator.hpp), MODEL §12:
//  - the first-order-hold update: its weights sum to 1, agree with the direct transcription,
//    keep their digits for h << tau, and are exact for a ramp (delayed by exactly tau);
//  - the exact-integration trap: for a piecewise-linear signal, halving the grid moves no
//    crossing by more than 1e-9 deg, because the crossing inside a cell is the root of the held
//    signal's output; linear interpolation of y there, or a zero-order hold, would move it;
//  - a step edge with lag: the level k is passed tau ln(1/(1-k)) late rising, tau ln(1/k)
//    falling;
//  - the exact lag of a polynomial equals the first-order hold for degree 1 and a dense
//    quadrature for degree 9; the regularised incomplete gamma functions against a series;
//  - the Gauss-Legendre rule against its tabulated 10-point nodes; a piece's value, integral and
//    derivatives exact for polynomials.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "conescan/gauss_panels.hpp"
#include "conescan/sensor_physics/detector.hpp"
#include "conescan/sensor_physics/locator.hpp"
#include "support/adl_scalar.hpp"
#include "support/approx.hpp"

#define CHECK_CLOSE(actual, expected, tolerance)                                     \
  CHECK_WITHIN(static_cast<long double>(actual), static_cast<long double>(expected), \
               static_cast<long double>(tolerance))

using conescan::lag_point;
using conescan::status;

TEMPLATE_TEST_CASE("the first-order hold's weights", "[physics]", float, double, long double,
                   conescan_test::adl_real) {
  using T = TestType;
  const T tolerance = T(64) * conescan_test::eps<T>();
  for (int e = -8; e <= 3; ++e) {
    const T r = conescan_test::scalar_from<T>(std::pow(10.0L, e));
    const auto w = conescan::lag_weights_of(r, T(1));
    // A constant signal stays constant.
    CHECK_CLOSE(w.decay + w.weight_start + w.weight_end, 1, tolerance);
    // phi2 against its series sum (-r)^k / (k+2)! in long double (40 terms; below r = 1 it
    // converges without cancellation), and its definition beyond.
    const long double rl = static_cast<long double>(r);
    long double phi2 = 0, term = 0.5L;
    for (int k = 0; k < 40; ++k, term *= -rl / (k + 2)) phi2 += term;
    if (rl > 1) phi2 = (std::exp(-rl) - 1 + rl) / (rl * rl);
    CHECK_CLOSE(conescan::lag_phi2(r), phi2, 4 * tolerance);
  }
  // The weights against the direct transcription of the update, where it does not cancel.
  const T y0 = T(3) / T(10), s0 = T(1) / T(5), s1 = T(9) / T(10);
  for (int i = 1; i <= 6; ++i) {
    const T h = T(i) / T(4);
    const auto w = conescan::lag_weights_of(h, T(1));
    CHECK_CLOSE(conescan::lag_step(w, y0, s0, s1), conescan::lag_step_direct(y0, s0, s1, h, T(1)),
                16 * tolerance);
  }
  // No lag: the output is the signal.
  const auto none = conescan::lag_weights_of(T(1), T(0));
  CHECK(conescan::lag_step(none, y0, s0, s1) == s1);
}

TEST_CASE("a ramp is delayed by exactly tau; a step reaches 1 - e^-1 after tau", "[physics]") {
  const double tau = 0.37, h = 0.05;
  std::vector<double> s(400), y(400);
  for (int k = 0; k < 400; ++k) s[k] = 2.0 * k * h;  // slope 2
  conescan::integrate_lag(s.data(), y.data(), 400, h, tau);
  // After the start's transient (e^-(t/tau)), y(t) = s(t - tau) exactly.
  for (int k = 300; k < 400; ++k) CHECK_CLOSE(y[k], 2.0 * (k * h - tau), 1e-12);
  std::vector<double> step(400, 1.0), out(400);
  step[0] = 0;
  conescan::integrate_lag(step.data(), out.data(), 400, h, tau);
  // The held signal ramps from 0 to 1 over the first cell; afterwards 1 - y decays as
  // e^{-t/tau} exactly, step by step.
  for (int k = 2; k < 40; ++k)
    CHECK_CLOSE((1 - out[k + 1]) / (1 - out[k]), std::exp(-h / tau), 1e-12);
}

namespace {

/// A trapezoidal pulse: 0, rising linearly over [1, 2], 1 until 5, falling over [5, 7], 0;
/// exactly piecewise linear on any grid whose step divides 1.
double trapezoid(double t) {
  if (t <= 1) return 0;
  if (t <= 2) return t - 1;
  if (t <= 5) return 1;
  if (t <= 7) return 1 - (t - 5) / 2;
  return 0;
}

struct sampled {
  std::vector<double> t, s, y;
  conescan::sampled_lag_signal<double> signal;
};

sampled sample(double step, double lag) {
  sampled r;
  const int n = static_cast<int>(std::lround(10 / step)) + 1;
  for (int k = 0; k < n; ++k) {
    r.t.push_back(k * step);
    r.s.push_back(trapezoid(k * step));
  }
  r.y.resize(n);
  conescan::integrate_lag(r.s.data(), r.y.data(), n, step, lag);
  r.signal = {r.s.data(), r.y.data(), n, 0.0, step, lag};
  return r;
}

}  // namespace

TEST_CASE("the exact-integration trap: halving the grid moves no crossing", "[physics]") {
  // A piecewise-linear signal is exactly what the first-order hold integrates: the output at
  // any t is then the same on every grid that holds the signal's corners, and so is the
  // crossing found inside a cell as the root of lag_within_step. Linear interpolation of y
  // between the nodes is what would move with the grid.
  for (double lag : {0.0, 0.1, 0.5, 2.0}) {
    const sampled coarse = sample(0.25, lag), fine = sample(0.125, lag),
                  finest = sample(1.0 / 64, lag);
    for (double k : {0.2, 0.5, 0.8}) {
      const double peak =
          conescan::sampled_peak(finest.signal, finest.t.data(), static_cast<int>(finest.t.size()));
      const double level = k * peak;
      auto crossings = [&](const sampled& g) {
        const int n = static_cast<int>(g.t.size());
        return std::make_pair(conescan::first_rising_crossing(g.signal, g.t.data(), n, level),
                              conescan::last_falling_crossing(g.signal, g.t.data(), n, level));
      };
      const auto a = crossings(coarse), b = crossings(fine), c = crossings(finest);
      INFO("lag " << lag << " k " << k);
      REQUIRE(a.first.ok());
      REQUIRE(a.second.ok());
      // 1e-9 deg of a scan turning once per 10 units of t: 2.8e-11 units.
      CHECK_CLOSE(a.first.value, b.first.value, 2.8e-11);
      CHECK_CLOSE(a.second.value, b.second.value, 2.8e-11);
      CHECK_CLOSE(a.first.value, c.first.value, 2.8e-11);
      CHECK_CLOSE(a.second.value, c.second.value, 2.8e-11);
      // The trap: y interpolated linearly between the coarse nodes misses by far more.
      if (lag > 0) {
        const int n = static_cast<int>(coarse.t.size());
        int cell = 0;
        while (cell + 1 < n && !(coarse.y[cell] < level && coarse.y[cell + 1] >= level)) ++cell;
        const double linear = coarse.t[cell] + 0.25 * (level - coarse.y[cell]) /
                                                   (coarse.y[cell + 1] - coarse.y[cell]);
        CHECK(std::abs(linear - a.first.value) > 1e-5);
      }
    }
  }
}

TEST_CASE("a zero-order hold delays a crossing by half a step; the first-order hold does not",
          "[physics]") {
  // The zero-order hold keeps s at s_k over a step, as if the signal arrived h/2 late.
  const double lag = 0.5, h = 0.25;
  const sampled exact = sample(h, lag);
  std::vector<double> y(exact.t.size());
  y[0] = 0;
  for (std::size_t k = 0; k + 1 < y.size(); ++k)
    y[k + 1] = exact.s[k] + (y[k] - exact.s[k]) * std::exp(-h / lag);
  const double level = 0.5;
  int cell = 0;
  while (!(y[cell] < level && y[cell + 1] >= level)) ++cell;
  // Inside the cell the zero-order hold's output relaxes towards s[cell].
  const double x = -lag * std::log((exact.s[cell] - level) / (exact.s[cell] - y[cell]));
  const double held = exact.t[cell] + x;
  const auto first = conescan::first_rising_crossing(exact.signal, exact.t.data(),
                                                     static_cast<int>(exact.t.size()), level);
  REQUIRE(first.ok());
  CHECK(held - first.value == Approx(h / 2).epsilon(0.05));
}

TEST_CASE("a step through the lag: the level is passed tau ln(1/(1-k)) and tau ln(1/k) late",
          "[physics]") {
  const double tau = 0.36, h = 1.0 / 128;
  std::vector<double> t, s;
  for (int k = 0; k <= 128 * 20; ++k) {
    t.push_back(k * h);
    s.push_back(k * h >= 2 && k * h < 12 ? 1.0 : 0.0);  // corners on the grid: exact
  }
  // The held signal rises over one cell: the edge sits half a cell late, [2 - h, 2] -> 2 - h/2.
  std::vector<double> y(t.size());
  conescan::integrate_lag(s.data(), y.data(), static_cast<int>(t.size()), h, tau);
  const conescan::sampled_lag_signal<double> signal{s.data(), y.data(), static_cast<int>(t.size()),
                                                    0.0,      h,        tau};
  for (double k : {0.1, 0.5, 0.9}) {
    const auto in =
        conescan::first_rising_crossing(signal, t.data(), static_cast<int>(t.size()), k);
    const auto out =
        conescan::last_falling_crossing(signal, t.data(), static_cast<int>(t.size()), k);
    REQUIRE(in.ok());
    REQUIRE(out.ok());
    // The held step is a ramp over [2 - h, 2]: its lag is the step's shifted by h/2 plus a
    // term of order h^2 / tau.
    CHECK_CLOSE(in.value - (2 - h / 2), tau * std::log(1 / (1 - k)), 2e-4);
    CHECK_CLOSE(out.value - (12 - h / 2), tau * std::log(1 / k), 2e-4);
  }
  // Never reached: a miss.
  CHECK(conescan::first_rising_crossing(signal, t.data(), static_cast<int>(t.size()), 1.5).state ==
        status::miss);
  CHECK(conescan::last_falling_crossing(signal, t.data(), static_cast<int>(t.size()), 1.5).state ==
        status::miss);
  CHECK(conescan::first_rising_crossing(signal, t.data(), static_cast<int>(t.size()), std::nan(""))
            .state == status::invalid);
}

TEMPLATE_TEST_CASE("the regularised incomplete gamma functions", "[physics]", float, double,
                   long double) {
  using T = TestType;
  for (long double v : {1e-30L, 1e-6L, 0.3L, 1.0L, 5.0L, 9.5L, 10.0L, 30.0L, 800.0L}) {
    T p[12];
    conescan::regularised_lower_gamma(T(v), 12, p);
    for (int a = 1; a <= 12; ++a) {
      // P(a, v) = 1 - e^-v sum_{i<a} v^i / i!, or its series for small v, in long double.
      long double expected;
      if (v < a) {
        long double term = std::exp(-v), series = 0, ratio = 1;
        for (int i = 1; i <= a; ++i) term *= v / i;
        for (int j = 0; j < 200; ++j) {
          series += ratio;
          ratio *= v / (a + 1 + j);
        }
        expected = term * series;
      } else {
        long double q = 0, term = std::exp(-v);
        for (int i = 0; i < a; ++i) {
          q += term;
          term *= v / (i + 1);
        }
        expected = 1 - q;
      }
      INFO("a " << a << " v " << v);
      CHECK_CLOSE(
          p[a - 1], expected,
          64 * std::numeric_limits<T>::epsilon() * expected + std::numeric_limits<T>::min());
    }
  }
}

TEST_CASE("the lag of a polynomial: the first-order hold for a line, quadrature for degree 9",
          "[physics]") {
  // Degree 1 is the first-order hold.
  const double y0 = 0.2, s0 = 0.1, s1 = 0.7, h = 0.3, lag = 0.45;
  const double d[2] = {s1, (s1 - s0) / h};  // p and p' at the step's end
  CHECK_CLOSE(std::exp(-h / lag) * y0 + conescan::lag_of_polynomial(d, 2, h, lag),
              conescan::lag_step(conescan::lag_weights_of(h, lag), y0, s0, s1), 1e-15);
  // Degree 9 against a composite Gauss quadrature of int_0^span p(chi - u) e^{-u/lag} du/lag.
  const auto rule = conescan::gauss_legendre_rule_of<long double, 10>();
  auto p = [](long double x) {
    long double v = 0;
    for (int k = 9; k >= 0; --k) v = v * x + (k % 3 == 0 ? 1.0L / (k + 1) : -0.5L / (k + 2));
    return v;
  };
  for (long double span : {1e-4L, 0.1L, 1.0L, 7.0L})
    for (long double lagl : {0.01L, 0.5L, 3.0L}) {
      const long double chi = 0.9L;
      long double derivatives[10];
      // Derivatives of p at chi by its coefficients.
      for (int m = 0; m < 10; ++m) {
        long double v = 0;
        for (int k = 9; k >= m; --k) {
          long double c = k % 3 == 0 ? 1.0L / (k + 1) : -0.5L / (k + 2);
          for (int i = 0; i < m; ++i) c *= (k - i);
          v = v * chi + c;
        }
        // v here is sum c_k k!/(k-m)! chi^(k-m), built by Horner in chi.
        derivatives[m] = v;
      }
      const long double exact = conescan::lag_of_polynomial(derivatives, 10, span, lagl);
      long double sum = 0;
      const int panels = 400;
      for (int i = 0; i < panels; ++i) {
        const long double a = span * i / panels, w = span / panels;
        for (int q = 0; q < 10; ++q) {
          const long double u = a + (rule.nodes[q] + 1) * w / 2;
          sum += rule.weights[q] * w / 2 * p(chi - u) * std::exp(-u / lagl) / lagl;
        }
      }
      INFO("span " << span << " lag " << lagl);
      CHECK_CLOSE(exact, sum, 1e-15L * (std::abs(sum) > 1 ? std::abs(sum) : 1));
    }
}

TEMPLATE_TEST_CASE("the Gauss-Legendre pieces", "[physics]", float, double, long double,
                   conescan_test::adl_real) {
  using T = TestType;
  const auto rule = conescan::gauss_legendre_rule_of<T, 10>();
  // Abramowitz and Stegun Table 25.4, n = 10.
  const long double x[5] = {0.148874338981631L, 0.433395394129247L, 0.679409568299024L,
                            0.865063366688985L, 0.973906528517172L};
  const long double w[5] = {0.295524224714753L, 0.269266719309996L, 0.219086362515982L,
                            0.149451349150581L, 0.066671344308688L};
  for (int i = 0; i < 5; ++i) {
    CHECK_CLOSE(rule.nodes[5 + i], x[i],
                1e-15L + 8 * static_cast<long double>(conescan_test::eps<T>()));
    CHECK_CLOSE(rule.nodes[4 - i], -x[i],
                1e-15L + 8 * static_cast<long double>(conescan_test::eps<T>()));
    CHECK_CLOSE(rule.weights[5 + i], w[i],
                1e-15L + 8 * static_cast<long double>(conescan_test::eps<T>()));
  }
  // A cubic on the piece [2, 2.5]: value, integral and derivatives exact.
  auto f = [](const T& t) { return T(T(1) - T(3) * t + t * t * t / T(2)); };
  T values[10];
  const T start = T(2), width = T(1) / T(2);
  for (int i = 0; i < 10; ++i) values[i] = f(T(start + (rule.nodes[i] + T(1)) * width / T(2)));
  const auto piece = conescan::legendre_panel_of(rule, start, width, values);
  const T at = T(9) / T(4);
  const long double tol = 200 * static_cast<long double>(conescan_test::eps<T>());
  CHECK_CLOSE(conescan::panel_value(piece, at), f(at), tol);
  // int_2^2.25 (1 - 3t + t^3/2) dt.
  auto primitive = [](long double t) { return t - 1.5L * t * t + t * t * t * t / 8; };
  CHECK_CLOSE(conescan::panel_integral(piece, at), primitive(2.25L) - primitive(2.0L), tol);
  T derivatives[10];
  conescan::panel_derivatives(piece, at, derivatives);
  CHECK_CLOSE(derivatives[1], -3 + 1.5L * 2.25L * 2.25L, 40 * tol);
  CHECK_CLOSE(derivatives[2], 3 * 2.25L, 4000 * tol);
  CHECK_CLOSE(derivatives[3], 3, 4e5L * tol);
  // The first few alone (what the chain's slopes read) are the whole table's to the bit.
  for (int count = 1; count <= 10; ++count) {
    T first[10];
    conescan::panel_derivatives(piece, at, first, count);
    for (int k = 0; k < count; ++k) CHECK(first[k] == derivatives[k]);
  }
  T value, slope;
  conescan::panel_value_slope(piece, at, value, slope);
  CHECK_CLOSE(slope, -3 + 1.5L * 2.25L * 2.25L, 40 * tol);
}

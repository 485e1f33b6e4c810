// Sensor physics (MODEL §12): the crossings that a head's radiance, field of view, detector lag
// and locator produce, in place of the geometric crossings of MODEL §5. The chain, per head and
// row, as named steps:
//   1. heights    the tangent height of the line of sight along the scan sensor_physics/height.hpp
//   2. radiance   the limb profile and the disk, the season factor sensor_physics/profile.hpp
//   3. field      the mean radiance over the rigid patch about the line   sensor_physics/field.hpp,
//                 of sight at each scan azimuth, by level sets             field_mean.hpp,
//                 modelled in the azimuth along a window                   field_sweep.hpp
//   4. detector   the first-order lag, exact for every piece sensor_physics/detector.hpp
//   5. locator    normalised, fixed or slope; rising in, falling out sensor_physics/locator.hpp
// The result is a crossings<T> that goes to MODEL §6's processing unchanged.
//
// How (docs/SENSOR_PHYSICS.md, "The model as implemented"):
//  - The signal differs from zero (space) or from its plateau (the disk) only near each
//    geometric crossing, where the heights the field sees lie in the profile's band or meet the
//    surface. Each crossing gets a window in scan azimuth there; two windows closer than the
//    lag's memory merge into one. Outside the windows the signal is constant, and every quantity
//    continues in closed form.
//  - In a window the field's mean s(phi) is laid on a lattice of pieces (each a Legendre
//    polynomial on 10 Gauss nodes, a piece spanning H of height, or the field's smoothing
//    where wider), cut where s is not smooth (a corner of the patch
//    passing the surface, the knee, delta50 of a step) and graded towards those places; a piece
//    where the whole patch lies in one constant part of the radiance is that constant. A pencil has
//    one line of sight and no mean: its pieces break exactly where it meets the surface (and
//    delta50 of a step), and without lag its output is its radiance, evaluated on exact heights.
//  - The lag of each piece is exact (lag_of_polynomial), carried from piece to piece.
//  - The locator brackets the crossing on samples of y and solves y = level by bracketed Newton
//    with y' = (s - y) / Lambda; the normalised locator's peak is the pulse's true maximum of y
//    (the disk's plateau, settled or not, or a maximum inside a window).
// Measured against the brute-force reference (tests/support/sensor_physics_reference.hpp,
// docs/SENSOR_PHYSICS.md): 8e-11 deg on a 1.5 deg square with 1 ms of lag at 1 rev/s, 5e-11 deg
// for a pencil with lag; a row with a field costs milliseconds to tens of them (some 700 field
// means, most from field_sweep.hpp's models of G).
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include "conescan/crossings.hpp"
#include "conescan/gauss_panels.hpp"
#include "conescan/scan_model.hpp"
#include "conescan/sensor_physics/detector.hpp"
#include "conescan/sensor_physics/field.hpp"
#include "conescan/sensor_physics/field_mean.hpp"
#include "conescan/sensor_physics/field_sweep.hpp"
#include "conescan/sensor_physics/height.hpp"
#include "conescan/sensor_physics/locator.hpp"
#include "conescan/sensor_physics/profile.hpp"
#include "conescan/small_sort.hpp"

namespace conescan {

/// The physics of one head (MODEL §12). SI and radians; the CLI's km and degrees are the
/// scene's to convert.
template <class T>
struct sensor_physics_settings {
  field_of_view<T> field{T(0), field_shape::square};  ///< fov_rad >= 0 (0: pencil beam)
  T spin_hz{0};  ///< scan rate, revolutions per second (> 0 when tau_s > 0)
  T tau_s{0};    ///< detector time constant (s); 0: no lag
  horizon_locator<T> locator{locator_kind::normalised, T(1) / T(2)};
  T scale_m{7000};        ///< H (m), >= 0 (0: step edge)
  T offset_m{0};          ///< delta50 (m)
  T disk{1};              ///< L_disk / L0, >= 0
  T season_amplitude{0};  ///< A, |A| < 1
  T plateau{1};           ///< the radiance scale L0 without the season term (1 in MODEL §12)
};

/// The detector's lag as scan azimuth, Lambda = 2 pi spin tau (rad; MODEL §12): the one place
/// the settings' spin and time constant become the lag the chain convolves with.
template <class T>
T lag_rad_of(const T& spin_hz, const T& tau_s) noexcept {
  return T(T(2) * pi<T>() * spin_hz * tau_s);
}

/// The shortest lag the slope locator resolves, as scan azimuth Lambda = 2 pi spin tau (rad): its
/// extremum is the root of y'' = (s' - y') / Lambda, whose rounding grows as 1 / Lambda. Measured
/// on fields over bright disks (seed 70 of a scan of the options' ranges): at Lambda = 6e-9 to
/// 2e-8 rad the crossings were 3e-3 to 0.023 deg off the limit tau -> 0 under ok, at 7e-8 1e-5
/// deg; from 1.8e-7 on they followed it. The level locators read y, not y'', and have no such
/// floor.
template <class T>
T shortest_slope_lag_rad() noexcept {
  return T(1) / T(1000000);
}

/// The faintest pulse the chain resolves, as a fraction of the plateau L0 (MODEL §12: a fainter
/// one is `miss`). The chain's tolerances are fractions of the plateau (the pieces' tails 1e-9,
/// the field's models 1e-12 to 1e-13), and a pulse's crossings carry them divided by its own
/// brightness: over a dark disk, a limb whose 50 % point lies below the surface, a 0.23 deg
/// square with 1.9 ms of lag and the slope locator was 5.6e-7 deg off the reference where the
/// pulse peaked at 5e-6 L0 (its brightest, l(0), 6.3e-5) and 0.12 deg at 2.4e-8 (l(0) 3.1e-7);
/// 5.8e-9 deg at 2.7e-4 (l(0) 3.4e-3). No real limb is that faint.
template <class T>
T faintest_pulse() noexcept {
  return T(1) / T(1000);
}

/// The lowest level a level locator looks for, as a fraction of the plateau L0: a fixed
/// threshold T below it, or a normalised k below it over the faintest pulse (k < 1e-5), is
/// invalid. The chain's tolerances are fractions of L0, and a crossing carries them divided by
/// its level: with the profile's cut raised for low levels (tail_cut_of), a 1 deg square with 1
/// ms of lag at 1 rev/s on H = 500 m was 9.1e-8 deg from the reference at T = 1e-8 L0, 1e-6 deg
/// at 1e-9 and 1.5e-5 deg at 1e-10; pencils and H = 7 km within 5.7e-7 deg down to 1e-10. No
/// real sensor's threshold is near it.
template <class T>
T lowest_level() noexcept {
  return T(1) / T(100000000);
}

/// The lowest normalised threshold k: lowest_level over the faintest pulse (1e-5).
template <class T>
T lowest_normalised_threshold() noexcept {
  return T(lowest_level<T>() / faintest_pulse<T>());
}

/// invalid for a setting outside the model's domain: a non-finite number, fov < 0, fov >= pi/2,
/// fov between 0 and the narrowest field (narrowest_field_deg), the slope locator with a lag
/// between 0 and shortest_slope_lag_rad,
/// spin < 0, tau < 0, tau > 0 without spin, a normalised threshold k outside [1e-5, 1) or a
/// fixed threshold T below 1e-8 of the plateau (lowest_level), H < 0 or subnormal (1 / H
/// overflows), disk < 0, |A| >= 1, plateau <= 0. ok otherwise.
template <class T>
status sensor_physics_settings_status(const sensor_physics_settings<T>& s) noexcept {
  using std::abs;
  const T values[] = {s.field.fov_rad, s.spin_hz,  s.tau_s, s.locator.threshold,
                      s.scale_m,       s.offset_m, s.disk,  s.season_amplitude,
                      s.plateau};
  for (const T& v : values)
    if (!is_finite(v)) return status::invalid;
  if (!(s.field.fov_rad >= T(0)) || !(s.field.fov_rad < pi<T>() / T(2))) return status::invalid;
  if (s.field.fov_rad > T(0) && s.field.fov_rad < deg_to_rad(narrowest_field_deg<T>()))
    return status::invalid;
  if (s.field.shape != field_shape::square && s.field.shape != field_shape::circle)
    return status::invalid;
  if (!(s.spin_hz >= T(0)) || !(s.tau_s >= T(0))) return status::invalid;
  if (s.tau_s > T(0) && !(s.spin_hz > T(0))) return status::invalid;
  switch (s.locator.kind) {
    case locator_kind::normalised:
      if (!(s.locator.threshold >= lowest_normalised_threshold<T>()) ||
          !(s.locator.threshold < T(1)))
        return status::invalid;
      break;
    case locator_kind::fixed:
      if (!(s.locator.threshold >= T(lowest_level<T>() * s.plateau))) return status::invalid;
      break;
    case locator_kind::slope:
      if (s.tau_s > T(0) && lag_rad_of(s.spin_hz, s.tau_s) < shortest_slope_lag_rad<T>())
        return status::invalid;
      break;
    default:
      return status::invalid;
  }
  if (!(s.scale_m >= T(0)) || !(s.disk >= T(0)) || !(abs(s.season_amplitude) < T(1)) ||
      !(s.plateau > T(0)))
    return status::invalid;
  if (s.scale_m > T(0) && !is_finite(T(T(1) / s.scale_m))) return status::invalid;
  return status::ok;
}

namespace physics_detail {

inline constexpr int nodes = 10;                    ///< Gauss nodes per piece
inline constexpr int max_geometry_panels = 64;      ///< geometry panels per window
inline constexpr int max_geometry_subpanels = 128;  ///< sub-panels of unresolved panels
inline constexpr int max_pieces = 640;              ///< pieces per window
inline constexpr int max_edges = 4;                 ///< jumps per window
inline constexpr int jump_terms = 4;                ///< derivatives of s a jump is carried by
inline constexpr int max_widths = 16;               ///< cached lag matrices
inline constexpr int max_samples = 40;              ///< locator samples per window

/// P_m^(k)(x) for k, m < nodes: table[k][m] (legendre_derivative_column, gauss_panels.hpp).
template <class T>
void legendre_derivative_table(const T& x,
                               std::array<std::array<T, nodes>, nodes>& table) noexcept {
  std::array<T, nodes> previous{}, column{};
  for (int k = 0; k < nodes; ++k) {
    legendre_derivative_column(x, k, previous, column);
    table[k] = column;  // its entries m < k are 0
    previous = column;
  }
}

}  // namespace physics_detail

/// The chain's resolution (docs/SENSOR_PHYSICS.md gives the error each default leaves).
template <class T>
struct sensor_physics_accuracy {
  T piece_scales{1};         ///< a field's piece spans this many H of height along the scan (or
                             ///< of its smoothing scale, an eighth of its heights' span, if larger;
                             ///< 2 leaves 1e-8 deg, noise the table's series cannot fit through)
  T slope_piece_scales{1};   ///< the same for the slope locator, which needs y'' (twice finer)
  T pencil_piece_scales{1};  ///< and for a pencil, whose output no field smooths
  T tail_cut{16};            ///< the profile is 0 above delta50 + tail_cut H (l < 7.8e-8 l(0))
  int samples{8};            ///< the locator's samples per window
};

/// One head's physics, prepared once: the settings, the profile, the lag Lambda = 2 pi spin tau
/// (rad of scan azimuth), the piece rule and its derivative tables.
template <class T>
struct sensor_physics_head {
  sensor_physics_settings<T> settings;
  sensor_physics_accuracy<T> accuracy;
  radiance_profile<T> profile;
  T lag_rad;
  gauss_legendre_rule<T, physics_detail::nodes> rule;
  field_rules<T> field;  ///< the field mean's quadrature rules (field_mean.hpp)
  /// P_m^(k) at the rule's nodes (0 .. nodes-1) and at 1 (index nodes): [point][k][m].
  std::array<std::array<std::array<T, physics_detail::nodes>, physics_detail::nodes>,
             physics_detail::nodes + 1>
      derivatives;
  status state;  ///< ok, or invalid (sensor_physics_settings_status)
};

/// A built head given new settings, its rules kept (they do not depend on the settings): the
/// head sensor_physics_head_build makes with these settings and the head's accuracy, without
/// rebuilding its tables (44 us in double; a calibration changes the lag and the limb at every
/// evaluation, src/scene_calibration/scene_model.hpp).
template <class T>
void sensor_physics_head_set(sensor_physics_head<T>& h,
                             const sensor_physics_settings<T>& s) noexcept {
  h.settings = s;
  h.state = sensor_physics_settings_status(s);
  h.profile = radiance_profile_of(s.scale_m, s.offset_m, s.disk);
  if (h.profile.state != status::ok) h.state = status::invalid;
  h.lag_rad = lag_rad_of(s.spin_hz, s.tau_s);
}

/// Builds a head in place (a flight computer keeps it in static storage: the head holds its
/// rules' tables, ~25 KB in double, 13 KB in float, too large for a small stack).
template <class T>
void sensor_physics_head_build(
    sensor_physics_head<T>& h, const sensor_physics_settings<T>& s,
    const sensor_physics_accuracy<T>& accuracy = sensor_physics_accuracy<T>{}) noexcept {
  h.accuracy = accuracy;
  sensor_physics_head_set(h, s);
  h.rule = gauss_legendre_rule_of<T, physics_detail::nodes>();
  field_rules_build(h.field);
  for (int i = 0; i < physics_detail::nodes; ++i)
    physics_detail::legendre_derivative_table(h.rule.nodes[i], h.derivatives[i]);
  physics_detail::legendre_derivative_table(T(1), h.derivatives[physics_detail::nodes]);
}

/// The head by value, for a host (sensor_physics_head_build in place on a small target).
template <class T>
sensor_physics_head<T> sensor_physics_head_of(
    const sensor_physics_settings<T>& s,
    const sensor_physics_accuracy<T>& accuracy = sensor_physics_accuracy<T>{}) noexcept {
  sensor_physics_head<T> h{};
  sensor_physics_head_build(h, s, accuracy);
  return h;
}

namespace physics_detail {

template <class T>
using piece_panel = legendre_panel<T, nodes>;

/// Heights and latitudes of the central line of sight along the scan over a window: panels in
/// phi (at most 0.2 rad wide: the heights, smooth on the scale of a radian, interpolate to below
/// 1e-7 m on 10 nodes, measured in tests/core/test_sensor_physics_heights.cpp), a Legendre
/// polynomial per panel; a panel the uniform panels leave unresolved (build_geometry) is cut in
/// 2^level equal sub-panels of its own, held in a pool.
template <class T>
struct geometry_grid {
  T start, width;
  int panels;
  bool latitudes;
  piece_panel<T> height[max_geometry_panels];
  piece_panel<T> latitude[max_geometry_panels];
  T lowest[max_geometry_panels];   ///< the least height at a panel's nodes (m)
  int level[max_geometry_panels];  ///< 0: the panel itself; else 2^level sub-panels
  int first[max_geometry_panels];  ///< a cut panel's first sub-panel in the pool
  int pool_used;
  piece_panel<T> pool_height[max_geometry_subpanels];
  piece_panel<T> pool_latitude[max_geometry_subpanels];

  int panel_of(const T& phi) const noexcept {
    using std::floor;
    const T position = (phi - start) / width;
    int g = position < T(0) ? 0 : static_cast<int>(long_double_value(floor(position)));
    return g > panels - 1 ? panels - 1 : g;
  }
  /// The sub-panel of a cut panel p that holds phi (its index in the pool).
  int subpanel_of(int p, const T& phi) const noexcept {
    using std::floor;
    const int n = 1 << level[p];
    const T position = (phi - (start + T(p) * width)) / width * T(n);
    int k = position < T(0) ? 0 : static_cast<int>(long_double_value(floor(position)));
    return first[p] + (k > n - 1 ? n - 1 : k);
  }
  const piece_panel<T>& height_panel(const T& phi) const noexcept {
    const int p = panel_of(phi);
    return level[p] == 0 ? height[p] : pool_height[subpanel_of(p, phi)];
  }
  const piece_panel<T>& latitude_panel(const T& phi) const noexcept {
    const int p = panel_of(phi);
    return level[p] == 0 ? latitude[p] : pool_latitude[subpanel_of(p, phi)];
  }
  T height_at(const T& phi) const noexcept { return panel_value(height_panel(phi), phi); }
  void height_slope(const T& phi, T& value, T& slope) const noexcept {
    panel_value_slope(height_panel(phi), phi, value, slope);
  }
  T sin_latitude_at(const T& phi) const noexcept { return panel_value(latitude_panel(phi), phi); }
};

template <class T>
inline T geometry_panel_width() noexcept {
  return T(1) / T(5);
}

/// A Legendre panel's tail, |c_8| + |c_9|: its last two coefficients, the measure of how well
/// the panel resolves what it holds (the geometry's and the plateau's panels are halved until it
/// is small).
template <class T>
T legendre_tail(const piece_panel<T>& panel) noexcept {
  using std::abs;
  return T(abs(panel.coefficients[nodes - 1]) + abs(panel.coefficients[nodes - 2]));
}

/// Whether a panel resolves the heights and (with the season term) the latitudes where the
/// radiance is not 0 (reaching below `top_m`): its Legendre tails, |c_8| + |c_9| (about ten times
/// the interpolation's error), at most 1e-3 m for the heights and 1e-8 for the latitudes' sines
/// (4e-10 of L0), or a hundred times their rounding where that is larger (float: heights of 1e7 m
/// to 1 m, their tails never below it). A panel all above `top_m` is not read: those past the
/// satellite's horizontal have a kink there (tails to 3e-4 on a low orbit).
template <class T>
bool panel_resolved(const piece_panel<T>& height, const piece_panel<T>& latitude, const T& lowest,
                    bool latitudes, const T& top_m) noexcept {
  if (!(lowest < top_m)) return true;
  const T epsilon = std::numeric_limits<T>::epsilon();
  const T height_rounding = T(1000000000) * epsilon, latitude_rounding = T(100) * epsilon;
  const T height_tolerance = height_rounding > T(1) / T(1000) ? height_rounding : T(T(1) / T(1000));
  const T latitude_tolerance =
      latitude_rounding > T(1) / T(100000000) ? latitude_rounding : T(T(1) / T(100000000));
  if (legendre_tail(height) > height_tolerance) return false;
  return !latitudes || !(legendre_tail(latitude) > latitude_tolerance);
}

/// Whether uniform panel p resolves its heights and latitudes (panel_resolved).
template <class T>
bool geometry_panel_resolved(const geometry_grid<T>& g, int p, const T& top_m) noexcept {
  return panel_resolved(g.height[p], g.latitude[p], g.lowest[p], g.latitudes, top_m);
}

/// The heights and latitudes at the nodes of the panel [panel_start, + width], as Legendre
/// panels, and their least height: store(height, latitude, lowest).
template <class T, class Surface, class Store>
void geometry_panel_of(const sensor_physics_head<T>& head, const scan_circle<T>& circle,
                       const Surface& surface, const T& panel_start, const T& width, bool latitudes,
                       const Store& store) noexcept {
  const surface_probe<T> probe = probe_of(surface);
  T heights[nodes], lats[nodes], lowest = T(0);
  for (int i = 0; i < nodes; ++i) {
    const T phi = panel_start + (head.rule.nodes[i] + T(1)) * width / T(2);
    const tangent_height<T> t = exact_height(circle, surface, probe, phi, latitudes);
    heights[i] = t.height_m;
    lats[i] = t.sin_latitude;
    if (i == 0 || t.height_m < lowest) lowest = t.height_m;
  }
  store(legendre_panel_of(head.rule, panel_start, width, heights),
        latitudes ? legendre_panel_of(head.rule, panel_start, width, lats) : piece_panel<T>{},
        lowest);
}

/// build_geometry's panels: `panels` of equal width over [start, start + span], none cut.
template <class T, class Surface>
void build_geometry_panels(geometry_grid<T>& g, const sensor_physics_head<T>& head,
                           const scan_circle<T>& circle, const Surface& surface, const T& start,
                           const T& span, int panels, bool latitudes) noexcept {
  g.start = start;
  g.width = span / T(panels);
  g.panels = panels;
  g.latitudes = latitudes;
  g.pool_used = 0;
  for (int p = 0; p < panels; ++p) {
    g.level[p] = 0;
    geometry_panel_of(head, circle, surface, T(start + T(p) * g.width), g.width, latitudes,
                      [&](const piece_panel<T>& h, const piece_panel<T>& l, const T& low) {
                        g.height[p] = h;
                        g.latitude[p] = l;
                        g.lowest[p] = low;
                      });
  }
}

/// Cuts uniform panel p in 2, 4, 8, ... sub-panels in the pool until each resolves its heights
/// and latitudes (panel_resolved); false where the pool runs out first (the finest cut that
/// fitted is kept: a kink, where the line of sight reaches the satellite's horizontal below the
/// radiance's top at perigee, never resolves, and its cuts serve no worse than the panel did).
template <class T, class Surface>
bool cut_geometry_panel(geometry_grid<T>& g, int p, const sensor_physics_head<T>& head,
                        const scan_circle<T>& circle, const Surface& surface,
                        const T& top_m) noexcept {
  const int base = g.pool_used;
  for (int level = 1; base + (1 << level) <= max_geometry_subpanels; ++level) {
    const int n = 1 << level;
    const T width = g.width / T(n);
    bool resolved = true;
    for (int k = 0; k < n; ++k)
      geometry_panel_of(head, circle, surface, T(g.start + T(p) * g.width + T(k) * width), width,
                        g.latitudes,
                        [&](const piece_panel<T>& h, const piece_panel<T>& l, const T& low) {
                          g.pool_height[base + k] = h;
                          g.pool_latitude[base + k] = l;
                          resolved = resolved && panel_resolved(h, l, low, g.latitudes, top_m);
                        });
    g.level[p] = level;
    g.first[p] = base;
    g.pool_used = base + n;
    if (resolved) return true;
  }
  return false;
}

/// The grid's panels over [start, end], the heights and latitudes at their nodes
/// (build_geometry_panels), halved until they resolve both where the radiance is not 0
/// (panel_resolved: a low orbit's tails there are 5e-5 to 2e-4 m and 1e-13 to 6e-11: nothing
/// changes on one, but for the rows whose windows reach the satellite's horizontal, 174 km up
/// at the paper's perigee) or the workspace's panels run out; a panel still unresolved then is
/// cut on its own (cut_geometry_panel). A scan that passes close to the Earth's centre, as any
/// scan across the disk from far away (the geostationary orbit: within its 8.7 deg angular
/// radius), turns its line of sight's closest point about the centre fast: its height and the
/// tangent point's latitude vary on the scale of the line's least nadir angle (0.04 rad at
/// 39 000 km), which 0.2 rad panels missed (found by a random scan to 42 000 km): the latitude
/// on the disk by 5e-5 of L0, the heights at the limb by tens of metres (tails to 1.7 km),
/// crossings 4e-6 to 1.2e-4 deg off the reference; and 64 panels over a window with a long lag's
/// history, 0.023 rad each, left the latitude within a few hundredths of a radian of the nadir
/// 1e-4 off (tails to 9e-5; 37 000 km out, the disk's output 3e-3 of L0 off).
template <class T, class Surface>
bool build_geometry(geometry_grid<T>& g, const sensor_physics_head<T>& head,
                    const scan_circle<T>& circle, const Surface& surface, const T& start,
                    const T& end, bool latitudes, const T& top_m, bool& cache_outgrown) noexcept {
  using std::ceil;
  const T span = end - start;
  const T count = ceil(span / geometry_panel_width<T>());
  int panels = count < T(1) ? 1 : static_cast<int>(long_double_value(count));
  if (panels > max_geometry_panels || !(span > T(0))) {
    cache_outgrown = panels > max_geometry_panels;
    return false;
  }
  auto resolved = [&] {
    for (int p = 0; p < g.panels; ++p)
      if (!geometry_panel_resolved(g, p, top_m)) return false;
    return true;
  };
  build_geometry_panels(g, head, circle, surface, start, span, panels, latitudes);
  while (!resolved() && 2 * panels <= max_geometry_panels) {
    panels *= 2;
    build_geometry_panels(g, head, circle, surface, start, span, panels, latitudes);
  }
  for (int p = 0; p < g.panels; ++p)
    if (!geometry_panel_resolved(g, p, top_m))
      cut_geometry_panel(g, p, head, circle, surface, top_m);
  return true;
}

/// A root of height(phi) = level inside [lo, hi] (the heights on either side), by bracketed
/// Newton on the geometry's polynomials.
template <class T>
T height_root(const geometry_grid<T>& g, const T& level, const T& lo, const T& hi) noexcept {
  auto f = [&](const T& phi) {
    T v, d;
    g.height_slope(phi, v, d);
    return value_slope<T>{T(v - level), d};
  };
  return bracketed_newton(f, lo, hi, T((lo + hi) / T(2))).x;
}

/// The lag of each Legendre polynomial P_m of a piece of width w, from 0 at the piece's start,
/// at the rule's nodes and at the piece's end (rows 0 .. nodes-1, nodes), and the decay of a
/// start value there: z(x) = decay z(start) + sum_m row[m] c_m (lag_of_polynomial on each P_m).
/// On a piece wider than 2 Lambda (`transient`) the lag is carried as its steady part and a
/// transient instead: y = q + (y(start) - q(start)) e^{-(x - start) / Lambda}, q = sum_k
/// (-Lambda)^k p^(k) (Lambda q' + q = p, a polynomial: the sum ends), q's values from the rows
/// `steady` (at the nodes) and `steady_start`; a polynomial through y's values at the nodes
/// cannot follow a transient much narrower than the piece (a kink of s' at a piece's start, 17
/// Lambda wide: y 5e-8 off, y' = (s - y) / Lambda 5e-4 off, and the slope locator's extremum
/// 0.037 deg). At most 2 Lambda wide the transient is smooth across the piece and q's terms
/// (2 Lambda / w)^k would grow: the values at the nodes serve.
template <class T>
struct lag_matrix {
  T width;
  T row[nodes + 1][nodes];
  T decay[nodes + 1];
  bool transient;
  T steady[nodes][nodes];
  T steady_start[nodes];
};

template <class T>
void lag_matrix_of(lag_matrix<T>& m, const sensor_physics_head<T>& head, const T& width) noexcept {
  using std::exp;
  m.width = width;
  const T lag = head.lag_rad;
  for (int point = 0; point <= nodes; ++point) {
    const T xi = point < nodes ? head.rule.nodes[point] : T(1);
    const T v = (xi + T(1)) * width / T(2) / lag;
    T gammas[nodes];
    regularised_lower_gamma(v, nodes, gammas);
    T g[nodes];
    const T ratio = T(-2) * lag / width;
    T power = T(1);
    for (int k = 0; k < nodes; ++k) {
      g[k] = power * gammas[k];
      power = power * ratio;
    }
    for (int mm = 0; mm < nodes; ++mm) {
      T sum = T(0);
      for (int k = 0; k <= mm; ++k) sum += g[k] * head.derivatives[point][k][mm];
      m.row[point][mm] = sum;
    }
    m.decay[point] = exp(-v);
  }
  // The steady part's rows: the same sums with every P(k + 1, V) = 1 (V -> infinity); at the
  // start, P_m^(k)(-1) = (-1)^(m + k) P_m^(k)(1).
  m.transient = width > T(2) * lag;
  if (!m.transient) return;
  const T ratio = T(-2) * lag / width;
  for (int point = 0; point <= nodes; ++point)
    for (int mm = 0; mm < nodes; ++mm) {
      T sum = T(0), power = T(1);
      for (int k = 0; k <= mm; ++k, power = power * ratio) {
        const T d = head.derivatives[point][k][mm];
        sum += power * (point < nodes ? d : (mm + k) % 2 == 0 ? d : T(-d));
      }
      if (point < nodes)
        m.steady[point][mm] = sum;
      else
        m.steady_start[mm] = sum;
    }
}

/// A piece of a line's signal: a constant, or a polynomial; the integral and the lag at its start.
template <class T>
struct line_piece {
  T start, width;
  bool constant;
  T value;
  piece_panel<T> signal, lagged;  ///< lagged: y, or its steady part q (lag_matrix::transient)
  T integral_start, lag_start;
  T transient;  ///< y(start) - q(start) on a piece wider than 2 Lambda, else 0
};

/// A line's signal over a window: its pieces, constant before and after, its jumps.
template <class T>
struct line_signal {
  int count;
  int capacity;  ///< the pieces this build may use (at most max_pieces)
  line_piece<T> piece[max_pieces];
  T start, end;
  T value_before, value_after;
  T integral_end, lag_end;
  int edges;
  T edge[max_edges];
  T jump[max_edges][jump_terms];  ///< s^(k)(edge+) - s^(k)(edge-)
  bool jumps;                     ///< any jump term not 0
};

/// The line's piece that holds chi (the last that starts at or before it; chi inside the line).
template <class T>
const line_piece<T>& piece_at(const line_signal<T>& line, const T& chi) noexcept {
  int lo = 0, hi = line.count - 1;  // binary search on the pieces' starts
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    if (line.piece[mid].start <= chi)
      lo = mid;
    else
      hi = mid - 1;
  }
  return line.piece[lo];
}

/// The line's signal, its integral from the line's start, and its lag, at chi.
template <class T>
struct line_values {
  T value, integral, lagged;
};

template <class T>
line_values<T> evaluate_line(const line_signal<T>& line, const T& lag, const T& chi) noexcept {
  using std::exp;
  if (!(chi > line.start)) {
    return {line.value_before, T(line.value_before * (chi - line.start)), line.value_before};
  }
  if (!(chi < line.end)) {
    const T after = line.value_after;
    const T lagged =
        lag > T(0) ? T(after + (line.lag_end - after) * exp(-(chi - line.end) / lag)) : after;
    return {after, T(line.integral_end + after * (chi - line.end)), lagged};
  }
  const line_piece<T>& p = piece_at(line, chi);
  if (p.constant) {
    const T lagged =
        lag > T(0) ? T(p.value + (p.lag_start - p.value) * exp(-(chi - p.start) / lag)) : p.value;
    return {p.value, T(p.integral_start + p.value * (chi - p.start)), lagged};
  }
  const T value = panel_value(p.signal, chi);
  if (!(lag > T(0))) return {value, T(p.integral_start + panel_integral(p.signal, chi)), value};
  T lagged = panel_value(p.lagged, chi);
  if (p.transient != T(0)) lagged += p.transient * exp(-(chi - p.start) / lag);
  return {value, T(p.integral_start + panel_integral(p.signal, chi)), lagged};
}

/// The line signal's derivatives 0 .. count-1 at chi (count in [1, nodes]; 0 beyond the value on
/// constant pieces and outside).
template <class T>
void line_derivatives(const line_signal<T>& line, const T& chi, T* out, int count) noexcept {
  for (int k = 0; k < count; ++k) out[k] = T(0);
  if (!(chi > line.start)) {
    out[0] = line.value_before;
    return;
  }
  if (!(chi < line.end)) {
    out[0] = line.value_after;
    return;
  }
  const line_piece<T>& p = piece_at(line, chi);
  if (p.constant) {
    out[0] = p.value;
    return;
  }
  panel_derivatives(p.signal, chi, out, count);
}

/// The radiance of a segment's kind at a height and sine of latitude.
enum class segment_kind : unsigned char { disk, sky_profile, sky_below_step, sky_above_step };

template <class T>
struct radiance_context {
  const radiance_profile<T>* profile;
  T plateau, amplitude, sin_sun;

  T factor(const T& sin_latitude) const noexcept {
    return plateau * season_factor(amplitude, sin_latitude, sin_sun);
  }
  T value(segment_kind kind, const T& height, const T& sin_latitude) const noexcept {
    switch (kind) {
      case segment_kind::disk:
        return factor(sin_latitude) * profile->disk;
      case segment_kind::sky_profile:
        return factor(sin_latitude) * limb_fraction(*profile, height);
      case segment_kind::sky_below_step:
        return factor(sin_latitude);
      case segment_kind::sky_above_step:
        break;
    }
    return T(0);
  }
  bool constant(segment_kind kind) const noexcept {
    return kind == segment_kind::sky_above_step || amplitude == T(0);
  }
};

template <class T>
segment_kind segment_kind_at(const radiance_profile<T>& p, const T& height) noexcept {
  if (height < T(0)) return segment_kind::disk;
  if (p.scale_m > T(0)) return segment_kind::sky_profile;
  return height < p.offset_m ? segment_kind::sky_below_step : segment_kind::sky_above_step;
}

/// A window's extent around one geometric crossing phi_g: where the heights seen lie in
/// [min(0, band_low), band_high], plus the field's half-width; and the locator's part of it,
/// where the heights lie in [min(0, band_low), knee_high].
template <class T>
struct window_extent {
  T lo, hi, root_lo, root_hi;
  T crossing;    ///< the geometric crossing
  int sky_sign;  ///< -1 Earth-in, +1 Earth-out
  T sky, disk;   ///< the locator's region's reach from it, towards the sky and the disk
};

/// The scalar in which the slope locator's polish reads the field's exact mean
/// (polish_slope_maximum): for double, long double where it carries more digits (x86's 64-bit
/// significand), else T itself (float, long double, multiprecision, Jet; double where long double
/// is double, as on the Cortex-M7). Its differences need the mean's last digits: far out the
/// heights carry the satellite's distance, and double's rounding of them leaves the mean ~1e-14 to
/// 2e-13 of itself rough from one azimuth to the next, 2000 times more than long double's
/// (measured: s'' by differences of 1e-7 rad on a sharp limb 25 000 km out, +-6 in double, +-0.005
/// in long double).
template <class T>
struct polish_scalar {
  using type = T;
};
template <>
struct polish_scalar<double> {
  using type = std::conditional_t<(std::numeric_limits<long double>::digits >
                                   std::numeric_limits<double>::digits),
                                  long double, double>;
};
template <class T>
using polish_scalar_t = typename polish_scalar<T>::type;
template <class T>
inline constexpr bool polish_is_wider = !std::is_same_v<polish_scalar_t<T>, T>;

/// The field mean's rules in the polish's scalar, built once per workspace (where it is wider).
template <class T>
struct polish_rules {
  field_rules<polish_scalar_t<T>> rules;
  bool built = false;
};
struct no_polish_rules {};

/// One crossing's (or a short pulse's) window: its one line, the central line of sight, with the
/// line's geometry and its signal (a pencil's radiance or the field's mean).
template <class T>
struct pulse_window {
  T lo, hi;            ///< the window of the output y (scan azimuth, rad)
  T root_lo, root_hi;  ///< where y changes: the locator's samples
  bool pencil;
  bool field;  ///< the line carries the field's mean s (field_mean.hpp), not a pencil's radiance
  geometry_grid<T> geometry;
  line_signal<T> line;
  T lattice_origin, lattice_step;
  int crossings;               ///< the geometric crossings inside (1, or 2 when merged)
  window_extent<T> extent[2];  ///< their extents (the locator's samples)
  /// The central line's exact height at phi (exact_height_source, set by the chain for the
  /// evaluation of a pencil without lag, whose output is its line's radiance itself).
  const void* exact_context;
  T (*exact_height_at)(const void* context, const T& phi);
  T (*exact_field_at)(const void* context, const T& phi);  ///< the field's mean s exactly
  /// The field's mean s exactly in the polish's scalar, where that is wider than T
  /// (polish_scalar; null elsewhere, and where the slope locator does not polish a field).
  const void* polish_context;
  polish_scalar_t<T> (*polish_field_at)(const void* context, const polish_scalar_t<T>& phi);
  radiance_context<T> radiance;  ///< the profile, the plateau, the season term
  field_sweep<T> sweep;          ///< the line's model of the field's G in phi (field_sweep.hpp)
  T breaks[4 * max_pieces];      ///< build_field_line's scratch: the pieces' ends, sorted
};

/// Where the profile needs resolving: heights in [band_low, band_high], the knee (fine pieces)
/// below knee_high.
template <class T>
struct profile_band {
  T band_low, knee_high, band_high;
};

template <class T>
profile_band<T> profile_band_of(const radiance_profile<T>& p, const T& tail_cut) noexcept {
  if (p.scale_m == T(0)) return {p.offset_m, p.offset_m, p.offset_m};
  // Above x_cut (16 by default: l < 7.8e-8, tail_cut_of), the tail beyond, integrated over any
  // field and lag, moves the output by < l(x_cut) H of the plateau per rad of height rate.
  const T& x_cut = tail_cut;
  return {T(p.offset_m + p.x_saturated * p.scale_m), T(p.offset_m + T(6) * p.scale_m),
          T(p.offset_m + x_cut * p.scale_m)};
}

/// The highest tangent height with radiance: the band's top, or the surface where the whole band
/// lies below it (delta50 + x_cut H < 0: a line below the surface sees the disk, whatever the
/// profile). Above it the sky is 0.
template <class T>
T radiance_top(const profile_band<T>& band) noexcept {
  return band.band_high > T(0) ? band.band_high : T(0);
}

/// The smallest fraction of the limb's plateau, l, at which the locator may look for its level:
/// normalised, k of a peak of at least min(L_disk, l(0)) L0 (0 where that bound is 0: a dark
/// disk's peak is the limb's, whatever it is); fixed, T over the brightest plateau; slope, none
/// (0). The season term's factor at its extreme.
template <class T>
T smallest_level_fraction(const sensor_physics_head<T>& head) noexcept {
  const sensor_physics_settings<T>& s = head.settings;
  const radiance_profile<T>& profile = head.profile;
  if (!(profile.scale_m > T(0)) || s.locator.kind == locator_kind::slope) return T(0);
  const T amplitude = s.season_amplitude < T(0) ? T(-s.season_amplitude) : s.season_amplitude;
  if (s.locator.kind == locator_kind::fixed)
    return T(s.locator.threshold / (s.plateau * (T(1) + amplitude)));
  const T surface = limb_fraction(profile, T(0));
  return T(s.locator.threshold * (profile.disk < surface ? profile.disk : surface) *
           (T(1) - amplitude));
}

/// Where the profile is cut (MODEL §12: 0 above delta50 + x_cut H), in scale heights: the
/// accuracy's tail cut, raised by ln(0.1 / f) for a locator that may look for a level f below a
/// tenth of the plateau. The tail's radiance beyond the cut (l ~ ln 2 e^{-x}) stays under l(16)
/// = 7.8e-8 of a tenth of the level: cut at 16 H, a lagged pencil's fixed level of 1e-4 L0 was
/// 7e-6 deg from the reference and one of 1e-7 L0 0.0063 deg; raised, within 5e-8 deg down to
/// 1e-10 L0, below the lowest level a locator may take (lowest_level, 1e-8 L0).
template <class T>
T tail_cut_of(const sensor_physics_head<T>& head) noexcept {
  using std::log;
  const T f = smallest_level_fraction(head);
  const T tenth = T(1) / T(10);
  if (!(f > T(0)) || !(f < tenth)) return head.accuracy.tail_cut;
  return T(head.accuracy.tail_cut + log(T(tenth / f)));
}

/// The lag matrices of the pieces' widths, the two lattice widths kept.
template <class T>
struct lag_cache {
  int count;
  bool outgrown;  ///< a window needed more pieces or panels than the workspace holds
  lag_matrix<T> matrix[max_widths];
  lag_matrix<T> scratch;

  const lag_matrix<T>& of(const sensor_physics_head<T>& head, const T& width) noexcept {
    for (int i = 0; i < count; ++i)
      if (matrix[i].width == width) return matrix[i];
    if (count < max_widths) {  // the lattice's widths and the settling run's
      lag_matrix_of(matrix[count], head, width);
      return matrix[count++];
    }
    lag_matrix_of(scratch, head, width);
    return scratch;
  }
};

}  // namespace physics_detail

/// The memory one head-row of the chain works in: two windows (Earth-in, Earth-out), their
/// geometry and their pieces. The core allocates nothing: the caller owns this (369 KB in
/// double, 168 KB in float; keep one per thread and reuse it).
template <class T>
struct sensor_physics_workspace {
  physics_detail::pulse_window<T> window[2];
  physics_detail::lag_cache<T> cache;
  /// The slope's polish reads the exact mean in a wider scalar (physics_detail::polish_scalar).
  std::conditional_t<physics_detail::polish_is_wider<T>, physics_detail::polish_rules<T>,
                     physics_detail::no_polish_rules>
      polish;
  /// Which part of the last row's pulse gave its peak (the normalised locator's level): 0 the
  /// Earth-in window (or the one window where the two merge), 1 the Earth-out window, 2 the
  /// plateau between them; -1 where no peak was taken. Where it changes from row to row a
  /// normalised locator's crossings have a kink (the peak is the largest of smooth parts): the
  /// physics table cuts its pieces there.
  int peak_part = -1;
};

namespace physics_detail {

/// A smooth run's piece is halved until its polynomial resolves the signal, at most this many
/// times (a 4096th of the piece).
inline constexpr int max_smooth_halvings = 12;

/// Whether a smooth run's piece resolves its signal: its Legendre tail at most 1e-9 of `scale`
/// (the plateau; the interpolation's error about a tenth of it).
template <class T>
bool smooth_piece_resolved(const sensor_physics_head<T>& head, const T& start, const T& width,
                           const T* values, const T& scale) noexcept {
  return !(legendre_tail(legendre_panel_of(head.rule, start, width, values)) >
           scale / T(1000000000));
}

/// Appends a piece [start, start + width] to the line; values at the rule's nodes from `values`
/// (or the constant), its integral and lag carried from the previous piece.
template <class T>
bool push_piece(line_signal<T>& line, const sensor_physics_head<T>& head, lag_cache<T>& cache,
                const T& start, const T& width, bool constant, const T& constant_value,
                const T* values, T& integral, T& lagged) noexcept {
  using std::exp;
  if (line.count >= line.capacity) {
    cache.outgrown = true;
    return false;
  }
  if (!(width > T(0))) return true;
  line_piece<T>& p = line.piece[line.count++];
  p.start = start;
  p.width = width;
  p.constant = constant;
  p.value = constant_value;
  p.integral_start = integral;
  p.lag_start = lagged;
  p.transient = T(0);
  const T lag = head.lag_rad;
  if (constant) {
    integral += constant_value * width;
    if (lag > T(0))
      lagged = constant_value + (lagged - constant_value) * exp(-width / lag);
    else
      lagged = constant_value;
    return true;
  }
  p.signal = legendre_panel_of(head.rule, start, width, values);
  integral += p.signal.coefficients[0] * width;
  if (lag > T(0)) {
    const lag_matrix<T>& m = cache.of(head, width);
    // y at the nodes (or, on a wide piece, its steady part q), and y at the piece's end.
    const T(*rows)[nodes] = m.transient ? m.steady : m.row;
    T z[nodes];
    for (int i = 0; i < nodes; ++i) {
      T sum = m.transient ? T(0) : T(m.decay[i] * p.lag_start);
      for (int k = 0; k < nodes; ++k) sum += rows[i][k] * p.signal.coefficients[k];
      z[i] = sum;
    }
    lagged = m.decay[nodes] * p.lag_start;
    for (int k = 0; k < nodes; ++k) lagged += m.row[nodes][k] * p.signal.coefficients[k];
    if (m.transient) {
      T start_value = T(0);
      for (int k = 0; k < nodes; ++k) start_value += m.steady_start[k] * p.signal.coefficients[k];
      p.transient = p.lag_start - start_value;
    }
    p.lagged = legendre_panel_of(head.rule, start, width, z);
  } else {
    p.lagged = p.signal;
    lagged = panel_value(p.signal, T(start + width));
  }
  return true;
}

/// The values of a polynomial piece [start, start + width] of the line and segment kind.
template <class T>
void piece_values(const pulse_window<T>& w, const sensor_physics_head<T>& head,
                  const radiance_context<T>& radiance, segment_kind kind, const T& start,
                  const T& width, T* values) noexcept {
  for (int i = 0; i < nodes; ++i) {
    const T phi = start + (head.rule.nodes[i] + T(1)) * width / T(2);
    const T height = w.geometry.height_at(phi);
    const T lat = w.geometry.latitudes ? w.geometry.sin_latitude_at(phi) : T(0);
    values[i] = radiance.value(kind, height, lat);
  }
}

/// Lays pieces along a window's line, carrying its integral and lag from piece to piece.
template <class T>
struct piece_layer {
  pulse_window<T>& w;
  const sensor_physics_head<T>& head;
  lag_cache<T>& cache;
  const radiance_context<T>& radiance;
  T& integral;
  T& lagged;
  T values[nodes] = {};

  bool polynomial(segment_kind kind, const T& start, const T& width) noexcept {
    piece_values(w, head, radiance, kind, start, width, values);
    return push_piece(w.line, head, cache, start, width, false, T(0), values, integral, lagged);
  }
  bool constant(const T& from, const T& to, const T& value) noexcept {
    return push_piece(w.line, head, cache, from, T(to - from), true, value, values, integral,
                      lagged);
  }

  /// A slowly varying run (the season factor on the disk or a saturated sky): pieces of the
  /// geometry's width, except where the detector is still settling from what came before: its
  /// transient e^{-x/Lambda} would not fit a wide polynomial, so the run starts with pieces of
  /// 2 Lambda growing by 1.5 (the interpolation error of the transient, e^{-D/Lambda} (w / 2
  /// Lambda)^10 / (2^9 10!) at distance D, stays below 1e-8 of it).
  bool smooth(T from, const T& to, segment_kind kind) noexcept {
    using std::ceil;
    if (!(to > from)) return true;
    const T lag = head.lag_rad;
    if (lag > T(0))
      for (T width = T(2) * lag; width < geometry_panel_width<T>() && to - from > T(2) * width;
           width = width * T(3) / T(2)) {
        if (!resolved_polynomial(kind, from, width, 0)) return false;
        from = from + width;
      }
    const T count = ceil((to - from) / geometry_panel_width<T>());
    const int n = count < T(1) ? 1 : static_cast<int>(long_double_value(count));
    const T width = (to - from) / T(n);
    for (int i = 0; i < n; ++i)
      if (!resolved_polynomial(kind, T(from + T(i) * width), width, 0)) return false;
    return true;
  }

  /// A smooth run's piece, halved until its polynomial resolves the signal: its Legendre tail
  /// at most 1e-9 (of L0; the interpolation's error about a tenth of it). The season factor
  /// varies on the scale of the line's least nadir angle where the scan passes close to the
  /// nadir (from far away), which a polynomial over 0.1 rad missed by 3e-3 of L0 (37 000 km
  /// out, a pencil with lag: its peak on the disk 1.1e-5 high, the crossings 1e-4 deg off the
  /// reference). At most 12 halvings (a 4096th of the piece).
  bool resolved_polynomial(segment_kind kind, const T& start, const T& width, int depth) noexcept {
    piece_values(w, head, radiance, kind, start, width, values);
    if (depth < max_smooth_halvings && !smooth_piece_resolved(head, start, width, values, T(1))) {
      const T half = width / T(2);
      return resolved_polynomial(kind, start, half, depth + 1) &&
             resolved_polynomial(kind, T(start + half), half, depth + 1);
    }
    return push_piece(w.line, head, cache, start, width, false, T(0), values, integral, lagged);
  }

  /// The lattice's cells over [c0, c1]: fine where any part is below knee_high, coarse (aligned
  /// 4-cell groups) above. Full cells take exactly the lattice's widths (their lag matrices are
  /// computed once); only a cell cut by a jump (the segment's ends) has its own width.
  bool lattice(const T& c0, const T& c1, segment_kind kind, const profile_band<T>& band) noexcept {
    using std::floor;
    const T step = w.lattice_step, coarse = T(4) * step;
    auto lattice_point = [&](long long i) {
      return T(w.lattice_origin + integer_value<T>(i) * step);
    };
    T x = c0;
    long long i = static_cast<long long>(long_double_value(floor((x - w.lattice_origin) / step)));
    if (lattice_point(i + 1) - x < step / T(1000)) ++i;  // x rounded just below a lattice point
    while (x < c1) {
      T end, width;
      if (x != lattice_point(i)) {  // off the lattice: up to the next lattice point
        end = lattice_point(i + 1) > c1 ? c1 : lattice_point(i + 1);
        width = end - x;
        ++i;
      } else if (i % 4 == 0 && !(lattice_point(i + 4) > c1) &&
                 w.geometry.height_at(x) >= band.knee_high &&
                 w.geometry.height_at(lattice_point(i + 4)) >= band.knee_high) {
        end = lattice_point(i + 4);
        width = coarse;
        i += 4;
      } else {
        end = lattice_point(i + 1);
        width = step;
        if (end > c1) {
          end = c1;
          width = c1 - x;
        }
        ++i;
      }
      if (!polynomial(kind, x, width)) return false;
      x = end;
    }
    return true;
  }
};

/// The pieces of one segment [a, b] of the line (no jump inside). Constant kinds: one piece.
/// Smooth kinds without the profile (the season term on the disk or under a step): a smooth
/// run. The profile: constant outside its band (saturated: L0 when A = 0; above the band: 0),
/// the lattice across it; the band's ends rounded outwards to the coarse lattice, so that only
/// jumps cut cells.
template <class T>
bool segment_pieces(pulse_window<T>& w, const sensor_physics_head<T>& head, lag_cache<T>& cache,
                    const radiance_context<T>& radiance, const T& a, const T& b,
                    const profile_band<T>& band, T& integral, T& lagged) noexcept {
  using std::ceil;
  using std::floor;
  piece_layer<T> layer{w, head, cache, radiance, integral, lagged};
  const T mid = (a + b) / T(2);
  const segment_kind kind = segment_kind_at(*radiance.profile, w.geometry.height_at(mid));
  if (kind != segment_kind::sky_profile) {
    if (radiance.constant(kind))
      return layer.constant(a, b, radiance.value(kind, w.geometry.height_at(mid), T(0)));
    return layer.smooth(a, b, kind);
  }
  // The band's extent on this segment: heights are monotone along it.
  const T ha = w.geometry.height_at(a), hb = w.geometry.height_at(b);
  const bool rising = hb > ha;
  auto position = [&](const T& level) {  // where the height passes level, clamped to [a, b]
    const T lo_h = rising ? ha : hb, hi_h = rising ? hb : ha;
    if (!(level > lo_h)) return rising ? a : b;
    if (!(level < hi_h)) return rising ? b : a;
    return height_root(w.geometry, level, a, b);
  };
  const T p_low = position(band.band_low), p_high = position(band.band_high);
  const T u0 = p_low < p_high ? p_low : p_high, u1 = p_low < p_high ? p_high : p_low;
  const T coarse = T(4) * w.lattice_step;
  T c0 = w.lattice_origin + floor((u0 - w.lattice_origin) / coarse) * coarse;
  T c1 = w.lattice_origin + ceil((u1 - w.lattice_origin) / coarse) * coarse;
  if (c0 < a) c0 = a;
  if (c1 > b) c1 = b;
  if (!(u1 > u0)) c1 = c0;
  // Before and after the band: saturated (below band_low) or empty (above band_high).
  auto outside = [&](const T& from, const T& to) {
    if (!(to > from)) return true;
    const T h = w.geometry.height_at(T((from + to) / T(2)));
    if (h > band.band_high || radiance.amplitude == T(0))
      return layer.constant(from, to, h > band.band_high ? T(0) : radiance.plateau);
    return layer.smooth(from, to, kind);
  };
  return outside(a, c0) && layer.lattice(c0, c1, kind, band) && outside(c1, b);
}

/// The derivatives 0 .. jump_terms-1 of a piece at phi.
template <class T>
void piece_derivatives(const line_piece<T>& p, const T& phi, T out[jump_terms]) noexcept {
  if (p.constant) {
    out[0] = p.value;
    for (int k = 1; k < jump_terms; ++k) out[k] = T(0);
    return;
  }
  panel_derivatives(p.signal, phi, out, jump_terms);
}

/// The first jump_terms derivatives along the line at phi of the radiance of a segment kind,
/// analytically: f = L0(phi) g(h(phi)) with g the profile's shape (or the disk's constant), the
/// height's derivatives from the line's geometry polynomial and the profile's from
/// limb_fraction_with_derivatives, by Faa di Bruno (f1 = g1 h1, f2 = g2 h1^2 + g1 h2, f3 = g3
/// h1^3 + 3 g2 h1 h2 + g1 h3) and Leibniz for the season factor. Exact, where the derivatives of
/// the pieces' interpolants at a jump would be rounding noise amplified by (nodes^2 / width)^k.
template <class T>
void side_derivatives(const pulse_window<T>& w, const radiance_context<T>& radiance,
                      segment_kind kind, const T& phi, T out[jump_terms]) noexcept {
  static_assert(jump_terms == 4, "the chain rule below is written for four terms");
  const geometry_grid<T>& g = w.geometry;
  T h[jump_terms];
  panel_derivatives(g.height_panel(phi), phi, h, jump_terms);
  T shape[jump_terms] = {T(0), T(0), T(0), T(0)};
  switch (kind) {
    case segment_kind::disk:
      shape[0] = radiance.profile->disk;
      break;
    case segment_kind::sky_below_step:
      shape[0] = T(1);
      break;
    case segment_kind::sky_above_step:
      break;
    case segment_kind::sky_profile: {
      const limb_fraction_derivatives<T> l =
          limb_fraction_with_derivatives(*radiance.profile, h[0]);
      shape[0] = l.value;
      shape[1] = l.first * h[1];
      shape[2] = l.second * h[1] * h[1] + l.first * h[2];
      shape[3] = l.third * h[1] * h[1] * h[1] + T(3) * l.second * h[1] * h[2] + l.first * h[3];
      break;
    }
  }
  // The season factor L0(phi) = plateau (1 + A sin(lat) sin(sun) / sin 23.44 deg).
  T factor[jump_terms] = {radiance.factor(T(0)), T(0), T(0), T(0)};
  if (radiance.amplitude != T(0)) {
    T lat[jump_terms];
    panel_derivatives(g.latitude_panel(phi), phi, lat, jump_terms);
    const T slope = radiance.factor(T(1)) - radiance.factor(T(0));  // d L0 / d sin(lat)
    factor[0] = radiance.factor(lat[0]);
    for (int k = 1; k < jump_terms; ++k) factor[k] = slope * lat[k];
  }
  const T binomial[jump_terms][jump_terms] = {{T(1), T(0), T(0), T(0)},
                                              {T(1), T(1), T(0), T(0)},
                                              {T(1), T(2), T(1), T(0)},
                                              {T(1), T(3), T(3), T(1)}};
  for (int k = 0; k < jump_terms; ++k) {
    T sum = T(0);
    for (int i = 0; i <= k; ++i) sum += binomial[k][i] * factor[i] * shape[k - i];
    out[k] = sum;
  }
}

/// A level the line's signal jumps at (the surface, or delta50 of a step profile), and where the
/// central line of sight meets it.
template <class T>
struct expected_edge {
  T level;       ///< height (m)
  T predicted;   ///< scan azimuth on the central line
  T rate;        ///< |d height / d phi| there (m/rad)
  int sky_sign;  ///< -1: the sky before the edge (Earth-in), +1: after (Earth-out)
};

/// Where the line meets the edge's level: bracketed from the linear prediction, expanding.
template <class T>
bool find_edge(const pulse_window<T>& w, const expected_edge<T>& e, const T& from, const T& to,
               T& out) noexcept {
  using std::abs;
  const T central = w.geometry.height_at(e.predicted);
  // Along the line the height falls (in) or rises (out) at about `rate` per rad.
  T guess = e.predicted + T(e.sky_sign) * (e.level - central) / e.rate;
  if (guess < from) guess = from;
  if (guess > to) guess = to;
  T step = T(1) / T(10000);
  for (int expand = 0; expand < 40; ++expand) {
    T lo = guess - step, hi = guess + step;
    if (lo < from) lo = from;
    if (hi > to) hi = to;
    const T hl = w.geometry.height_at(lo) - e.level, hh = w.geometry.height_at(hi) - e.level;
    if ((hl <= T(0) && hh >= T(0)) || (hl >= T(0) && hh <= T(0))) {
      out = hl == T(0) ? lo : hh == T(0) ? hi : height_root(w.geometry, e.level, lo, hi);
      return true;
    }
    if (lo == from && hi == to) return false;
    step = step * T(2);
  }
  return false;
}

/// Newton on the exact heights from an edge's place (a central difference for the slope), at
/// most 8 steps, each kept within 1e-3 rad of the start.
template <class T, class ExactHeight>
void polish_edge(const ExactHeight& height_at, const T& level, T& edge) noexcept {
  using std::abs;
  const T start = edge, reach = T(1) / T(1000), d = T(1) / T(10000000);
  for (int it = 0; it < 8; ++it) {
    const T f = height_at(edge) - level;
    const T slope = (height_at(T(edge + d)) - height_at(T(edge - d))) / (T(2) * d);
    if (!(slope != T(0)) || !is_finite(slope)) return;
    T next = edge - f / slope;
    if (next > start + reach) next = start + reach;
    if (next < start - reach) next = start - reach;
    const T step = next - edge;
    edge = next;
    if (!(abs(step) > T(4) * std::numeric_limits<T>::epsilon() * (T(1) + abs(edge)))) return;
  }
}

/// The line's jumps across its edge e (`after`: its first piece past it), carried by exact terms.
template <class T>
bool edge_jump(pulse_window<T>& w, const sensor_physics_head<T>& head,
               const radiance_context<T>& radiance, int e, int after) noexcept {
  line_signal<T>& line = w.line;
  T left[jump_terms], right[jump_terms];
  if (after <= 0 || after >= line.count) return false;
  // The kinds on either side, from the pieces' midpoints (the edge's own height is its level).
  const line_piece<T>& before_piece = line.piece[after - 1];
  const line_piece<T>& after_piece = line.piece[after];
  const segment_kind left_kind = segment_kind_at(
      *radiance.profile, w.geometry.height_at(T(before_piece.start + before_piece.width / T(2))));
  const segment_kind right_kind = segment_kind_at(
      *radiance.profile, w.geometry.height_at(T(after_piece.start + after_piece.width / T(2))));
  side_derivatives(w, radiance, left_kind, line.edge[e], left);
  side_derivatives(w, radiance, right_kind, line.edge[e], right);
  // A jump too small to move the output by 1e-15 of the plateau over the lag's reach (a
  // saturated profile meeting a disk of the same radiance: the pieces' rounding) is none: its
  // terms would cost every evaluation for nothing. Only a pencil's line has edges (a field's
  // mean does not jump): the reach is the lag's.
  T size = T(0), power = T(1);
  const T reach = T(40) * head.lag_rad + w.lattice_step;
  for (int k = 0; k < jump_terms; ++k) {
    line.jump[e][k] = right[k] - left[k];
    size += (line.jump[e][k] < T(0) ? T(-line.jump[e][k]) : line.jump[e][k]) * power;
    power = power * reach / T(k + 1);
  }
  if (!(size > T(1) / T(1000000000000000LL) * radiance.plateau))
    for (int k = 0; k < jump_terms; ++k) line.jump[e][k] = T(0);
  else
    line.jumps = true;
  return true;
}

/// Builds a pencil's line over [from, to]: its edges, its pieces, its jumps.
template <class T, class ExactHeight>
bool build_line(pulse_window<T>& w, const sensor_physics_head<T>& head, lag_cache<T>& cache,
                const radiance_context<T>& radiance, const profile_band<T>& band,
                const expected_edge<T>* edges, int edge_count, const T& from, const T& to,
                const ExactHeight& exact_height_at) noexcept {
  line_signal<T>& line = w.line;
  line.count = 0;
  line.capacity = max_pieces;
  line.jumps = false;
  line.start = from;
  line.end = to;
  line.edges = edge_count;
  for (int e = 0; e < edge_count; ++e)
    if (!find_edge(w, edges[e], from, to, line.edge[e])) return false;
  // The geometry's panels place an edge to their interpolation error, which grows where a wide
  // panel reaches a kink of the heights (the line leaving the sphere's side, c = 0, two degrees
  // from a grazing horizon on a large sphere: 1 km); Newton on the exact heights puts it where the
  // line meets the level exactly (MODEL §12: H = 0 is the geometric crossing at delta50).
  for (int e = 0; e < edge_count; ++e) polish_edge(exact_height_at, edges[e].level, line.edge[e]);
  for (int e = 1; e < edge_count; ++e)
    if (!(line.edge[e] > line.edge[e - 1])) return false;
  const T h_from = w.geometry.height_at(from);
  const segment_kind first = segment_kind_at(*radiance.profile, h_from);
  line.value_before =
      radiance.value(first, h_from, w.geometry.latitudes ? w.geometry.sin_latitude_at(from) : T(0));
  T integral = T(0), lagged = line.value_before;
  int piece_at_edge[max_edges];
  T a = from;
  for (int e = 0; e <= edge_count; ++e) {
    const T b = e < edge_count ? line.edge[e] : to;
    if (!segment_pieces(w, head, cache, radiance, a, b, band, integral, lagged)) return false;
    if (e < edge_count) piece_at_edge[e] = line.count;  // the first piece after the edge
    a = b;
  }
  line.integral_end = integral;
  line.lag_end = lagged;
  const line_piece<T>& last = line.piece[line.count - 1];
  line.value_after = last.constant ? last.value : panel_value(last.signal, to);
  for (int e = 0; e < edge_count; ++e)
    if (!edge_jump(w, head, radiance, e, piece_at_edge[e])) return false;
  return true;
}

/// The output y, the field's mean signal s and dy/dphi at phi.
template <class T>
struct pulse_values {
  T output, mean, slope, curvature;  ///< y, s, dy/dphi, d2y/dphi2 (a jump's delta left out)
};

/// dy/dphi through the lag from the line's values at phi: the detector's equation, lag y' = s - y.
template <class T>
T lagged_slope(const line_values<T>& v, const T& lag) noexcept {
  return (v.value - v.lagged) / lag;
}

/// A window's output at phi from its line (build_window): a pencil's radiance or the field's
/// mean, through the detector's lag.
template <class T>
pulse_values<T> evaluate_window(const pulse_window<T>& w, const sensor_physics_head<T>& head,
                                const T& phi) noexcept {
  const T& lag = head.lag_rad;
  if (!(lag > T(0)) && !w.field) {
    // Without lag the pencil's output is the radiance of its line of sight itself: evaluated
    // exactly from the line's geometry (the pieces' interpolation would leave 1e-7 of it).
    // The height exactly: the geometry's panels interpolate it to 1e-7 m, but where a wide
    // panel reaches a kink of the heights (a grazing horizon on a large sphere) to a kilometre,
    // and the output's jump sits where the height crosses its level.
    const T height =
        w.exact_height_at ? w.exact_height_at(w.exact_context, phi) : w.geometry.height_at(phi);
    T d[jump_terms];
    const segment_kind kind = segment_kind_at(*w.radiance.profile, height);
    side_derivatives(w, w.radiance, kind, phi, d);
    const T lat = w.geometry.latitudes ? w.geometry.sin_latitude_at(phi) : T(0);
    d[0] = w.radiance.value(kind, height, lat);
    return {d[0], d[0], d[1], d[2]};
  }
  const line_values<T> v = evaluate_line(w.line, lag, phi);
  if (lag > T(0)) {
    T derivatives[2] = {};  // s and s': y'' = (s' - y') / lag
    line_derivatives(w.line, phi, derivatives, 2);
    const T slope = lagged_slope(v, lag);
    return {v.lagged, v.value, slope, T((derivatives[1] - slope) / lag)};
  }
  T derivatives[3] = {};  // s, s' and s''
  line_derivatives(w.line, phi, derivatives, 3);
  if (w.field && w.exact_field_at) {
    // Without lag the output is the field's mean itself: exactly, not the pieces' interpolant
    // (which a circle's tangency, (phi - phi*)^(3/2), leaves 1e-7 deg from it).
    const T s = w.exact_field_at(w.exact_context, phi);
    return {s, s, derivatives[1], derivatives[2]};
  }
  return {v.value, v.value, derivatives[1], derivatives[2]};
}

/// What the field's mean needs of the radiance (field_mean.hpp): the season's amplitude A
/// sin(delta_sun) / sin 23.44 deg.
template <class T>
field_radiance<T> field_radiance_of(const radiance_context<T>& radiance) noexcept {
  using std::sin;
  const T sin_obliquity = sin(T(2344) / T(100) * (pi<T>() / T(180)));
  return {radiance.profile, radiance.plateau,
          T(radiance.amplitude * radiance.sin_sun / sin_obliquity)};
}

/// The rigid field at phi and its mean s (field_mean.hpp), by the rules `rules`.
template <class T, class Surface>
T field_signal_at(const field_of_view<T>& field, const field_rules<T>& rules,
                  const scan_circle<T>& circle, const Surface& surface,
                  const radiance_context<T>& radiance, const T& phi) noexcept {
  return field_mean_at(field_patch_at(circle, surface, field, phi, radiance.amplitude != T(0)),
                       field_radiance_of(radiance), rules);
}

/// The same for a head's field, by its rules.
template <class T, class Surface>
T field_signal_at(const sensor_physics_head<T>& head, const scan_circle<T>& circle,
                  const Surface& surface, const radiance_context<T>& radiance,
                  const T& phi) noexcept {
  return field_signal_at(head.settings.field, head.field, circle, surface, radiance, phi);
}

/// The patch's lowest and highest heights at phi: the square's corners; the circle's points
/// along the height's gradient, refined by a parabola in the angle about the centre.
template <class T>
struct patch_range {
  T low, high;
  T corner[4];     ///< the square's corners (or the circle's low, high, low, high)
  T side[4];       ///< the square's sides' extremes (side_extreme; the circle: its corners')
  bool inside[4];  ///< a side's extreme lies inside it (else it is an end's corner)
};

/// The extreme of a square's side, heights a, c at its ends (t = -1, 1) and height(t) between:
/// where the height along the side has an interior extreme (its parabola through the ends and the
/// middle turns inside), that extreme, refined by golden section (30 steps: its place within 2e-7
/// of the side, its value to the second order of that); else the end of the same kind (the
/// lower end for a minimum). A level curve nearly parallel to a side touches it inside first:
/// the chord then grows as the square root of the distance, s' as well, and s is (phi -
/// phi*)^(3/2) there, as at a circle's tangency (found by a random scan: a 2.4 deg square on a
/// sharp limb 15 600 km out, s' falling by 9 in 1e-4 rad before the corner's contact, missed by
/// the pieces: s 4e-4 of L0 off, Earth-in 4e-3 deg).
template <class T, class Height>
T side_extreme(const T& a, const T& c, const Height& height, bool& inside) noexcept {
  inside = false;
  const T b = height(T(0));
  const T curvature = a - T(2) * b + c;
  const int sign = curvature > T(0) ? 1 : -1;  // a minimum (+1) or a maximum
  const T end = sign > 0 ? (a < c ? a : c) : (a > c ? a : c);
  if (!(curvature != T(0))) return end;
  const T vertex = (a - c) / (T(2) * curvature);
  if (!(vertex > T(-1) && vertex < T(1))) return end;
  // The library's one search (root_finding.hpp), on -sign * height: its largest is the extreme.
  const T extreme =
      -T(sign) *
      golden_section_maximum([&](const T& t) { return T(-T(sign) * height(t)); }, T(-1), T(1), 30)
          .value;
  inside = sign > 0 ? extreme < end : extreme > end;
  return inside ? extreme : end;
}

template <class T, class Surface>
patch_range<T> patch_range_of(const field_patch<T, Surface>& p) noexcept {
  using std::atan2;
  using std::cos;
  using std::sin;
  const T h = p.half;
  patch_range<T> r{};
  if (p.shape == field_shape::square) {
    r.corner[0] = p.height(T(-h), T(-h));
    r.corner[1] = p.height(h, T(-h));
    r.corner[2] = p.height(h, h);
    r.corner[3] = p.height(T(-h), h);
    r.side[0] = side_extreme(
        r.corner[0], r.corner[1], [&](const T& t) { return p.height(T(t * h), T(-h)); },
        r.inside[0]);
    r.side[1] = side_extreme(
        r.corner[1], r.corner[2], [&](const T& t) { return p.height(h, T(t * h)); }, r.inside[1]);
    r.side[2] = side_extreme(
        r.corner[3], r.corner[2], [&](const T& t) { return p.height(T(t * h), h); }, r.inside[2]);
    r.side[3] = side_extreme(
        r.corner[0], r.corner[3], [&](const T& t) { return p.height(T(-h), T(t * h)); },
        r.inside[3]);
    r.low = r.high = r.corner[0];
    for (int k = 0; k < 4; ++k)
      for (const T& c : {r.corner[k], r.side[k]}) {
        if (c < r.low) r.low = c;
        if (c > r.high) r.high = c;
      }
    return r;
  }
  const T gx = p.height(h, T(0)) - p.height(T(-h), T(0));
  const T gy = p.height(T(0), h) - p.height(T(0), T(-h));
  const T toward = atan2(gy, gx), delta = T(1) / T(20);
  auto extreme = [&](const T& angle, int sign) {
    const T a = T(sign) * p.height(T(h * cos(T(angle - delta))), T(h * sin(T(angle - delta))));
    const T b = T(sign) * p.height(T(h * cos(angle)), T(h * sin(angle)));
    const T c = T(sign) * p.height(T(h * cos(T(angle + delta))), T(h * sin(T(angle + delta))));
    const T curvature = a - T(2) * b + c;
    if (!(curvature < T(0))) return T(T(sign) * b);
    const T offset = (a - c) / (T(2) * curvature);  // the parabola's top, in units of delta
    const T top = b - (a - c) * offset / T(4);
    return T(T(sign) * top);
  };
  r.high = extreme(toward, 1);
  r.low = extreme(T(toward + pi<T>()), -1);
  r.corner[0] = r.corner[2] = r.low;
  r.corner[1] = r.corner[3] = r.high;
  for (int k = 0; k < 4; ++k) {
    r.side[k] = r.corner[k];
    r.inside[k] = false;
  }
  return r;
}

/// The heights where s is not smooth (field_levels_of) and their gradings.
template <class T>
struct field_levels {
  T level[3];
  T finest[3];           // a corner's crossing's grading (0: a plain cut)
  T tangency_finest[3];  // a square's side's, or the circle's, tangency's
  int count = 0;
};

/// The heights where s is not smooth as a feature of the patch passes them, each with its
/// grading (field_places).
template <class T>
field_levels<T> field_levels_of(const sensor_physics_head<T>& head, const T& step,
                                const T& rate) noexcept {
  const radiance_profile<T>& profile = head.profile;
  const bool circle_shape = head.settings.field.shape == field_shape::circle;
  const T sharp = step / T(4096);  // the finest grading: 2^-12 of a cell
  field_levels<T> f{};
  // The surface where the radiance jumps: the circle's tangency, (phi - phi*)^(3/2) however broad
  // the limb (H = 42 km graded only to H's width, a whole cell, left 2.2e-3 deg at Earth-out over
  // a disk of 0.79 L0 with a limb of 0.09 at the surface); a square's corner: a plain cut.
  if (profile.disk != limb_fraction(profile, T(0))) {
    f.level[f.count] = T(0);
    f.finest[f.count++] = circle_shape ? sharp : T(0);
  }
  // The knee: a corner passing it is a kink of s smoothed over H; graded down to H's width along
  // the scan where H is small against the cell (4 H below it). A knee narrower than the finest
  // grading (2^-12 of a cell; a step) is at that scale a jump: the circle's tangency with it is
  // graded as with the surface (a plain cut left the 0.43 deg cell beside it 1e-6 of L0 and s'
  // 2e-3 off: a 2.5 deg circle on H = 2 m, Earth-in 3e-5 deg off through a lag), a square's
  // corner on it is a kink, a plain cut, but for the slope locator without lag, which reads s''
  // there: where the patch's height density falls past the corner far faster than it rose
  // before it, the extremum of s' lies in the knee's tail, some 10 H before the corner (a 1.89
  // deg square on H = 21 m, 25 200 km out: at the plain cut 2.9e-4 deg off the reference, graded
  // to H's width 2e-8 deg), so it is graded to H's width there, or to 2^-20 of a cell (the
  // extremum then within that of the corner: 2e-7 deg at the widest cells).
  if (profile.offset_m > T(0) || profile.scale_m > T(0)) {
    f.level[f.count] = profile.offset_m;
    const T knee_width = profile.scale_m / rate;
    const bool reads_knee_tail = head.settings.locator.kind == locator_kind::slope &&
                                 !(head.lag_rad > T(0)) && profile.scale_m > T(0);
    const T tail_finest = knee_width > step / T(1048576) ? knee_width : T(step / T(1048576));
    f.finest[f.count++] = !(T(4) * knee_width < step) ? T(0)
                          : knee_width > sharp        ? knee_width
                          : circle_shape              ? sharp
                          : reads_knee_tail           ? tail_finest
                                                      : T(0);
  }
  // A square's side touching a level inside it: graded as the circle's tangency.
  for (int l = 0; l < f.count; ++l)
    f.tangency_finest[l] = l == 0 && f.level[0] == T(0) ? sharp
                           : f.finest[l] > T(0)         ? f.finest[l]
                                                        : sharp;
  return f;
}

/// A feature's height on the patch: a corner (k < 4), or a square's side's extreme (k >= 4;
/// equal to a corner's unless the side touches a level inside: a tangency, graded as the
/// circle's).
template <class T>
T patch_feature(const patch_range<T>& r, int k) noexcept {
  return k < 4 ? r.corner[k] : r.side[k - 4];
}

/// Where feature k passes `level` in [a, b], its offset from the level at a being fa: bisection
/// on the exact heights to 8 epsilon.
template <class T, class RangeAt>
T feature_crossing(const RangeAt& range_at, int k, const T& level, const T& a, const T& b,
                   const T& fa) noexcept {
  T lo = a, hi = b, flo = fa;
  for (int it = 0; it < 60 && hi - lo > T(8) * std::numeric_limits<T>::epsilon(); ++it) {
    const T m = (lo + hi) / T(2);
    const T fm = patch_feature(range_at(m), k) - level;
    if ((fm < T(0)) == (flo < T(0))) {
      lo = m;
      flo = fm;
    } else {
      hi = m;
    }
  }
  return (lo + hi) / T(2);
}

/// The places in [from, to] where s is not smooth: a corner of the square (the circle's lowest or
/// highest point) passing a height where the radiance jumps (the surface, unless L_disk = l(0);
/// delta50 of a step) or the knee (delta50, for H > 0): s is C^1 there (the circle's tangency:
/// (phi - phi*)^(3/2)), so pieces end there, and shrink towards those of the knee and of the
/// circle (`finest`: the grading's floor, 2^-12 of a cell at the circle's tangency with the
/// surface or a step, H's width along the scan at a knee, at least 2^-20 of a cell; 0 for a
/// plain cut). Found on the lattice's cells by bisection on the exact heights.
template <class T, class Surface>
int field_places(const sensor_physics_head<T>& head, const scan_circle<T>& circle,
                 const Surface& surface, const T& from, const T& to, const T& step, const T& rate,
                 T* out, T* finest, int capacity) noexcept {
  const field_of_view<T>& field = head.settings.field;
  const bool circle_shape = field.shape == field_shape::circle;
  const field_levels<T> levels = field_levels_of(head, step, rate);
  auto range_at = [&](const T& phi) {
    return patch_range_of(field_patch_at(circle, surface, field, phi, false));
  };
  int n = 0;
  using std::ceil;
  const T count = ceil((to - from) / step);
  const int cells = count < T(1) ? 1 : static_cast<int>(long_double_value(count));
  patch_range<T> before = range_at(from);
  T a = from;
  for (int i = 1; i <= cells && n < capacity; ++i) {
    const T b = i == cells ? to : T(from + T(i) * step);
    const patch_range<T> after = range_at(b);
    for (int k = 0; k < (circle_shape ? 2 : 8); ++k)
      for (int l = 0; l < levels.count && n < capacity; ++l) {
        const T fa = patch_feature(before, k) - levels.level[l];
        const T fb = patch_feature(after, k) - levels.level[l];
        if ((fa < T(0)) == (fb < T(0))) continue;
        if (k >= 4 && !before.inside[k - 4] && !after.inside[k - 4])
          continue;  // the side's extreme is an end's at both ends: a corner's crossing
        out[n] = feature_crossing(range_at, k, levels.level[l], a, b, fa);
        finest[n++] = k < 4 ? levels.finest[l] : levels.tangency_finest[l];
      }
    before = after;
    a = b;
  }
  return n;
}

/// The lattice cells a long window joins into one piece where the whole field lies in one smooth
/// part of the radiance (build_field_line): as many as fit in a quarter of a geometry panel (0.05
/// rad, where a piece's polynomial follows the latitude's smooth course to rounding), at least 1.
template <class T>
int smooth_join_cells(const T& step) noexcept {
  const T cells = geometry_panel_width<T>() / T(4) / step;
  return cells < T(2) ? 1 : static_cast<int>(long_double_value(cells));
}

/// Where the whole field lies over the scan azimuths [a, b] (its patch at both ends and the
/// middle): in one part of the radiance without a feature, or not.
enum class field_part { feature, sky, disk, saturated };

/// The part the field lies in over [a, b]: the sky above radiance_top (the band's top and the
/// surface: a patch above the band's top but partly on the disk, under a limb whose band lies
/// below the surface, had been taken for sky, the lagged output's history before Earth-in cut
/// short: a 2.39 deg circle with 1 ms of lag and the slope locator, delta50 = -15 km, 2.0e-3 deg
/// off the reference), the disk below the surface, the saturated limb between the surface and
/// the band's foot; else `feature`.
template <class T, class Surface>
field_part field_part_over(const sensor_physics_head<T>& head, const scan_circle<T>& circle,
                           const Surface& surface, const profile_band<T>& band, const T& a,
                           const T& b) noexcept {
  T low = T(0), high = T(0);
  for (int i = 0; i < 3; ++i) {
    const patch_range<T> r = patch_range_of(
        field_patch_at(circle, surface, head.settings.field, T(a + (b - a) * T(i) / T(2)), false));
    if (i == 0 || r.low < low) low = r.low;
    if (i == 0 || r.high > high) high = r.high;
  }
  if (low > radiance_top(band)) return field_part::sky;
  if (high < T(0)) return field_part::disk;
  if (low >= T(0) && high < band.band_low) return field_part::saturated;
  return field_part::feature;
}

/// The ends of the field line's pieces over (from, to], sorted, `to` last, into w.breaks: the
/// lattice's cells, and the places where s is not smooth graded towards them (down to their
/// `finest`, field_places). A long window (a fast scan's lag remembers tens of degrees: 40 lag
/// constants, 115 deg at 4 rev/s and 2 ms; with the season term the in-window reaches twice that
/// into the disk) has more lattice cells than the workspace holds pieces. Where the whole field
/// lies in one part of the radiance without a feature (the sky above the band, the disk, the
/// saturated limb), s is a constant or, with the season term, as smooth as the latitude along the
/// scan: such cells are joined, `join` lattice steps to a piece (build_window asks for it when a
/// line cut at every cell outgrew the workspace; join 1: every cell). false where the ends
/// outgrow 4 `capacity` (cache.outgrown: never a coarser line).
template <class T, class Surface>
bool field_line_breaks(pulse_window<T>& w, const sensor_physics_head<T>& head, lag_cache<T>& cache,
                       const scan_circle<T>& circle, const Surface& surface,
                       const profile_band<T>& band, const T& from, const T& to, const T& rate,
                       int join, int capacity, int& count) noexcept {
  const T step = w.lattice_step;
  T places[24];
  T finest[24];  // each place's finest grading (rad), 0 for a plain cut
  const int np = field_places(head, circle, surface, from, to, step, rate, places, finest, 24);
  T* const breaks = w.breaks;
  int nb = 0;
  bool full = false;
  auto add = [&](const T& x) {
    if (!(x > from && x < to)) return;
    if (nb + 1 >= 4 * capacity) {  // a place kept for `to`
      full = true;
      return;
    }
    breaks[nb++] = x;
  };
  auto part_of = [&](const T& a, const T& b) {
    return field_part_over(head, circle, surface, band, a, b);
  };
  field_part part_before = join > 1 ? part_of(from, T(from + step)) : field_part::feature;
  int joined = 0;
  for (T x = from + step; x < to && !full; x = x + step) {
    if (join > 1) {
      const field_part part_after = part_of(x, T(x + step));
      const bool inside =
          part_before != field_part::feature && part_after == part_before && ++joined % join != 0;
      part_before = part_after;
      if (inside) continue;
      joined = 0;
    }
    add(x);
  }
  for (int i = 0; i < np; ++i) {
    add(places[i]);
    if (!(finest[i] > T(0))) continue;
    for (T d = step / T(2); d > finest[i]; d = d / T(2)) {
      add(T(places[i] - d));
      add(T(places[i] + d));
    }
  }
  if (full) {
    cache.outgrown = true;
    return false;
  }
  breaks[nb++] = to;
  sort_ascending(breaks, nb);
  count = nb;
  return true;
}

/// The field line's pieces between its ends (field_line_breaks), in order: build_field_line's
/// second step. A piece where the whole field lies in one constant part of the radiance (space
/// above the band; without the season term, the disk or the saturated limb) is that constant,
/// consecutive ones of one value joined; any other is a polynomial of s, its means by G's model
/// in phi (field_sweep.hpp: segments of up to a geometry panel, none shorter than four cells,
/// fewer means than its nodes cost).
template <class T, class Surface>
struct field_line_pieces {
  pulse_window<T>& w;
  const sensor_physics_head<T>& head;
  lag_cache<T>& cache;
  const scan_circle<T>& circle;
  const Surface& surface;
  const radiance_context<T>& radiance;
  const profile_band<T>& band;
  T to;
  bool season;
  field_radiance<T> mean_radiance;
  T integral, lagged;
  T values[nodes]{};
  bool pending = false;  // a run of constant cells not yet pushed
  T pending_from{}, pending_value{};

  field_part part_of(const T& a, const T& b) const noexcept {
    return field_part_over(head, circle, surface, band, a, b);
  }
  bool constant_value(const T& a, const T& b, T& value) const noexcept {
    const field_part part = part_of(a, b);
    if (part == field_part::sky) {
      value = T(0);
      return true;
    }
    if (season || part == field_part::feature) return false;
    value = part == field_part::disk ? T(radiance.plateau * head.profile.disk) : radiance.plateau;
    return true;
  }
  bool flush(const T& to_here) noexcept {
    if (!pending) return true;
    pending = false;
    return push_piece(w.line, head, cache, pending_from, T(to_here - pending_from), true,
                      pending_value, values, integral, lagged);
  }
  /// A cell on the disk with the season term: s follows the latitude along the scan, smooth on
  /// the scale of the least angle between the patch and the line through the Earth's centre (from
  /// far away the scan may cross it: the latitude turns about that line, and s bends where the
  /// line meets the patch's sides). Halved, as a pencil's smooth run (resolved_polynomial), until
  /// the piece's Legendre tail is at most 1e-9 of the plateau; at most 12 halvings.
  bool resolved(const T& start, const T& end, int depth) noexcept {
    auto patch_at = [this](const T& phi) {
      return field_patch_at(circle, surface, head.settings.field, phi, season);
    };
    for (int k = 0; k < nodes; ++k)
      values[k] =
          field_sweep_mean(w.sweep, patch_at, mean_radiance, head.field,
                           T(start + (head.rule.nodes[k] + T(1)) * (end - start) / T(2)), to);
    if (season && depth < max_smooth_halvings &&
        !smooth_piece_resolved(head, start, T(end - start), values, radiance.plateau) &&
        part_of(start, end) == field_part::disk) {
      const T middle = (start + end) / T(2);
      return resolved(start, middle, depth + 1) && resolved(middle, end, depth + 1);
    }
    return push_piece(w.line, head, cache, start, T(end - start), false, T(0), values, integral,
                      lagged);
  }
  /// Every piece from `from` to the ends' last.
  bool push_all(const T& from, const T* breaks, int count) noexcept {
    T a = from;
    for (int i = 0; i < count; ++i) {
      const T b = breaks[i];
      if (!(b > a)) continue;
      T value;
      if (constant_value(a, b, value)) {
        if (pending && !(value == pending_value) && !flush(a)) return false;
        if (!pending) {
          pending = true;
          pending_from = a;
          pending_value = value;
        }
      } else {
        if (!flush(a) || !resolved(a, b, 0)) return false;
      }
      a = b;
    }
    return flush(to);
  }
};

/// Builds the field's line over [from, to]: its pieces' ends (field_line_breaks), then the pieces
/// (field_line_pieces), each a constant or a polynomial of s, the lag carried across them.
template <class T, class Surface>
bool build_field_line(pulse_window<T>& w, const sensor_physics_head<T>& head, lag_cache<T>& cache,
                      const scan_circle<T>& circle, const Surface& surface,
                      const radiance_context<T>& radiance, const profile_band<T>& band,
                      const T& from, const T& to, const T& rate, int join, int capacity) noexcept {
  line_signal<T>& line = w.line;
  line.count = 0;
  line.capacity = capacity;
  line.jumps = false;
  line.edges = 0;
  line.start = from;
  line.end = to;
  int count = 0;
  if (!field_line_breaks(w, head, cache, circle, surface, band, from, to, rate, join, capacity,
                         count))
    return false;
  line.value_before = field_signal_at(head, circle, surface, radiance, from);
  field_sweep_start(w.sweep, geometry_panel_width<T>(), T(T(4) * w.lattice_step));
  const bool season = radiance.amplitude != T(0);
  field_line_pieces<T, Surface> pieces{w,       head,
                                       cache,   circle,
                                       surface, radiance,
                                       band,    to,
                                       season,  field_radiance_of(radiance),
                                       T(0),    line.value_before};
  if (!pieces.push_all(from, w.breaks, count)) return false;
  line.integral_end = pieces.integral;
  line.lag_end = pieces.lagged;
  const line_piece<T>& last = line.piece[line.count - 1];
  line.value_after = last.constant ? last.value : panel_value(last.signal, to);
  return true;
}

/// The lattice's step along the scan (rad): a piece spans the profile's H of height at the
/// accuracy's scales (fewer for a pencil, or for the slope locator), or where wider an eighth of
/// a field's heights across the scan (the field smooths the profile over them: the span ~ fov
/// times the height's rate); at most a geometry panel (H = 0).
template <class T>
T lattice_step_of(const sensor_physics_head<T>& head, bool field, const T& half_along,
                  const T& rate) noexcept {
  T scales = field ? head.accuracy.piece_scales : head.accuracy.pencil_piece_scales;
  if (head.settings.locator.kind == locator_kind::slope &&
      head.accuracy.slope_piece_scales < scales)
    scales = head.accuracy.slope_piece_scales;
  T scale = head.profile.scale_m;
  if (field && T(half_along * rate / T(4)) > scale) scale = half_along * rate / T(4);
  T step = scale > T(0) ? T(scales * scale / rate) : geometry_panel_width<T>();
  if (step > geometry_panel_width<T>()) step = geometry_panel_width<T>();
  return step;
}

/// The field's line over [from, to] (build_field_line), cut at every cell within a quarter of the
/// workspace's pieces; else (a fast scan's long memory, two sharp limbs in one window) the cells
/// of the smooth parts joined, within all of them. Each time the workspace doubled, the first
/// build kept its capacity: every window an earlier workspace built is built as before, bit for
/// bit, and the rest within 1.1e-7 deg of the reference (a long lag with a sharp profile or the
/// season term's history, 0.2-2.4 deg fields at 2.4-4.9 rev/s with 1.6-3.9 ms; a 0.6 deg square
/// on H = 93 m seen from 28 000 km, whose merged window holds both crossings' graded places,
/// 2.9e-8 deg: `invalid` before). With the season term the first build joins the smooth cells
/// too: the in-window reaches 40 Lambda into the disk (build_pulse), whose cells vary with the
/// latitude alone, and a joined piece is halved until resolved as a cell is (9 % fewer
/// instructions a row on the benchmark's WGS84 orbit, a 1.5 deg square with 1 ms of lag; its
/// crossings within 3e-14 deg).
template <class T, class Surface>
bool build_field_line_fitting(pulse_window<T>& w, const sensor_physics_head<T>& head,
                              lag_cache<T>& cache, const scan_circle<T>& circle,
                              const Surface& surface, const radiance_context<T>& radiance,
                              const profile_band<T>& band, const T& from, const T& to,
                              const T& rate) noexcept {
  const T step = w.lattice_step;
  const int first_join = radiance.amplitude != T(0) ? smooth_join_cells(step) : 1;
  if (build_field_line(w, head, cache, circle, surface, radiance, band, from, to, rate, first_join,
                       max_pieces / 4))
    return true;
  if (!cache.outgrown) return false;
  cache.outgrown = false;
  return build_field_line(w, head, cache, circle, surface, radiance, band, from, to, rate,
                          smooth_join_cells(step), max_pieces);
}

/// Builds a window [lo, hi] of the output: the geometry of its line over it (widened by the
/// field's half-width, the lag's history where the plateau varies, and the lattice's rounding),
/// then the line's signal. false when a pencil's line misses an expected edge or the window
/// outgrows the workspace.
template <class T, class Surface>
bool build_window(pulse_window<T>& w, const sensor_physics_head<T>& head, lag_cache<T>& cache,
                  const scan_circle<T>& circle, const Surface& surface,
                  const radiance_context<T>& radiance, const expected_edge<T>* edges,
                  int edge_count, const T& lo, const T& hi, const T& rate) noexcept {
  w.radiance = radiance;
  w.exact_context = nullptr;
  w.exact_height_at = nullptr;
  w.exact_field_at = nullptr;
  w.polish_context = nullptr;
  w.polish_field_at = nullptr;
  w.field = head.settings.field.fov_rad > T(0);
  w.pencil = !w.field;
  w.lo = lo;
  w.hi = hi;
  const T half_along = w.field ? patch_half_along(head.settings.field, circle) : T(0);
  const T step = lattice_step_of(head, w.field, half_along, rate);
  const T history =
      radiance.amplitude != T(0) && head.lag_rad > T(0) ? lag_history(head.lag_rad) : T(0);
  // Eight lattice steps cover the line's range rounded outwards to the lattice and its coarse
  // groups; at most two geometry panels (two of the longest steps, H = 0's): eight of those, 92
  // deg a side, took a step profile's window with the season term's history past a workspace
  // of 32 panels (a turn and more: `invalid` below ~260 km, 1.6 ms at 3.8 rev/s).
  const T margin = T(8) * step < T(2) * geometry_panel_width<T>()
                       ? T(T(8) * step)
                       : T(T(2) * geometry_panel_width<T>());
  const T g_lo = lo - half_along - history - margin, g_hi = hi + half_along + margin;
  const profile_band<T> band = profile_band_of(head.profile, tail_cut_of(head));
  // The heights the radiance reaches: the band's top, or the surface where the whole band lies
  // below it (the disk's edge is read there), and a field's heights across the scan.
  const T top = radiance_top(band) + (w.field ? T(half_along * rate) : T(0));
  if (!build_geometry(w.geometry, head, circle, surface, g_lo, g_hi, radiance.amplitude != T(0),
                      top, cache.outgrown))
    return false;
  w.lattice_origin = g_lo;
  w.lattice_step = step;
  // The line's range rounded outwards to the lattice, so that its first and last cells are
  // whole (their lag matrices shared).
  using std::ceil;
  using std::floor;
  const T from = g_lo + floor((lo - half_along - history - g_lo) / step) * step;
  const T to = g_lo + ceil((hi + half_along - g_lo) / step) * step;
  if (w.field)
    return build_field_line_fitting(w, head, cache, circle, surface, radiance, band, from, to,
                                    rate);
  const surface_probe<T> probe = probe_of(surface);
  auto exact_at = [&](const T& phi) {
    return exact_height(circle, surface, probe, phi, false).height_m;
  };
  return build_line(w, head, cache, radiance, band, edges, edge_count, from, to, exact_at);
}

/// |d height / d phi| of the central line at phi (central difference of the exact height).
template <class T, class Surface>
T height_rate(const scan_circle<T>& circle, const Surface& surface, const surface_probe<T>& probe,
              const T& phi) noexcept {
  using std::abs;
  const T step = T(1) / T(100000);
  const T up = exact_height(circle, surface, probe, T(phi + step), false).height_m;
  const T down = exact_height(circle, surface, probe, T(phi - step), false).height_m;
  return abs(up - down) / (T(2) * step);
}

/// Where the central line's height passes a level about the crossing phi_g (window_extent_of).
template <class T, class Surface>
struct height_passage {
  const scan_circle<T>& circle;
  const Surface& surface;
  const surface_probe<T>& probe;
  const T& phi_g;
  const T& rate;
  const T& widen;

  bool passed(const T& target, int direction, bool upwards, const T& d) const noexcept {
    const T h = exact_height(circle, surface, probe, T(phi_g + T(direction) * d), false).height_m;
    return upwards ? h >= target : h <= target;
  }

  // How far along the central line its height passes `target` (towards the sky: upwards,
  // towards the disk: downwards): from the linear guess, doubled until the exact height passes it
  // (heights curve away from the tangent, so the linear guess can be far off near grazing), at
  // most `limit`.
  T distance(const T& target, int direction, bool upwards, const T& limit) const noexcept {
    T d = (target < T(0) ? -target : target) / rate / T(4);
    if (!(d > T(1) / T(100000))) d = T(1) / T(100000);
    int i = 0;
    for (; i < 60 && d < limit && !passed(target, direction, upwards, d); ++i) d = d * T(2);
    if (!(d < limit)) return limit * widen;
    // The doubling overshoots by up to 2: four bisections bring it within 1/16 of the distance.
    if (i > 0) {
      T lo = d / T(2), hi = d;
      for (int k = 0; k < 4; ++k) {
        const T m = (lo + hi) / T(2);
        if (passed(target, direction, upwards, m))
          hi = m;
        else
          lo = m;
      }
      d = hi;
    }
    return d * widen;
  }
};

/// Widens e to at least 1e-3 rad about phi_g and sets its samples' reach: window_extent_of's end.
template <class T>
void finish_extent(window_extent<T>& e, const T& phi_g, int sky_sign) noexcept {
  // A step profile at the surface seen by a pencil has no extent of its own: a window of
  // 1e-3 rad about the crossing holds its jump and the locator's bracket.
  const T least = T(1) / T(1000);
  if (e.lo > phi_g - least) e.lo = phi_g - least;
  if (e.hi < phi_g + least) e.hi = phi_g + least;
  if (e.root_lo > phi_g - least) e.root_lo = phi_g - least;
  if (e.root_hi < phi_g + least) e.root_hi = phi_g + least;
  // The samples' reach: the whole locator region.
  const T before = phi_g - e.root_lo, after = e.root_hi - phi_g;
  e.sky = sky_sign < 0 ? before : after;
  e.disk = sky_sign < 0 ? after : before;
}

template <class T, class Surface>
window_extent<T> window_extent_of(const scan_circle<T>& circle, const Surface& surface,
                                  const surface_probe<T>& probe, const profile_band<T>& band,
                                  const T& phi_g, int sky_sign, const T& rate, const T& half_along,
                                  const T& widen, const T& half_chord, const T& root_top,
                                  const T& lag, const field_of_view<T>& field) noexcept {
  // The heights at phi_g, with 0: the line of sight's (the patch's, for a field).
  const T h = exact_height(circle, surface, probe, phi_g, false).height_m;
  T low = h < T(0) ? h : T(0), high = h > T(0) ? h : T(0);
  if (field.fov_rad > T(0)) {
    const patch_range<T> r = patch_range_of(field_patch_at(circle, surface, field, phi_g, false));
    if (r.low < low) low = r.low;
    if (r.high > high) high = r.high;
  }
  const T bottom = band.band_low < T(0) ? band.band_low : T(0);
  const T top = radiance_top(band);
  const height_passage<T, Surface> passage{circle, surface, probe, phi_g, rate, widen};
  const T quarter_turn = pi<T>() / T(2);
  // The locator's region: from root_top on the sky side (where the output has left zero or, out,
  // has surely passed the level) to the disk's saturation; the window adds the field's half-
  // width, and the lag's memory (20 Lambda, e^-20 = 2e-9) on its history side, before the region,
  // though never higher than the band's top, above which the signal is 0.
  const T to_root = passage.distance(T(root_top - low), sky_sign, true, quarter_turn);
  const T disk = passage.distance(T(bottom - high), -sky_sign, false, half_chord);
  const T memory = lag_history(lag);
  T sky = to_root + memory;
  if (memory > T(0)) {
    const T full = passage.distance(T(top - low), sky_sign, true, T(sky / widen));
    if (full < sky) sky = full;
  }
  if (sky < to_root) sky = to_root;
  window_extent<T> e;
  e.crossing = phi_g;
  e.sky_sign = sky_sign;
  e.sky = to_root + half_along;
  e.disk = disk + half_along;
  if (sky_sign < 0) {  // Earth-in: sky, then disk, where the output rises a few Lambda late
    e.root_lo = phi_g - to_root - half_along;
    e.root_hi = phi_g + disk + half_along + T(4) * lag;
    e.lo = phi_g - sky - half_along;
    e.hi = e.root_hi;
  } else {  // Earth-out: disk (history), then sky
    e.root_lo = phi_g - disk - half_along;
    e.root_hi = phi_g + sky + half_along;  // the output's fall lags up to the memory
    e.lo = e.root_lo - memory;
    e.hi = e.root_hi;
  }
  finish_extent(e, phi_g, sky_sign);
  return e;
}

/// A signal view of a window for the locator algorithms: at(phi) = {y, dy/dphi}.
template <class T>
struct window_signal {
  const pulse_window<T>* w;
  const sensor_physics_head<T>* head;
  const T* sample_phi;  ///< samples already evaluated, looked up rather than evaluated again
  const lag_point<T>* sample_value;
  int samples;
  lag_point<T> at(const T& phi) const noexcept {
    for (int i = 0; i < samples; ++i)
      if (sample_phi[i] == phi) return sample_value[i];
    const pulse_values<T> v = evaluate_window(*w, *head, phi);
    return {v.output, v.slope};
  }
};

/// A largest value and its place; `inside`: refined between samples (not a sample's own).
template <class T>
struct window_maximum {
  T value;
  T phi;
  bool inside;
};

/// The largest value of f on [lo, hi] and its place, to a relative bracket of 1e-9 (golden-section
/// search, 45 steps): the pulse's peak.
template <class T, class F>
window_maximum<T> refine_maximum_at(const F& f, T lo, T hi) noexcept {
  const golden_maximum<T> m = golden_section_maximum(f, lo, hi, 45);
  return {m.value, m.x, true};
}

/// refine_maximum_at's value alone.
template <class T, class F>
T refine_maximum(const F& f, T lo, T hi) noexcept {
  return refine_maximum_at(f, lo, hi).value;
}

/// The output's largest and smallest values over the plateau [from, to] between separated
/// windows, where the whole field lies on the disk: s = L_disk L0 averaged over the field. Without
/// the season term s is constant and y relaxes to it from y_from. With it s varies slowly (the
/// tangent points' latitudes along the scan): s on panels of at most 0.5 rad, halved until their
/// Legendre tails fall below 1e-8 (the field's mean of
/// sin(latitude) by its 2 x 2 Gauss points: sin(lat) is nearly linear across a field), and y the
/// exact lag of those panels from y_from (plateau_output); extremes over the nodes refined by
/// golden section.
template <class T>
struct plateau_range {
  T highest;       ///< the largest output
  T lowest_mean;   ///< the smallest field mean: the output dips below a level only if this does
  T highest_mean;  ///< the largest field mean: the output, a weighted mean of it, stays below
};

/// The field's mean disk radiance at phi (plateau_of's samples of s): the season factor's mean
/// over the patch (field_mean.hpp's patch_latitude_mean: by fans near the line through the
/// Earth's centre, where the latitude turns about that line, else the weight's polynomial).
template <class T, class Surface>
T plateau_disk_mean(const sensor_physics_head<T>& head, const scan_circle<T>& circle,
                    const Surface& surface, const surface_probe<T>& probe,
                    const radiance_context<T>& radiance, const T& phi) noexcept {
  const field_of_view<T>& field = head.settings.field;
  if (!(field.fov_rad > T(0)))
    return radiance.profile->disk *
           radiance.factor(exact_height(circle, surface, probe, phi).sin_latitude);
  const field_patch<T, Surface> patch = field_patch_at(circle, surface, field, phi, true);
  return radiance.profile->disk *
         radiance.factor(field_detail::patch_latitude_mean(patch, head.field));
}

/// The lag's steady output on a plateau panel's s, a polynomial of degree nodes - 1, as a
/// polynomial of the same degree on the same panel: q = sum over k of (-Lambda)^k s^(k), which
/// solves q + Lambda q' = s (y' = (s - y) / Lambda) exactly. In the panel's Legendre coefficients
/// (P_j' = sum over k = j-1, j-3, ... of (2k + 1) P_k), q_m = s_m - Lambda (2 / width) (2m + 1)
/// (q_{m+1} + q_{m+3} + ...), from the top down: once a panel, where the sum's derivatives at
/// every phi took a table of nodes^2 values each time (half a pencil's chain with the season term
/// on WGS84, whose disk's plateau the output's extremes search). Its m-th coefficient carries the
/// rounding of the ones above times (2 Lambda / width)(2m + 1), as the sum's k-th term carried
/// (2 Lambda / width)^k P_9^(k)(1): at most some 1e-11 of s on a panel at least 4 Lambda wide
/// (plateau_output); the crossings moved by at most 1e-13 deg from the sum's (measured).
template <class T>
piece_panel<T> plateau_steady_panel(const T& lag, const piece_panel<T>& s) noexcept {
  piece_panel<T> q = s;
  const T rate = lag * T(2) / s.width;
  T tail[2] = {T(0), T(0)};  // sum of q_j over j > m, by the parity of j
  for (int m = nodes - 1; m >= 0; --m) {
    q.coefficients[m] =
        s.coefficients[m] - rate * T(tail[(m + 1) % 2] * integer_factor<T>(2 * m + 1));
    tail[m % 2] += q.coefficients[m];
  }
  return q;
}

/// One panel of the plateau (visit_plateau_panels): s as a polynomial over [start, start +
/// width], its values at the rule's nodes, and the output at its start.
template <class T>
struct plateau_panel {
  piece_panel<T> s;
  T values[nodes];
  T start, width;
  T y_start;
  bool series;  ///< at least 4 Lambda wide: the output by the steady series and its transient
  piece_panel<T> steady;  ///< the steady output (plateau_steady_panel; series only)
  T transient;            ///< y_start less the steady output there (series only)
};

/// Sets a plateau panel's output at its start and, where the series serves, its transient.
template <class T>
void plateau_panel_start(const sensor_physics_head<T>& head, const T& y_start,
                         plateau_panel<T>& p) noexcept {
  p.y_start = y_start;
  p.series = p.width >= T(4) * head.lag_rad;
  p.transient = T(0);
  if (!p.series) return;
  p.steady = plateau_steady_panel(head.lag_rad, p.s);
  p.transient = y_start - panel_value(p.steady, p.start);
}

/// The output at phi on a plateau panel (plateau_of): the exact lag of the panel's s (a
/// polynomial) from its start, by the steady series (plateau_steady_panel) and its transient on a
/// panel at least 4 Lambda wide, else by the rule's Gauss points over [start, phi] of the lag's
/// kernel times s (the kernel's exponent spans at most 4 there: the rule's remainder ~1e-18 of s).
/// The series' first four terms alone, as before, left 4e-4 of L0 where a bright disk's s bent on
/// panels 2.7 Lambda wide (Lambda = 8.7e-3 rad, s falling from 72 to 65.5 L0 over 0.38 rad), and
/// a crossing of the level there 8.4e-5 deg off the reference; now within 5e-9 of L0 of the
/// reference's output, the crossing 1.7e-10 deg.
template <class T>
T plateau_output(const sensor_physics_head<T>& head, const plateau_panel<T>& p,
                 const T& phi) noexcept {
  using std::exp;
  const T lag = head.lag_rad;
  if (!(lag > T(0))) return panel_value(p.s, phi);
  const T span = phi - p.start;
  if (p.series) return T(panel_value(p.steady, phi) + p.transient * exp(-span / lag));
  T sum = T(0);
  for (int i = 0; i < nodes; ++i) {
    const T x = (head.rule.nodes[i] + T(1)) / T(2);  // in [0, 1] along [start, phi]
    sum += head.rule.weights[i] * exp(-(T(1) - x) * span / lag) *
           panel_value(p.s, T(p.start + x * span));
  }
  return T(p.y_start * exp(-span / lag) + span / (T(2) * lag) * sum);
}

/// The place of the rule's node i on a plateau panel.
template <class T>
T plateau_node(const sensor_physics_head<T>& head, const plateau_panel<T>& p, int i) noexcept {
  return T(p.start + (head.rule.nodes[i] + T(1)) * p.width / T(2));
}

/// One plateau panel's largest output and smallest field mean folded into range (plateau_of).
template <class T>
void plateau_panel_extremes(const sensor_physics_head<T>& head, const plateau_panel<T>& p,
                            plateau_range<T>& range) noexcept {
  auto output = [&](const T& phi) { return plateau_output(head, p, phi); };
  int best = 0, worst = 0, brightest = 0;
  T y[nodes];
  for (int i = 0; i < nodes; ++i) {
    y[i] = output(plateau_node(head, p, i));
    if (y[i] > y[best]) best = i;
    if (p.values[i] < p.values[worst]) worst = i;
    if (p.values[i] > p.values[brightest]) brightest = i;
  }
  auto bracket = [&](int i, T& lo, T& hi) {
    lo = i > 0 ? plateau_node(head, p, i - 1) : p.start;
    hi = i + 1 < nodes ? plateau_node(head, p, i + 1) : T(p.start + p.width);
  };
  T lo, hi;
  bracket(best, lo, hi);
  const T top = refine_maximum(output, lo, hi);
  bracket(worst, lo, hi);
  const T bottom = -refine_maximum([&](const T& phi) { return T(-panel_value(p.s, phi)); }, lo, hi);
  bracket(brightest, lo, hi);
  const T brightest_mean =
      refine_maximum([&](const T& phi) { return panel_value(p.s, phi); }, lo, hi);
  if (top > range.highest) range.highest = top;
  if (bottom < range.lowest_mean) range.lowest_mean = bottom;
  if (brightest_mean > range.highest_mean) range.highest_mean = brightest_mean;
}

/// The plateau [from, to]'s panels of s, in order along the scan, each passed to visit(panel)
/// (plateau_panel), the output carried from y_from at `from` (plateau_output; plateau_of).
template <class T, class Surface, class Visit>
void visit_plateau_panels(const sensor_physics_head<T>& head, const scan_circle<T>& circle,
                          const Surface& surface, const radiance_context<T>& radiance,
                          const T& from, const T& to, const T& y_from,
                          const Visit& visit) noexcept {
  using std::ceil;
  const T gap = to - from;
  const surface_probe<T> probe = probe_of(surface);
  const T count = ceil(gap / (T(1) / T(2)));
  const int panels = count < T(1) ? 1 : static_cast<int>(long_double_value(count));
  T y_start = y_from;
  // A scan near the nadir turns its tangent points fast (build_geometry), and a patch crossing
  // the line through the centre bends s (field_mean.hpp, patch_latitude_mean): each panel is
  // halved on its own until its tail falls below 1e-8 of L0, at most 12 times.
  auto walk = [&](auto& self, const T& start, const T& width, int depth) -> void {
    plateau_panel<T> p;
    p.start = start;
    p.width = width;
    for (int i = 0; i < nodes; ++i)
      p.values[i] =
          plateau_disk_mean(head, circle, surface, probe, radiance, plateau_node(head, p, i));
    p.s = legendre_panel_of(head.rule, start, width, p.values);
    if (legendre_tail(p.s) > T(1) / T(100000000) && depth < 12) {
      self(self, start, T(width / T(2)), depth + 1);
      self(self, T(start + width / T(2)), T(width / T(2)), depth + 1);
      return;
    }
    plateau_panel_start(head, y_start, p);
    visit(p);
    y_start = plateau_output(head, p, T(start + width));
  };
  const T width = gap / T(panels);
  for (int p = 0; p < panels; ++p) walk(walk, T(from + T(p) * width), width, 0);
}

template <class T, class Surface>
plateau_range<T> plateau_of(const sensor_physics_head<T>& head, const scan_circle<T>& circle,
                            const Surface& surface, const radiance_context<T>& radiance,
                            const T& from, const T& to, const T& y_from, const T& s_from) noexcept {
  using std::exp;
  const T lag = head.lag_rad;
  const T gap = to - from;
  if (radiance.amplitude == T(0) || !(gap > T(0))) {
    const T end = lag > T(0) ? T(s_from + (y_from - s_from) * exp(-gap / lag)) : s_from;
    return {y_from > end ? y_from : end, s_from, s_from};
  }
  plateau_range<T> range{y_from, s_from, s_from};
  visit_plateau_panels(head, circle, surface, radiance, from, to, y_from,
                       [&](const plateau_panel<T>& p) { plateau_panel_extremes(head, p, range); });
  // y is a weighted mean of s (a positive kernel of unit weight) and its start: it never exceeds
  // the larger of y_from and s's largest value. The panels' lag above can, where s bends on a scale
  // finer than its panels after their halvings: a field whose patch crosses the line through the
  // Earth's centre (the season term's latitude turning about it, field_mean.hpp) put the
  // plateau's largest output at 1.029 over a disk whose mean never passes 0.961, and the
  // normalised level 0.04 deg off (far seed 24's scene 89). Bounded by the panels' largest s.
  const T bound = y_from > range.highest_mean ? y_from : range.highest_mean;
  if (range.highest > bound) range.highest = bound;
  return range;
}

/// The plateau's passages of a level (plateau_crossings_of): how many upwards and downwards, the
/// first upwards and the last downwards.
template <class T>
struct plateau_passages {
  int rising, falling;
  T first_rising, last_falling;
};

/// Where the predicate `above` changes from side0 between lo and hi, bisected to the rounding.
template <class T, class Above>
T bisected_side_change(const Above& above, T lo, T hi, bool side0) noexcept {
  for (int it = 0; it < 200; ++it) {
    const T mid = (lo + hi) / T(2);
    if (!(mid > lo && mid < hi)) break;
    (above(mid) == side0 ? lo : hi) = mid;
  }
  return hi;
}

/// Where the plateau's output (plateau_output, carried from y_from at `from`) passes `level` on
/// [from, to], with the season term: each panel's output at its ends and the rule's nodes, each
/// change of side bisected to the rounding. Found by a scan of the options' ranges:
/// a bright disk dimmed along the scan by the season term (A = -0.63) passed a normalised level of
/// 0.88 on the disk, before Earth-out's locator region, where the chain had said `miss`.
template <class T, class Surface>
plateau_passages<T> plateau_crossings_of(const sensor_physics_head<T>& head,
                                         const scan_circle<T>& circle, const Surface& surface,
                                         const radiance_context<T>& radiance, const T& from,
                                         const T& to, const T& y_from, const T& level) noexcept {
  plateau_passages<T> found{0, 0, T(0), T(0)};
  if (!(to > from)) return found;
  visit_plateau_panels(
      head, circle, surface, radiance, from, to, y_from, [&](const plateau_panel<T>& p) {
        auto above = [&](const T& phi) { return plateau_output(head, p, phi) >= level; };
        T x0 = p.start;
        bool side0 = above(x0);
        for (int i = 0; i <= nodes; ++i) {
          const T x1 = i < nodes ? plateau_node(head, p, i) : T(p.start + p.width);
          const bool side1 = above(x1);
          if (side1 != side0) {
            const T at = bisected_side_change(above, x0, x1, side0);
            if (side1) {
              if (found.rising++ == 0) found.first_rising = at;
            } else {
              ++found.falling;
              found.last_falling = at;
            }
          }
          x0 = x1;
          side0 = side1;
        }
      });
  return found;
}

/// Samples of a window's locator region, `count` per geometric crossing: half towards the sky,
/// spaced quadratically (dense near the crossing, where a grazing scan's heights grow slowly),
/// half towards the disk, uniformly; sorted, inside [root_lo, root_hi]; at most 2 (count + 1)
/// into out.
template <class T>
int window_samples(const pulse_window<T>& w, int count, T* out) noexcept {
  int n = 0;
  const int half = count / 2;
  for (int c = 0; c < w.crossings; ++c) {
    const window_extent<T>& e = w.extent[c];
    for (int i = 0; i <= half; ++i) {
      const T f = T(i) / T(half);
      out[n++] = e.crossing + T(e.sky_sign) * e.sky * f * f;
      if (i > 0) out[n++] = e.crossing - T(e.sky_sign) * e.disk * f;
    }
  }
  sort_ascending(out, n);
  int kept = 0;
  for (int i = 0; i < n; ++i)
    if (out[i] >= w.root_lo && out[i] <= w.root_hi && (kept == 0 || out[i] > out[kept - 1]))
      out[kept++] = out[i];
  return kept;
}

/// The places that bracket the extremes of a window's output and its slope: the locator region's
/// ends and four places in each of the central line's pieces (a polynomial of degree 9 there, or
/// the lag's exponential: a piece holds at most a few extremes), clamped to the region, in order;
/// `piece_place_count` of them.
template <class T>
int piece_place_count(const pulse_window<T>& w) noexcept {
  return 4 * w.line.count + 2;
}

template <class T>
T piece_place(const pulse_window<T>& w, int i) noexcept {
  if (i == 0) return w.root_lo;
  if (i == piece_place_count(w) - 1) return w.root_hi;
  const line_piece<T>& p = w.line.piece[(i - 1) / 4];
  const T x = p.start + p.width * T(2 * ((i - 1) % 4) + 1) / T(8);
  return x < w.root_lo ? w.root_lo : x > w.root_hi ? w.root_hi : x;
}

/// The band of y' that is rounding, not a slope: 1e-10 of the steepest sample's (a plateau's y'
/// lies far below it), for the searches of the output's extremes between samples.
template <class T>
T slope_noise(const lag_point<T>* sampled, int count) noexcept {
  T steepest = T(0);
  for (int i = 0; i < count; ++i) {
    const T magnitude = sampled[i].slope < T(0) ? T(-sampled[i].slope) : sampled[i].slope;
    if (magnitude > steepest) steepest = magnitude;
  }
  return steepest / T(10000000000LL);
}

/// A merged window's disk between its two geometric crossings, where its samples may be far
/// apart (H's band above the surface can leave Earth-in's locator region no disk: a 17 deg pulse
/// sampled nowhere between its crossings): with the season term the output rises and falls more
/// than once there, between two samples whose slopes have one sign. The samples then missed the
/// larger of two maxima (a 1.77 deg circle 39 000 km out, near the nadir: 1.0625 and 1.0466, the
/// smaller taken for the normalised peak, 0.022 deg of chord off the reference) and the dip
/// between them (a fixed threshold between the dip and the maxima: `ok` where the reference says
/// `multiple`). The line's piece places inside each such interval bracket every extreme (y'
/// passing through `noise`'s band), each refined (golden section); their places into out, at most
/// capacity. Between two consecutive extremes y is monotone: with them among the samples the
/// locators see the whole disk.
template <class T>
int merged_disk_extremes(const pulse_window<T>& w, const sensor_physics_head<T>& head, const T* phi,
                         const lag_point<T>* sampled, int count, const T& noise, T* out,
                         int capacity) noexcept {
  if (w.crossings != 2) return 0;
  const T first =
      w.extent[0].crossing < w.extent[1].crossing ? w.extent[0].crossing : w.extent[1].crossing;
  const T last =
      w.extent[0].crossing < w.extent[1].crossing ? w.extent[1].crossing : w.extent[0].crossing;
  auto up = [&](const T& x) { return evaluate_window(w, head, x).output; };
  auto down = [&](const T& x) { return T(-evaluate_window(w, head, x).output); };
  int n = 0;
  auto extreme = [&](const T& lo, const T& hi, const T& slope_lo, const T& slope_hi) {
    if (n >= capacity) return;
    if (slope_lo > noise && slope_hi < -noise) out[n++] = refine_maximum_at(up, lo, hi).phi;
    if (slope_lo < -noise && slope_hi > noise) out[n++] = refine_maximum_at(down, lo, hi).phi;
  };
  const int places = piece_place_count(w);
  int p = 0;
  for (int i = 0; i + 1 < count; ++i) {
    if (phi[i] < first || phi[i + 1] > last) continue;
    while (p < places && !(piece_place(w, p) > phi[i])) ++p;
    T before = phi[i], slope_before = sampled[i].slope;
    for (; p < places && piece_place(w, p) < phi[i + 1]; ++p) {
      const T x = piece_place(w, p);
      const T slope = evaluate_window(w, head, x).slope;
      extreme(before, x, slope_before, slope);
      before = x;
      slope_before = slope;
    }
    if (before > phi[i]) extreme(before, phi[i + 1], slope_before, sampled[i + 1].slope);
  }
  return n;
}

/// MODEL §12's normalised locator takes the largest output anywhere. With the season term the
/// disk brightens along the scan, and the output can peak on the disk's side at the samples' end
/// or beyond them: past the Earth-in window's last sample, or in the Earth-out window's lag
/// history before its first (the benchmark's orbit, at true anomalies 120-122 and 308-316 deg,
/// was up to 2.5e-4 deg off the brute-force reference before; now within 1e-9 deg). The largest
/// sample at an end with the output turning back there (its slope, sampled with it): the end
/// interval is refined. The part of the window beyond the samples on the disk's side (a single
/// crossing's window; a merged one's disk lies between its samples): searched for its value only,
/// the level's (`inside` false: no sample is added outside the locator's region). The sky's side
/// beyond the samples is darker.
template <class T, class Keep>
void keep_disk_side_peak(const pulse_window<T>& w, const sensor_physics_head<T>& head, const T* phi,
                         const lag_point<T>* sampled, int count, int best, Keep& keep) noexcept {
  auto f = [&](const T& x) { return evaluate_window(w, head, x).output; };
  if (best == count - 1 && best > 0 && sampled[best].slope < T(0))
    keep(refine_maximum_at(f, phi[best - 1], phi[best]));
  if (best == 0 && count > 1 && sampled[0].slope > T(0)) keep(refine_maximum_at(f, phi[0], phi[1]));
  if (w.crossings != 1) return;
  const bool disk_after = w.extent[0].sky_sign < 0;  // Earth-in: sky, then disk
  const T lo = disk_after ? phi[count - 1] : w.lo, hi = disk_after ? w.hi : phi[0];
  if (!(hi > lo)) return;
  window_maximum<T> beyond = refine_maximum_at(f, lo, hi);
  beyond.inside = false;
  keep(beyond);
}

/// dy/dphi of a field's window from its pieces alone (evaluate_window's slope without the exact
/// mean it adds without lag): cheap enough to scan every piece.
template <class T>
T piece_slope(const pulse_window<T>& w, const sensor_physics_head<T>& head, const T& phi) noexcept {
  if (head.lag_rad > T(0))
    return lagged_slope(evaluate_line(w.line, head.lag_rad, phi), head.lag_rad);
  if (!w.field) return evaluate_window(w, head, phi).slope;
  T derivatives[2] = {};
  line_derivatives(w.line, phi, derivatives, 2);
  return derivatives[1];
}

/// The output's maxima between the window's piece places (piece_place: four in each piece of the
/// central line): where the pieces' y' falls through 0, the place refined on the pieces. The
/// window's samples, spaced for the crossing, can step over a bump narrower than their spacing
/// where neither neighbour's slope says so. Found by random scans: a 1.72 deg square leaving a
/// flat disk of 0.94 L0 at Earth-out without lag, whose trailing side still reads the limb's
/// bright band: the output peaks at 0.94024, 1e-3 rad wide, between a plateau sample (y' = 0) and
/// a falling one, and the peak taken from Earth-in's smaller bump put both normalised crossings
/// 5.4e-5 deg off the reference; a 0.62 deg square through 0.07 ms of lag (Lambda 1.3e-3 rad)
/// entering a disk of 0.78 L0 under a limb of 1 L0, 30 600 km out: the bright band crossing the
/// field lifts y to 0.81050 between a rising sample and one on the disk's plateau, also rising,
/// and the level came from the plateau's 0.81043 (1.6e-5 deg off at each crossing). With lag the
/// bump's value is the pieces' output, as the samples' are. Without lag a field's is the exact
/// mean's, and it is taken for `top` only where it exceeds it by more than 1e-7 of itself: the
/// margin keeps out the pieces' ringing on a plateau and the exact mean's own error where a
/// circle's tangency meets a knee of a millimetre (up to 3e-8 of L0, which raised the level and
/// moved the crossings off the step's by 4e-11 rad); a bump it leaves out moves a normalised
/// crossing by at most ~1e-7 deg.
template <class T>
void keep_piece_peaks(const pulse_window<T>& w, const sensor_physics_head<T>& head, const T& noise,
                      window_maximum<T>& top) noexcept {
  using std::abs;
  const bool exact = w.field && !(head.lag_rad > T(0));
  if (exact && !w.exact_field_at) return;
  auto pieces = [&](const T& x) {
    return exact ? evaluate_line(w.line, T(0), x).value : evaluate_window(w, head, x).output;
  };
  const int count = piece_place_count(w);
  T before = piece_slope(w, head, piece_place(w, 0));
  for (int i = 0; i + 1 < count; ++i) {
    const T after = piece_slope(w, head, piece_place(w, i + 1));
    if (before > noise && after < -noise) {
      window_maximum<T> m = refine_maximum_at(pieces, piece_place(w, i), piece_place(w, i + 1));
      if (!exact) {
        if (m.value > top.value) top = m;
      } else {
        m.value = w.exact_field_at(w.exact_context, m.phi);
        if (m.value - top.value > abs(top.value) / T(10000000)) top = m;
      }
    }
    before = after;
  }
}

/// A pencil without lag outputs its line's radiance, which jumps at the line's edges (the
/// surface's cut, a step): its largest value near one is a one-sided limit there, wherever the
/// samples lie. Both sides of every edge are candidates (found by a random scan: a limb of 0.75
/// L0 at the surface above a disk of 0.68 L0 that the season term brightens along the scan; the
/// samples' largest lay on the disk, 0.705 against the limb's 0.778 at the cut, and the
/// normalised level was taken from it: 0.062 deg off the reference at each crossing).
template <class T, class Keep>
void keep_jump_sides(const pulse_window<T>& w, const sensor_physics_head<T>& head,
                     Keep& keep) noexcept {
  if (!w.pencil || head.lag_rad > T(0) || !w.line.jumps) return;
  const line_signal<T>& line = w.line;
  const T side = w.lattice_step / T(1000000000);
  for (int e = 0; e < line.edges; ++e) {
    if (!(line.edge[e] > w.lo && line.edge[e] < w.hi)) continue;
    for (int k = -1; k <= 1; k += 2) {
      const T x = line.edge[e] + T(k) * side;
      keep(window_maximum<T>{evaluate_window(w, head, x).output, x, true});
    }
  }
}

/// The largest output over a window's samples and between them, refined where it is inside (then
/// `inside`, with its place). Every maximum, not the largest sample's alone: y' falling through 0
/// between two samples (each sample's slope is known), or a sample above both neighbours (where y
/// jumps: a pencil without lag). A merged window's samples lie far apart on the disk, and with the
/// season term the output can peak a few Lambda past Earth-in, where the disk is brightest,
/// between two samples and above the largest sample elsewhere (a 0.18 deg square with 1.5 deg of
/// Lambda: 1.0482 against 1.0464, 2.5e-3 deg of chord off the reference before). `dim_disk`: the
/// disk is dimmer than the limb just above the surface, so the output may peak between the last
/// sky sample and the surface's jump, beside a run of samples on the disk's plateau taken for the
/// largest: the intervals on both sides of that run are refined too.
template <class T>
window_maximum<T> window_peak(const pulse_window<T>& w, const sensor_physics_head<T>& head,
                              const T* phi, const T* y, const lag_point<T>* sampled, int count,
                              bool dim_disk) noexcept {
  using std::abs;
  int best = 0;
  for (int i = 1; i < count; ++i)
    if (y[i] > y[best]) best = i;
  window_maximum<T> top{y[best], phi[best], false};
  auto f = [&](const T& x) { return evaluate_window(w, head, x).output; };
  auto keep = [&top](const window_maximum<T>& m) {
    if (m.value > top.value) top = m;
  };
  // A plateau's y' is rounding, far below 1e-10 of the steepest sample's; a sample above its
  // neighbours by rounding only (a plateau flat to 1e-16) is not a maximum worth refining either.
  const T noise = slope_noise(sampled, count);
  auto falls = [&](int i) {
    return i >= 0 && i + 1 < count && sampled[i].slope > noise && sampled[i + 1].slope < -noise;
  };
  for (int i = 0; i + 1 < count; ++i)
    if (falls(i)) keep(refine_maximum_at(f, phi[i], phi[i + 1]));
  for (int i = 1; i + 1 < count; ++i) {
    const T lower = y[i - 1] < y[i + 1] ? y[i - 1] : y[i + 1];
    if (y[i] >= y[i - 1] && y[i] >= y[i + 1] && !falls(i - 1) && !falls(i) &&
        y[i] - lower > T(1) / T(1000000000000LL) * abs(y[i]))
      keep(refine_maximum_at(f, phi[i - 1], phi[i + 1]));
  }
  keep_disk_side_peak(w, head, phi, sampled, count, best, keep);
  keep_piece_peaks(w, head, noise, top);
  keep_jump_sides(w, head, keep);
  if (dim_disk) {
    int last = best;
    while (last + 1 < count && !(y[last + 1] < y[best])) ++last;
    if (best > 0) keep(refine_maximum_at(f, phi[best - 1], phi[best]));
    if (last + 1 < count) keep(refine_maximum_at(f, phi[last], phi[last + 1]));
  }
  return top;
}

/// The largest slope in [lo, hi] (a bracket of the largest sample of the slope): the root of the
/// curvature by the Illinois method where it falls through 0 there, else golden section on the
/// slope (a kink of the signal). Shared by every locator of the chain.
template <class T, class Curvature, class Slope>
T slope_maximum(const Curvature& curvature, const Slope& slope, T lo, T hi) noexcept {
  T clo = curvature(lo), chi = curvature(hi);
  if (!(clo > T(0) && chi < T(0))) return golden_maximum_place(slope, lo, hi);
  int side = 0;
  for (int it = 0; it < 100; ++it) {
    const T m = (lo * chi - hi * clo) / (chi - clo);
    const T cm = curvature(m);
    // The root itself: kept as the bracket's end, it made every later secant step land on it
    // again (the other end only halved), and the bracket's middle was returned after the last
    // step, half the bracket off (a 12.95 deg circle's flat extremum: 6.8e-7 rad, 3.9e-5 deg).
    if (cm == T(0)) return m;
    if (cm > T(0)) {
      lo = m;
      clo = cm;
      if (side == -1) chi = chi / T(2);
      side = -1;
    } else {
      hi = m;
      chi = cm;
      if (side == 1) clo = clo / T(2);
      side = 1;
    }
    using std::abs;
    if (!(hi - lo > T(4) * std::numeric_limits<T>::epsilon() * (abs(m) > T(1) ? abs(m) : T(1))))
      break;
  }
  return T((lo + hi) / T(2));
}

/// Where the slope locator's crossing may lie in a window: its extremum is sought on the
/// crossing's own side of the turn (MODEL §12). A merged window holds both crossings: Earth-in's
/// extremum lies before the middle of their geometric azimuths, Earth-out's after it (a disk
/// dimmer than the limb rises again towards Earth-out, and a rise there is not the Earth-in
/// crossing however steep). A window of one crossing ends at its locator's samples.
template <class T>
bool on_crossing_side(const pulse_window<T>& w, int sign, const T& x) noexcept {
  const T middle = w.crossings == 2 ? T((w.extent[0].crossing + w.extent[1].crossing) / T(2))
                                    : T(sign > 0 ? w.root_hi : w.root_lo);
  return sign > 0 ? !(x > middle) : !(x < middle);
}

/// With lag a pencil's y' = (s - y) / Lambda jumps where s does (the surface's cut, a step):
/// its one-sided values there are candidates for the extremum that samples of y' step over
/// (found by a randomized scan: the knee's smaller extremum taken at Earth-out, 0.08 deg off the
/// reference's cut). The edge whose side exceeds the continuous extremum `value` at `place` is
/// the crossing (MODEL §12: the extremum of dy/dphi), else `place`; only an edge on the
/// crossing's side of the turn (a dark disk's cut at Earth-out, where y' jumps up, had been taken
/// for Earth-in, and Earth-in's cut for Earth-out: the crossings swapped).
template <class T>
T steeper_edge(const pulse_window<T>& w, const sensor_physics_head<T>& head, int sign,
               const T& place, const T& value) noexcept {
  if (!w.pencil || !(head.lag_rad > T(0)) || !w.line.jumps) return place;
  const line_signal<T>& line = w.line;
  T best = value, at = place;
  const T side = w.lattice_step / T(1000000000);
  for (int e = 0; e < line.edges; ++e) {
    if (!(line.edge[e] > w.root_lo && line.edge[e] < w.root_hi) ||
        !on_crossing_side(w, sign, line.edge[e]))
      continue;
    for (int k = -1; k <= 1; k += 2) {
      const T v = T(sign) * evaluate_window(w, head, T(line.edge[e] + T(k) * side)).slope;
      if (v > best) {
        best = v;
        at = line.edge[e];
      }
    }
  }
  return at;
}

/// sign s'' of a field's window without lag at phi, from its exact mean read in the polish's
/// scalar (polish_scalar), by sixth-order differences of step e: on a knee narrower than the
/// usual step (polish_slope_maximum), where the step must shrink to a fraction of the knee and
/// the differences' rounding grows as 1/e^2. Sixth order, as the profile's bright side is
/// sharper than H (l's density falls as e^-v, v = ln 2 e^-z): fourth-order differences at an
/// eighth of H's width along the scan left 4e-8 deg (a 0.29 deg square on H = 218 m), sixth-order
/// 1e-9, at the same rounding.
template <class T>
T wide_mean_curvature(const pulse_window<T>& w, int sign, const T& phi, const T& e) noexcept {
  using W = polish_scalar_t<T>;
  auto s = [&](const W& x) { return w.polish_field_at(w.polish_context, x); };
  const W at = W(phi), step = W(e);
  const W m3 = s(W(at - W(3) * step)), m2 = s(W(at - W(2) * step)), m1 = s(W(at - step));
  const W c = s(at), p1 = s(W(at + step)), p2 = s(W(at + W(2) * step)), p3 = s(W(at + W(3) * step));
  return T(sign) * T((W(2) * (m3 + p3) - W(27) * (m2 + p2) + W(270) * (m1 + p1) - W(490) * c) /
                     (W(180) * step * step));
}

/// sign y'' of a field's window at phi from its exact mean s (field_signal_at): without lag s''
/// by fourth-order differences of step e; with it (s' - y') / Lambda, s' by the same differences
/// and y' = (s - y) / Lambda, y the chain's; `wide`: wide_mean_curvature's (no lag). The pieces'
/// own y'' carries their interpolation error twice differentiated: at a broad, flat extremum of
/// the slope (H of tens of km, a field of a degree or more) 3e-5 of its size, which moved the
/// slope locator by up to 4e-5 deg against the brute-force reference; the exact mean's
/// differences hold it to ~1e-10 of it.
template <class T>
T exact_slope_curvature(const pulse_window<T>& w, const sensor_physics_head<T>& head, int sign,
                        const T& phi, const T& e, bool wide = false) noexcept {
  if (wide) return wide_mean_curvature(w, sign, phi, e);
  auto s = [&](const T& x) { return w.exact_field_at(w.exact_context, x); };
  const T m2 = s(T(phi - T(2) * e)), m1 = s(T(phi - e)), c = s(phi), p1 = s(T(phi + e)),
          p2 = s(T(phi + T(2) * e));
  const T lag = head.lag_rad;
  if (!(lag > T(0))) return T(sign) * (T(16) * (m1 + p1) - (m2 + p2) - T(30) * c) / (T(12) * e * e);
  const T first = (T(8) * (p1 - m1) - (p2 - m2)) / (T(12) * e);
  const T y = evaluate_window(w, head, phi).output;
  return T(sign) * (first - (c - y) / lag) / lag;
}

/// The root of exact_slope_curvature of step e near `from` by the secant method, within `reach`
/// of `place`, until it moves by less than 2e-10 rad: true with the root `at` and the secant's last
/// slope of the curvature `rate` (per rad); false where it leaves the reach or does not settle.
template <class T>
bool exact_curvature_root(const pulse_window<T>& w, const sensor_physics_head<T>& head, int sign,
                          const T& from, const T& e, const T& place, const T& reach, T& at, T& rate,
                          bool wide = false) noexcept {
  using std::abs;
  T x0 = from, x1 = T(from + e);
  T g0 = exact_slope_curvature(w, head, sign, x0, e, wide);
  T g1 = exact_slope_curvature(w, head, sign, x1, e, wide);
  for (int it = 0; it < 16; ++it) {
    if (!(g1 != g0)) return false;
    rate = (g1 - g0) / (x1 - x0);
    const T x2 = x1 - g1 / rate;
    if (!(abs(T(x2 - place)) < reach)) return false;
    if (abs(T(x2 - x1)) < T(2) / T(10000000000LL) * (T(1) + abs(x2))) {
      at = x2;
      return true;
    }
    x0 = x1;
    g0 = g1;
    x1 = x2;
    g1 = exact_slope_curvature(w, head, sign, x1, e, wide);
  }
  return false;
}

/// How far the exact mean's rounding (some 1e-14 of it) can move the root of
/// exact_slope_curvature with lag at step e: s' by differences carries 1.5 / e of it, y'' that
/// over Lambda, and the root that over the curvature's rate (per rad). Measured on two sharp
/// limbs (H of 66 and 575 m at steps of 5e-7 rad): the root moved 3e-10 to 1e-9 rad between a
/// step and its eighth, within this bound at the eighth.
template <class T>
T polish_rounding(const pulse_window<T>& w, const sensor_physics_head<T>& head, const T& at,
                  const T& e, const T& rate) noexcept {
  using std::abs;
  const T mean = evaluate_window(w, head, at).mean;
  return T(T(3) / T(200000000000000LL)) * abs(mean) / (e * head.lag_rad * abs(rate));
}

/// How far the exact mean's rounding in T, up to 2e-13 of it far out (polish_scalar), can move the
/// root of exact_slope_curvature without lag at step e: s'' by fourth-order differences carries
/// 16/3 of it over e^2, the root that over the curvature's rate (per rad).
template <class T>
T flat_extremum_rounding(const pulse_window<T>& w, const sensor_physics_head<T>& head, const T& at,
                         const T& e, const T& rate) noexcept {
  using std::abs;
  const T mean = evaluate_window(w, head, at).mean;
  return T(T(16) / T(3) * T(2) / T(10000000000000LL)) * abs(mean) / (e * e * abs(rate));
}

/// The root of exact_slope_curvature of step e near `place` where the secant left its reach: on
/// a flat extremum the pieces' y'' can place the root further off than a thousandth of a lattice
/// step (a 0.40 deg square on H = 3.8 km, 23 800 km out: 1.8e-5 rad, 19 thousandths; the pieces'
/// place was kept, 1.0e-3 deg off the brute-force reference). Steps from `place` the way the
/// curvature points, doubling from `first_step` up to `limit`, until sign y'' falls through 0;
/// then the bracket's root (slope_maximum). True with the root `at` and the bracket's rate of the
/// curvature (per rad); false where no such bracket lies within `limit` or a value is not finite.
template <class T>
bool bracketed_curvature_root(const pulse_window<T>& w, const sensor_physics_head<T>& head,
                              int sign, const T& place, const T& e, const T& first_step,
                              const T& limit, T& at, T& rate, bool wide) noexcept {
  auto curvature = [&](const T& x) { return exact_slope_curvature(w, head, sign, x, e, wide); };
  auto slope = [&](const T& x) { return T(T(sign) * piece_slope(w, head, x)); };
  T near = place, near_value = curvature(place);
  if (!is_finite(near_value)) return false;
  const bool rightwards = near_value > T(0);  // sign y' still rising: the maximum lies ahead
  for (T step = first_step; !(step > limit); step = T(step * T(2))) {
    const T far = rightwards ? T(place + step) : T(place - step);
    const T far_value = curvature(far);
    if (!is_finite(far_value)) return false;
    if ((far_value > T(0)) != rightwards) {
      const T lo = rightwards ? near : far, hi = rightwards ? far : near;
      rate = T((rightwards ? T(far_value - near_value) : T(near_value - far_value)) / T(hi - lo));
      at = slope_maximum(curvature, slope, lo, hi);
      return is_finite(at);
    }
    near = far;
    near_value = far_value;
  }
  return false;
}

/// polish_slope_maximum's state: the differences' step e, the secant's reach and its centre, the
/// root found so far and the curvature's rate there (per rad), and whether the mean is read in
/// the wider scalar (wide_mean_curvature).
template <class T>
struct slope_polish {
  T e, reach, centre, at, rate;
  bool wide = false;
};

/// The finest step polish_slope_maximum's differences take: 2^-16 of a lattice step.
template <class T>
T finest_polish_step(const pulse_window<T>& w) noexcept {
  return w.lattice_step / T(65536);
}

/// polish_slope_maximum's differences at `place`: their step and scalar; false where the knee is
/// too narrow for them (the pieces' place then stands).
template <class T>
bool slope_polish_plan(const pulse_window<T>& w, const sensor_physics_head<T>& head, const T& place,
                       slope_polish<T>& p) noexcept {
  using std::abs;
  // With lag only s' is differenced (its rounding 1/e): a finer step (measured: 3e-9 deg at
  // 1/256 against 3e-8 at 1/128 on a 1.2 deg circle with H = 26 km and 1.8 ms at 4 rev/s).
  p.reach = w.lattice_step / T(1000);
  p.e = w.lattice_step / T(head.lag_rad > T(0) ? 256 : 128);
  // The differences hold where the limb's knee, H of height, spans at least eight steps of them
  // along the scan. Where it does not, the step shrinks to a fraction of the knee, down to 2^-16
  // of a lattice step, if the mean's rounding allows: with lag, whose s' alone is differenced
  // (rounding ~1e-14 / e in double), to an eighth of the knee (a 2.25 deg circle through 2 ms of
  // lag on H = 575 m, 32 000 km out, whose flat extremum the pieces' y'' had placed 1.1e-5 deg
  // off the reference, is within 1e-8 deg of it; two wide fields far out, 1.4e-6 and 2e-6 deg
  // off, within 1e-9); without lag, s'' (rounding / e^2), to an eighth of the knee where a
  // square's mean can be read in a wider scalar than T (wide_mean_curvature; in double the
  // differences there moved a 1.4 deg square on H = 100 m by 1e-4 times their step, and such a limb
  // is left to the pieces: flat-topped slopes far out 1.2e-6 to 1.4e-6 deg off the reference,
  // within 1.5e-8 in long double).
  const T finest = finest_polish_step(w);
  T height = T(0), rate = T(0);
  w.geometry.height_slope(place, height, rate);
  const bool lag = head.lag_rad > T(0);
  const bool narrow = !(head.profile.scale_m > T(8) * p.e * abs(rate));
  if (narrow) {
    if (!lag && !(polish_is_wider<T> && w.polish_field_at)) return false;
    p.e = head.profile.scale_m / (T(8) * abs(rate));
    if (!(p.e > finest)) return false;
  }
  // Without lag on such a knee a square's mean is read in the wider scalar, sixth-order
  // differences. A circle keeps the pieces' root: read so, two of them moved 4e-8 deg away from
  // the reference (0.63 and 2.2 deg circles on H of 2 and 12 m), none nearer, and their rows
  // cost up to six times more (its exact mean is the dearer, and long double is x87's).
  p.wide = narrow && !lag;
  return !(p.wide && head.settings.field.shape == field_shape::circle);
}

/// The root of the exact mean's curvature near the pieces' `place` (exact_curvature_root, or
/// bracketed_curvature_root where the secant leaves its reach, within an eighth of a lattice
/// step; the later steps then keep to the reach about it), found again in the wider scalar where
/// the rounding in T moves it; false where none is found.
template <class T>
bool slope_polish_root(const pulse_window<T>& w, const sensor_physics_head<T>& head, int sign,
                       const T& place, slope_polish<T>& p) noexcept {
  const bool lag = head.lag_rad > T(0);
  p.at = place;
  p.rate = T(0);
  p.centre = place;
  auto bracketed = [&](bool wide_scalar) {
    const bool ok = bracketed_curvature_root(w, head, sign, place, p.e, p.reach,
                                             T(w.lattice_step / T(8)), p.at, p.rate, wide_scalar);
    if (ok) p.centre = p.at;
    return ok;
  };
  // A flat extremum (s''' small: a wide field's slope on a limb some km thick, far out) is moved
  // by the differences' rounding in T by more than 1e-10 rad, or the secant wanders off: without
  // lag, where a square's mean can be read in the wider scalar, its root is found again there,
  // sixth-order differences (a 1.84 deg square on H = 10 km, 30 000 km out: Earth-out 1.4e-4 deg
  // off the reference in double, the root not found; 1.9e-8 deg so).
  const bool wider_retry = !p.wide && !lag && polish_is_wider<T> && w.polish_field_at;
  bool found =
      exact_curvature_root(w, head, sign, place, p.e, place, p.reach, p.at, p.rate, p.wide);
  if (!found && !wider_retry) found = bracketed(p.wide);
  if (wider_retry &&
      (!found || flat_extremum_rounding(w, head, p.at, p.e, p.rate) > T(1) / T(10000000000LL))) {
    T again = p.at;
    if (!exact_curvature_root(w, head, sign, found ? p.at : place, p.e, p.centre, p.reach, again,
                              p.rate, true)) {
      if (!bracketed(true)) return false;
      again = p.at;
    }
    p.at = again;
    p.wide = true;
    return true;
  }
  return found;
}

/// Without lag on such a knee, a kink of s' finer than it (a corner meeting the surface's cut
/// under a dimmer disk) moves the root with the step, by a fraction of it: the root is found
/// again at half the step, and false (the pieces' place kept) where it moved by more than a
/// sixteenth of the step (a 0.45 deg square on H = 8 m, delta50 72 km over a disk of 0.61: s'
/// peaks on the corner's contact with the surface, and the root at a quarter of the knee was
/// 8.8e-6 deg off the reference; there it moves by 0.3 of the step). A smooth extremum's root
/// moves by far less (the flattest found, 7e-10 rad at a step of 1.2e-7), and the first is kept:
/// the half step's rounding is four times its.
template <class T>
bool slope_polish_holds_at_half_step(const pulse_window<T>& w, const sensor_physics_head<T>& head,
                                     int sign, const slope_polish<T>& p) noexcept {
  using std::abs;
  T again = p.at, again_rate = p.rate;
  return exact_curvature_root(w, head, sign, p.at, T(p.e / T(2)), p.centre, p.reach, again,
                              again_rate, true) &&
         !(abs(T(again - p.at)) > p.e / T(16));
}

/// With lag, a kink of s' (a corner of the patch meeting the surface's cut under a brighter
/// disk) within the differences' reach moves their root by up to their step: the root is
/// checked at an eighth of the step and found again there while it moves by more than the
/// finer step's rounding could move it (a 1.5 deg square through 0.27 ms of lag on H = 2 km,
/// 14 000 km out: 1.5e-5 deg off the reference, the kink 5e-6 rad from the extremum, now within
/// 1e-9; a 0.08 deg square through 2.5 ms, 4.4e-7 deg, now 1e-12). Without lag s'' is
/// differenced, whose rounding 1/e^2 forbids a finer step; the kink there is the pieces' check
/// (polish_slope_maximum). False where a finer root is not found.
template <class T>
bool slope_polish_past_kink(const pulse_window<T>& w, const sensor_physics_head<T>& head, int sign,
                            slope_polish<T>& p) noexcept {
  using std::abs;
  const T finest = finest_polish_step(w);
  for (int refinement = 0; refinement < 3 && head.lag_rad > T(0) && p.e / T(8) > finest;
       ++refinement) {
    const T finer = p.e / T(8);
    const T moved = exact_slope_curvature(w, head, sign, p.at, finer) / p.rate;
    if (!(abs(moved) > T(2) / T(10000000000LL) * (T(1) + abs(p.at)) &&
          abs(moved) > T(4) * polish_rounding(w, head, p.at, finer, p.rate)))
      break;
    p.e = finer;
    const T from = p.at;
    if (!exact_curvature_root(w, head, sign, from, p.e, p.centre, p.reach, p.at, p.rate))
      return false;
  }
  return true;
}

/// The slope's extremum near `place` (the root of the pieces' y''), polished as the root of the
/// exact mean's (exact_slope_curvature) by the secant method, within a thousandth of a lattice
/// step of it (the pieces' own error is far less; a tenth let the secant reach other roots, 4e-3
/// deg away), until it moves by less than 2e-10 rad, and kept where y'' falls through 0 there (a
/// maximum): a field on a smooth profile only (a step's mean has kinks, where differences do not
/// hold, and its pieces are exact between them). The differences' step without lag, 1/128 of a
/// lattice step, balances their truncation (1e-6 deg at 1/32 on a 1.3 deg square with H = 1.6
/// km) against the exact mean's rounding (~1e-14, amplified by 1/e^2: 6e-8 deg at 1/256);
/// measured there within 1e-8 deg of the reference. Where the secant leaves the reach the root is
/// bracketed within an eighth of a lattice step (bracketed_curvature_root). `place` itself where
/// neither finds a root, the secant does not settle, or the root is no maximum or one the pieces
/// find less steep by more than 1e-7 of the slope (a kink of s near the extremum).
template <class T>
T polish_slope_maximum(const pulse_window<T>& w, const sensor_physics_head<T>& head, int sign,
                       const T& place) noexcept {
  using std::abs;
  if (!w.field || !w.exact_field_at || !(head.profile.scale_m > T(0))) return place;
  slope_polish<T> p;
  if (!slope_polish_plan(w, head, place, p) || !slope_polish_root(w, head, sign, place, p) ||
      (p.wide && !slope_polish_holds_at_half_step(w, head, sign, p)) ||
      !slope_polish_past_kink(w, head, sign, p))
    return place;
  // A maximum of y' (y'' falling through 0 there), not a minimum the secant also finds.
  const bool maximum = exact_slope_curvature(w, head, sign, T(p.at - p.e), p.e, p.wide) > T(0) &&
                       exact_slope_curvature(w, head, sign, T(p.at + p.e), p.e, p.wide) < T(0);
  // Nor a place the pieces find less steep than their own extremum by more than their
  // error: a kink of s' (a corner of the patch meeting the surface's cut) next to it, whose
  // differences give a root e away (a 0.91 deg square on H = 43 km over a brighter disk:
  // 6.6e-6 rad from the kink, y' 1.9e-4 of itself lower, 3.8e-4 deg off the reference).
  const T steepest = T(sign) * piece_slope(w, head, place);
  const bool steeper =
      !(steepest - T(sign) * piece_slope(w, head, p.at) > abs(steepest) / T(10000000));
  return maximum && steeper ? p.at : place;
}

/// MODEL §12's slope rule for a pencil without lag, whose output jumps (at the surface's cut, at a
/// step): the jump is the crossing only where the extremum of the continuous part of dy/dphi lies
/// beyond the cut, that is where the continuous part is steeper at the cut, on its sky side, than
/// at its steepest place on this side of the pulse (`continuous`, the samples' refined maximum of
/// sign y'): a limb whose steepest point, delta50 - 0.367 H, lies below the surface, or just above
/// it where the season term's L0' steepens the limb towards the cut. Decided by the slopes, not by
/// the sign of y'' at the cut: a limb 32 H above the surface is flat there but for the season
/// term's L0'', whose sign says nothing about the limb (found by a random scan: the cut taken,
/// 0.011 deg off the reference, for a limb 406 m up under A = 0.044). Continuous in delta50: as
/// the limb's steepest point descends to the cut the two slopes meet there.
template <class T>
bool jump_is_steepest(const pulse_window<T>& w, const sensor_physics_head<T>& head, const T& edge,
                      int sign, const T& continuous) noexcept {
  // The sky side: before the edge at Earth-in (sign +1), after it at Earth-out.
  const T sky = edge - T(sign) * w.lattice_step / T(1000000);
  return !(continuous > T(sign) * evaluate_window(w, head, sky).slope);
}

/// A bracket's end `to` for the continuous part's extremum near the sample at `from`, moved back
/// to this side of the output's jumps between them (a millionth of a lattice step short): beyond a
/// jump the refinement reads another branch of y' (the disk's, after the surface's cut), and a
/// limb whose steepest point lies within a sample's spacing above the cut was refined onto the
/// disk's slope (found by sweeping delta50 through 0.367 H: the cut taken, 2e-5 deg off, where
/// the limb's extremum was the steeper). Every jump, whichever way it goes: a dark disk's cut at
/// Earth-out jumps up, and the falling limb's extremum refined across it ended on the disk, whose
/// y' is 0 (0.13 deg off the reference). `jumps`: the output jumps (a pencil without lag).
template <class T>
T sky_side_of_jumps(const pulse_window<T>& w, bool jumps, const T& from, T to) noexcept {
  if (!jumps) return to;
  const line_signal<T>& line = w.line;
  const T margin = w.lattice_step / T(1000000);
  for (int e = 0; e < line.edges; ++e) {
    const T edge = line.edge[e];
    if (from < edge && edge < to) to = edge - margin > from ? T(edge - margin) : from;
    if (to < edge && edge < from) to = edge + margin < from ? T(edge + margin) : from;
  }
  return to;
}

/// A continuous extremum refined up to a jump of the output, where sky_side_of_jumps stopped its
/// bracket a margin short: sign y' is greatest at the cut itself, on the limb's side, and the cut
/// is the crossing (MODEL §12: the extremum of dy/dphi's continuous part; a limb whose steepest
/// point lies below the surface). `jumps`: the output jumps (a pencil without lag).
template <class T>
T onto_adjacent_edge(const pulse_window<T>& w, bool jumps, const T& place) noexcept {
  using std::abs;
  if (!jumps) return place;
  const T reach = T(2) * w.lattice_step / T(1000000);
  for (int e = 0; e < w.line.edges; ++e)
    if (!(abs(T(place - w.line.edge[e])) > reach)) return w.line.edge[e];
  return place;
}

/// The jump of a pencil without lag's output in the locator's direction (sign: +1 rising at
/// Earth-in, -1 falling at Earth-out) that MODEL §12's slope rule may take: with a step profile
/// (H = 0) above the surface, the step's (the limit of the limb's extremum as H -> 0, whatever
/// the cut's size: a disk brighter than 2 L0 jumps more at the cut, which made the crossing jump
/// by 0.011 deg between H = 0 and 1 mm), else the largest (the cut's), on the crossing's side of
/// the turn; -1 for none or where the output does not jump (a field, a lag).
template <class T>
int slope_jump(const pulse_window<T>& w, const sensor_physics_head<T>& head, int sign) noexcept {
  using std::abs;
  if (!w.pencil || head.lag_rad > T(0) || !w.line.jumps) return -1;
  const line_signal<T>& line = w.line;
  const T offset = head.profile.offset_m;
  const bool step = !(head.profile.scale_m > T(0)) && offset > T(0);
  int largest = -1;
  for (int e = 0; e < line.edges; ++e) {
    if (!(T(sign) * line.jump[e][0] > T(0)) || !on_crossing_side(w, sign, line.edge[e])) continue;
    if (step) {
      const T height = w.geometry.height_at(line.edge[e]);
      if (abs(T(height - offset)) < abs(height)) return e;  // the step's edge, not the cut's
    }
    if (largest < 0 || T(sign) * line.jump[e][0] > T(sign) * line.jump[largest][0]) largest = e;
  }
  return largest;
}

/// The slope locator: the extremum of sign y' over a window, found where y'' changes sign (a
/// root, well conditioned, where the extremum itself is flat: a relative error e of y' would move
/// its maximum by sqrt(e) of the knee's width). Samples of sign y', four in each of the line's
/// pieces, bracket its local maxima; inside each, the root of sign y'' by the Illinois method;
/// where y'' does not change sign there (the extremum is at a jump of y': a step edge without lag),
/// golden section on sign y'. miss when sign y' is never positive.
template <class T>
result<T> steepest_place(const pulse_window<T>& w, const sensor_physics_head<T>& head,
                         int sign) noexcept {
  // A pencil without lag outputs its line's radiance, which jumps where the line meets the
  // surface (and at delta50 for a step): y' is infinite there. MODEL §12 takes the jump only
  // where the continuous part's extremum lies beyond it (jump_is_steepest); with a step profile
  // (H = 0) the continuous part's extremum is the step itself (slope_jump). The continuous part
  // is the limb's, on the sky's side of the jump: beyond it the disk's season term rises too,
  // and a limb whose steepest point lies 41 km below the surface (its slope at the cut 6e-4 of
  // L0 a radian) had the disk's rise (0.9 a radian) taken, 2 deg inside the disk.
  const int jump = slope_jump(w, head, sign);
  if (jump >= 0 && !(head.profile.scale_m > T(0))) return result<T>::good(w.line.edge[jump]);
  const bool jumps = w.pencil && !(head.lag_rad > T(0)) && w.line.jumps;
  auto curvature = [&](const T& x) { return T(T(sign) * evaluate_window(w, head, x).curvature); };
  auto slope = [&](const T& x) { return T(T(sign) * evaluate_window(w, head, x).slope); };
  // sign y' at the places that bracket its maxima, in order: four places in each of the line's
  // pieces (y' is a polynomial of degree 9 there, or the lag's exponential). Two edges close in
  // height under a wide field (a step 1 km above a dimmer disk, a 2 deg square) give y' two
  // maxima of nearly one size, the larger between two samples that missed it (found by a random
  // scan: 0.125 deg off the reference at Earth-out); a piece holds at most a few. A pencil's
  // pieces too, not the window's samples: behind a sharp limb (H = 79 m) its lagged y' peaks
  // within a few H of height, which samples spaced for the crossing stepped over (0.047 deg off
  // the reference at Earth-in, the extremum taken on the decay after it).
  const int count = piece_place_count(w);
  auto place_at = [&](int i) { return piece_place(w, i); };
  auto value_at = [&](int i) {
    const T x = place_at(i);
    if (!on_crossing_side(w, sign, x)) return T(-1);
    if (jump >= 0 && T(sign) * (x - w.line.edge[jump]) > T(0)) return T(-1);  // beyond the cut
    return T(T(sign) * piece_slope(w, head, x));
  };
  T largest = T(0);
  for (int i = 0; i < count; ++i) {
    const T v = value_at(i);
    if (v > largest) largest = v;
  }
  if (!(largest > T(0)))
    return jump >= 0 ? result<T>::good(w.line.edge[jump]) : result<T>::bad(status::miss);
  // Every local maximum within half the largest is refined; the largest refined slope wins.
  T place = place_at(0), best = T(-1), before = T(-1), here = value_at(0);
  for (int i = 0; i < count; ++i) {
    const T after = i + 1 < count ? value_at(i + 1) : T(-1);
    if (here > before && !(after > here) && !(here < largest / T(2))) {
      const T candidate = slope_maximum(
          curvature, slope, sky_side_of_jumps(w, jumps, place_at(i), place_at(i > 0 ? i - 1 : 0)),
          sky_side_of_jumps(w, jumps, place_at(i), place_at(i + 1 < count ? i + 1 : count - 1)));
      const T value = slope(candidate);
      if (value > best) {
        best = value;
        place = candidate;
      }
    }
    before = here;
    here = after;
  }
  place = polish_slope_maximum(w, head, sign, place);
  const T steepest = slope(place);
  if (jump >= 0 && jump_is_steepest(w, head, w.line.edge[jump], sign, steepest))
    return result<T>::good(w.line.edge[jump]);
  return result<T>::good(
      steeper_edge(w, head, sign, onto_adjacent_edge(w, jumps, place), steepest));
}

/// Level crossings among samples (rising, falling) after (before) a place.
template <class T>
void count_crossings(const T* y, int count, const T& level, int& rising, int& falling) noexcept {
  rising = falling = 0;
  for (int i = 0; i + 1 < count; ++i) {
    if (y[i] < level && y[i + 1] >= level) ++rising;
    if (y[i] >= level && y[i + 1] < level) ++falling;
  }
}

}  // namespace physics_detail

namespace physics_detail {

/// Whether every radiance the scan can see is fainter than faintest_pulse: the brighter of the
/// disk and the limb at the surface, l(0) (the limb's brightest visible point), times the season
/// factor's least value over latitudes.
template <class T>
bool pulse_too_faint(const sensor_physics_head<T>& head, const T& sin_sun_declination) noexcept {
  using std::abs;
  const sensor_physics_settings<T>& s = head.settings;
  const T limb = limb_fraction(head.profile, T(0));
  const T brightest = s.disk > limb ? s.disk : limb;
  const T least_season =
      season_factor(T(-abs(s.season_amplitude)), T(1), T(abs(sin_sun_declination)));
  return !(brightest * least_season >= faintest_pulse<T>());
}

/// The row's own checks (MODEL §7, §12): ok, or the status the chain returns at once.
template <class T, class Surface>
status row_status(const sensor_physics_head<T>& head, const scan_circle<T>& circle,
                  const Surface& surface, const T& sin_sun_declination,
                  const crossings<T>& geometric) noexcept {
  using std::abs;
  using std::atan2;
  using std::sin;
  using std::sqrt;
  if (head.state != status::ok || circle.state != status::ok || surface.state != status::ok)
    return status::invalid;
  if (geometric.state != status::ok) return geometric.state;
  const sensor_physics_settings<T>& s = head.settings;
  const T sin_obliquity = sin(T(2344) / T(100) * (pi<T>() / T(180)));
  if (!is_finite(sin_sun_declination) ||
      !(abs(s.season_amplitude * sin_sun_declination) < sin_obliquity))
    return status::invalid;  // a season factor <= 0
  const T gamma = atan2(circle.sin_gamma, circle.cos_gamma);
  const T sigma =
      atan2(T(sqrt(circle.axis.x * circle.axis.x + circle.axis.y * circle.axis.y)), circle.axis.z);
  if (!(s.field.fov_rad / T(2) < gamma - sigma)) return status::invalid;  // the field reaches S
  if (s.field.fov_rad > T(0) &&
      !(T(2) * field_half_along(s.field, circle.sin_gamma) < geometric.chord()))
    return status::grazing;  // the pulse narrower than the field
  // The lag is integrated from y = s over lag_history before the pulse, which must then be sky:
  // a memory longer than the sky's arc would carry the previous turn's pulse into this one.
  if (!(lag_history(head.lag_rad) <= T(2) * pi<T>() - geometric.chord())) return status::invalid;
  if (pulse_too_faint(head, sin_sun_declination)) return status::miss;
  return status::ok;
}

/// How high up the sky the locator's region reaches: where the profile is a tenth of the
/// smallest level it may look for (smallest_level_fraction), at least the knee's top (the slope
/// locator's), within the band.
template <class T>
T locator_reach(const sensor_physics_head<T>& head, const profile_band<T>& band) noexcept {
  T top = band.knee_high;
  const T fraction = T(smallest_level_fraction(head) / T(10));
  if (fraction > T(0) && fraction < T(1)) {
    const T height = fixed_threshold_height(head.profile, fraction);
    if (height > top) top = height;
  }
  return top > band.band_high ? band.band_high : top;
}

/// The edges each crossing's line is expected to meet, and the central line's height rates.
template <class T>
struct pulse_edges {
  expected_edge<T> in[2];   ///< delta50 (a step profile's), then the surface
  expected_edge<T> out[2];  ///< the surface, then delta50 (a step profile's)
  bool steps;               ///< a step profile above the surface: both edges, else the surface's
  T rate_in, rate_out;      ///< |d height / d phi| at the crossings (m/rad)
};

/// Lays the row's windows over the extents in and out, one merged or one each, and builds them.
template <class T, class Surface>
bool build_windows(sensor_physics_workspace<T>& work, const sensor_physics_head<T>& head,
                   const scan_circle<T>& circle, const Surface& surface,
                   const radiance_context<T>& radiance, const pulse_edges<T>& expected,
                   const window_extent<T>& in, const window_extent<T>& out, bool merged) noexcept {
  const bool steps = expected.steps;
  const T rate_in = expected.rate_in, rate_out = expected.rate_out;
  expected_edge<T> edges[max_edges];
  int n = 0;
  for (int i = steps ? 0 : 1; i < 2; ++i) edges[n++] = expected.in[i];
  pulse_window<T>& w0 = work.window[0];
  pulse_window<T>& w1 = work.window[1];
  w0.crossings = merged ? 2 : 1;
  w0.extent[0] = in;
  w0.extent[1] = out;
  w0.root_lo = in.root_lo;
  w0.root_hi = merged ? out.root_hi : in.root_hi;
  if (merged) {
    for (int i = 0; i < (steps ? 2 : 1); ++i) edges[n++] = expected.out[i];
    return build_window(w0, head, work.cache, circle, surface, radiance, edges, n, in.lo, out.hi,
                        rate_in < rate_out ? rate_out : rate_in);
  }
  w1.crossings = 1;
  w1.extent[0] = out;
  w1.root_lo = out.root_lo;
  w1.root_hi = out.root_hi;
  return build_window(w0, head, work.cache, circle, surface, radiance, edges, n, in.lo, in.hi,
                      rate_in) &&
         build_window(w1, head, work.cache, circle, surface, radiance, expected.out, steps ? 2 : 1,
                      out.lo, out.hi, rate_out);
}

/// Plans the row's windows about its geometric crossings and builds them: one per crossing, or
/// one for both (merged) when they are closer than the lag's memory and the field; widened and
/// built again (at most 4 times) when the line misses an expected edge. ok, grazing (the line
/// misses its edge every time), invalid (the workspace outgrown).
template <class T, class Surface>
status build_pulse(sensor_physics_workspace<T>& work, const sensor_physics_head<T>& head,
                   const scan_circle<T>& circle, const Surface& surface,
                   const radiance_context<T>& radiance, const crossings<T>& geometric,
                   bool& merged) noexcept {
  const radiance_profile<T>& profile = head.profile;
  const surface_probe<T> probe = probe_of(surface);
  const T phi_in = geometric.phi_in, phi_out = geometric.phi_out, lag = head.lag_rad;
  const T rate_in = height_rate(circle, surface, probe, phi_in);
  const T rate_out = height_rate(circle, surface, probe, phi_out);
  if (!(rate_in > T(0)) || !(rate_out > T(0)) || !is_finite(rate_in) || !is_finite(rate_out))
    return status::grazing;
  const profile_band<T> band = profile_band_of(profile, tail_cut_of(head));
  const T reach = locator_reach(head, band);
  const T half_along = patch_half_along(head.settings.field, circle);
  const pulse_edges<T> edges{
      {{profile.offset_m, phi_in, rate_in, -1}, {T(0), phi_in, rate_in, -1}},
      {{T(0), phi_out, rate_out, 1}, {profile.offset_m, phi_out, rate_out, 1}},
      profile.scale_m == T(0) && profile.offset_m > T(0),
      rate_in,
      rate_out};
  work.cache.count = 0;
  work.cache.outgrown = false;
  T widen = T(5) / T(4);
  for (int attempt = 0; attempt < 4; ++attempt, widen = widen * T(3) / T(2)) {
    window_extent<T> in =
        window_extent_of(circle, surface, probe, band, phi_in, -1, rate_in, half_along, widen,
                         geometric.half_chord(), reach, lag, head.settings.field);
    const window_extent<T> out =
        window_extent_of(circle, surface, probe, band, phi_out, 1, rate_out, half_along, widen,
                         geometric.half_chord(), reach, lag, head.settings.field);
    // With the season term the disk's radiance varies, so no closed form follows the window:
    // the in-window reaches 40 Lambda into the disk and its locator region with it.
    if (radiance.amplitude != T(0)) {
      in.hi = in.hi + T(2) * lag_history(lag);
      in.root_hi = in.hi;
      in.disk = in.root_hi - in.crossing;
    }
    merged = out.lo - in.hi < lag_history(lag) + T(2) * half_along;
    if (build_windows(work, head, circle, surface, radiance, edges, in, out, merged))
      return status::ok;
    if (work.cache.outgrown) return status::invalid;
  }
  return status::grazing;
}

/// The output sampled over a window's locator region (the locator's brackets).
template <class T>
struct window_sampling {
  T phi[2 * max_samples + 4];
  T output[2 * max_samples + 4];
  lag_point<T> value[2 * max_samples + 4];
  int count;

  void sample(const pulse_window<T>& w, const sensor_physics_head<T>& head) noexcept {
    const int per = head.accuracy.samples < 4             ? 4
                    : head.accuracy.samples > max_samples ? max_samples
                                                          : head.accuracy.samples;
    count = window_samples(w, per, phi);
    for (int i = 0; i < count; ++i) {
      const pulse_values<T> v = evaluate_window(w, head, phi[i]);
      output[i] = v.output;
      value[i] = {v.output, v.slope};
    }
    // A merged window's disk: its extremes join the samples (merged_disk_extremes).
    T extremes[2 * max_samples + 4];
    const int added = merged_disk_extremes(w, head, phi, value, count, slope_noise(value, count),
                                           extremes, 2 * max_samples + 4 - count);
    for (int i = 0; i < added; ++i) insert(w, head, extremes[i]);
  }
  window_signal<T> signal(const pulse_window<T>& w,
                          const sensor_physics_head<T>& head) const noexcept {
    return {&w, &head, phi, value, count};
  }
  /// One more sample at `at` (inside the window, between two samples), in its place: a maximum
  /// the samples stepped over (a limb brighter than the disk just above the surface's jump).
  void insert(const pulse_window<T>& w, const sensor_physics_head<T>& head, const T& at) noexcept {
    if (count >= 2 * max_samples + 4) return;
    int i = count;
    while (i > 0 && phi[i - 1] > at) {
      phi[i] = phi[i - 1];
      output[i] = output[i - 1];
      value[i] = value[i - 1];
      --i;
    }
    const pulse_values<T> v = evaluate_window(w, head, at);
    phi[i] = at;
    output[i] = v.output;
    value[i] = {v.output, v.slope};
    ++count;
  }
};

/// The crossing past a window's locator region, where the signal is constant and the output
/// relaxes to it: root_hi + Lambda ln((s - y)/(s - level)). miss when it never passes the level.
template <class T>
result<T> relaxation_crossing(const pulse_window<T>& w, const sensor_physics_head<T>& head,
                              const T& level, bool rising) noexcept {
  using std::log;
  const T lag = head.lag_rad;
  const pulse_values<T> end = evaluate_window(w, head, w.root_hi);
  if (!(lag > T(0))) return result<T>::bad(status::miss);
  if (rising ? !(end.output < level && end.mean > level)
             : !(end.output >= level && end.mean < level))
    return result<T>::bad(status::miss);
  return result<T>::good(T(w.root_hi + lag * log((end.mean - end.output) / (end.mean - level))));
}

/// A pulse that passes the level on one side of the Earth only (MODEL §12: Earth-in the first
/// rising crossing, Earth-out the last falling one, multiple only where the output passes the
/// level upwards twice): the season term or a limb dimmer than the level leaves the other side's
/// limb below it, and over a disk below it too the one pulse rises and falls within one window
/// (its sky and its surface). Both crossings then lie in that window, the plateau and the other
/// window below the level throughout. True with in and out set; else false (the caller's rules).
/// `rising0`.. `falling1`: the windows' samples' crossings of the level (count_crossings).
/// Found by a scan of the options' ranges: a pencil 29 550 km out, the season term at A = 0.73
/// over a disk of 0.16 L0, was `multiple` where the reference found the one pulse.
template <class T>
bool pulse_on_one_side(const window_signal<T>& signal0, const window_sampling<T>& s0, int rising0,
                       int falling0, const window_signal<T>& signal1, const window_sampling<T>& s1,
                       int rising1, int falling1, const plateau_range<T>& plateau, const T& level,
                       result<T>& in, result<T>& out) noexcept {
  if (!(plateau.highest < level)) return false;
  const bool in_side = rising0 == 1 && falling0 == 1 && rising1 == 0 && falling1 == 0;
  const bool out_side = rising0 == 0 && falling0 == 0 && rising1 == 1 && falling1 == 1;
  if (!in_side && !out_side) return false;
  const window_signal<T>& signal = in_side ? signal0 : signal1;
  const window_sampling<T>& samples = in_side ? s0 : s1;
  const result<T> rise = first_rising_crossing(signal, samples.phi, samples.count, level);
  const result<T> fall = last_falling_crossing(signal, samples.phi, samples.count, level);
  if (!rise.ok() || !fall.ok() || !(rise.value < fall.value)) return false;
  in = rise;
  out = fall;
  return true;
}

/// Where the season term varies the disk, the output can pass the level on the plateau between
/// separated windows (a bright disk dimmed or brightened along the scan): the crossing a window's
/// samples lack is the plateau's (plateau_crossings_of), and the pulse is ok where the output
/// passes the level upwards once over the turn. `rising0`.. `falling1`: the windows' samples'
/// crossings (count_crossings). miss where a crossing is found nowhere, multiple where the output
/// passes the level upwards twice.
template <class T>
status plateau_located(const plateau_passages<T>& plateau, int rising0, int falling0, int rising1,
                       int falling1, result<T>& in, result<T>& out) noexcept {
  if (rising0 + plateau.rising + rising1 > 1 || falling0 + plateau.falling + falling1 > 1)
    return status::multiple;
  if (!in.ok() && plateau.rising == 1) in = result<T>::good(plateau.first_rising);
  if (!out.ok() && plateau.falling == 1) out = result<T>::good(plateau.last_falling);
  if (!in.ok() || !out.ok()) return status::miss;
  return in.value < out.value ? status::ok : status::multiple;
}

/// The threshold locators on the sampled windows: Earth-in the first rising crossing, Earth-out
/// the last falling one (past a window, the relaxation; with the season term, the plateau's:
/// plateau_located); multiple when the output falls below the level between them (in a window's
/// samples, or the plateau's field mean). `passages(level)`: the plateau's crossings of the level.
template <class T, class Passages>
crossings<T> locate_level(const pulse_window<T>& w0, const pulse_window<T>& w1, bool merged,
                          const sensor_physics_head<T>& head, const window_sampling<T>& s0,
                          const window_sampling<T>& s1, const plateau_range<T>& plateau,
                          const T& level, const Passages& passages) noexcept {
  const window_signal<T> signal0 = s0.signal(w0, head);
  const window_signal<T> signal1 = merged ? signal0 : s1.signal(w1, head);
  const window_sampling<T>& out_samples = merged ? s0 : s1;
  // With the season term the disk past the in-window is not constant: the plateau's series.
  const bool season = head.settings.season_amplitude != T(0);
  result<T> in = first_rising_crossing(signal0, s0.phi, s0.count, level);
  if (!in.ok() && !merged && !season) in = relaxation_crossing(w0, head, level, true);
  result<T> out = last_falling_crossing(signal1, out_samples.phi, out_samples.count, level);
  if (!out.ok()) out = relaxation_crossing(w1, head, level, false);
  int rising = 0, falling = 0;
  count_crossings(s0.output, s0.count, level, rising, falling);
  if (!merged) {
    int rising1 = 0, falling1 = 0;
    count_crossings(s1.output, s1.count, level, rising1, falling1);
    if (pulse_on_one_side(signal0, s0, rising, falling, signal1, s1, rising1, falling1, plateau,
                          level, in, out))
      return crossings_from_azimuths(in.value, out.value, 0);
    if (falling > 0 || rising1 > 0 || (in.ok() && out.ok() && plateau.lowest_mean < level))
      return crossings<T>::failed(status::multiple);
    if (season && (!in.ok() || !out.ok())) {
      const status located =
          plateau_located(passages(level), rising, falling, rising1, falling1, in, out);
      if (located != status::ok) return crossings<T>::failed(located);
    }
  } else if (rising > 1 || falling > 1) {
    return crossings<T>::failed(status::multiple);
  }
  if (!in.ok() || !out.ok()) return crossings<T>::failed(status::miss);
  return crossings_from_azimuths(in.value, out.value, 0);
}

}  // namespace physics_detail

namespace physics_detail {

/// The central line's exact height for the windows (pulse_window::exact_height_at).
template <class T, class Surface>
struct exact_height_source {
  const sensor_physics_head<T>* head;
  const scan_circle<T>* circle;
  const Surface* surface;
  const radiance_context<T>* radiance;
  surface_probe<T> probe;

  static T at(const void* self, const T& phi) {
    const exact_height_source* s = static_cast<const exact_height_source*>(self);
    return exact_height(*s->circle, *s->surface, s->probe, phi, false).height_m;
  }
  static T field_at(const void* self, const T& phi) {
    const exact_height_source* s = static_cast<const exact_height_source*>(self);
    return field_signal_at(*s->head, *s->circle, *s->surface, *s->radiance, phi);
  }
};

/// The field's exact mean in the polish's scalar W (polish_scalar) for a row in T: the row's
/// circle and surface cast member by member, the profile and the radiance rebuilt in W from the
/// head's settings, the rules the workspace's (built once). Bound in place: its radiance points
/// at its own profile.
template <class T, class Surface>
struct polish_source {
  using W = polish_scalar_t<T>;
  using wide_surface = decltype(scalar_cast<W>(std::declval<Surface>()));
  const field_rules<W>* rules;
  field_of_view<W> field;
  radiance_profile<W> profile;
  radiance_context<W> radiance;
  scan_circle<W> circle;
  wide_surface surface;

  void bind(polish_rules<T>& work_rules, const sensor_physics_head<T>& head,
            const scan_circle<T>& row_circle, const Surface& row_surface,
            const radiance_context<T>& row_radiance) noexcept {
    if (!work_rules.built) field_rules_build(work_rules.rules);
    work_rules.built = true;
    rules = &work_rules.rules;
    const sensor_physics_settings<T>& s = head.settings;
    field = {W(s.field.fov_rad), s.field.shape};
    profile = radiance_profile_of(W(s.scale_m), W(s.offset_m), W(s.disk));
    radiance = {&profile, W(row_radiance.plateau), W(row_radiance.amplitude),
                W(row_radiance.sin_sun)};
    circle = scalar_cast<W>(row_circle);
    surface = scalar_cast<W>(row_surface);
  }
  static W field_at(const void* self, const W& phi) {
    const polish_source* s = static_cast<const polish_source*>(self);
    return field_signal_at(s->field, *s->rules, s->circle, s->surface, s->radiance, phi);
  }
};

}  // namespace physics_detail

namespace physics_detail {

/// Points every window of the workspace at the exact sources: the central line's height and the
/// field's mean (`source`), and the polish's mean in the wider scalar where the slope locator
/// polishes a field (`polish`, where polish_is_wider).
template <class T, class Surface>
void bind_exact_sources(sensor_physics_workspace<T>& work,
                        const exact_height_source<T, Surface>& source,
                        polish_source<T, Surface>& polish, bool polished) noexcept {
  for (pulse_window<T>& w : work.window) {
    w.exact_context = &source;
    w.exact_height_at = &exact_height_source<T, Surface>::at;
    w.exact_field_at = &exact_height_source<T, Surface>::field_at;
    if constexpr (polish_is_wider<T>) {
      w.polish_context = &polish;
      w.polish_field_at = polished ? &polish_source<T, Surface>::field_at : nullptr;
    }
  }
}

/// The pulse's largest output: the normalised locator's peak, from the windows and the plateau
/// between separated ones; `part` the part that gave it (0 the in-window or the merged one, 1 the
/// out-window, 2 the plateau). A window's maximum that lies between its samples (a limb brighter
/// than the disk, just above the surface's jump) joins them, so that the locator sees the output
/// pass its level there, whichever locator it is.
template <class T>
T pulse_peak(const pulse_window<T>& w0, const pulse_window<T>& w1, bool merged,
             const sensor_physics_head<T>& head, window_sampling<T>& s0, window_sampling<T>& s1,
             const plateau_range<T>& plateau, int& part) noexcept {
  const bool dim_disk = head.settings.disk < limb_fraction(head.profile, T(0));
  const window_maximum<T> top0 =
      window_peak(w0, head, s0.phi, s0.output, s0.value, s0.count, dim_disk);
  if (top0.inside) s0.insert(w0, head, top0.phi);
  T peak = top0.value;
  part = 0;
  if (merged) return peak;
  const window_maximum<T> top1 =
      window_peak(w1, head, s1.phi, s1.output, s1.value, s1.count, dim_disk);
  if (top1.inside) s1.insert(w1, head, top1.phi);
  if (top1.value > peak) {
    peak = top1.value;
    part = 1;
  }
  if (plateau.highest > peak) {
    peak = plateau.highest;
    part = 2;
  }
  return peak;
}

}  // namespace physics_detail

/// The crossings of MODEL §12 for one head and row: the physics chain in place of the geometric
/// crossings (scan_model.hpp), for processing by MODEL §6 unchanged.
///   head: sensor_physics_head_of(settings); circle: the head's true scan circle
///   (sensor_head::circle()); surface: the horizon sphere or ellipsoid in scan-frame components
///   (sensor_physics/height.hpp), the apparent-horizon terms folded into the ellipsoid;
///   sin_sun_declination: the row's Sun (the season term; any finite value when A = 0);
///   geometric: the scan model's crossings on the same surface; work: the caller's workspace.
/// Steps: the row's checks, the windows (heights, radiance, pieces, lag), the output sampled, the
/// peak, the locator.
/// Statuses: the geometric crossings' own when not ok (the physics acts on a pulse the geometry
/// found); invalid (head, circle or surface not ok, a non-finite Sun, a season factor <= 0, a
/// field reaching S: fov/2 >= gamma - sigma, a lag whose memory, 20 Lambda, exceeds the sky's arc
/// 2 pi - W, or a window that outgrows the workspace); grazing (a
/// field at least as wide along the scan as the chord, or a line of sight that misses the surface
/// near a crossing: the pulse is narrower than the field); miss (the output never passes the
/// level); multiple (the output falls below the level between the crossings: two pulses);
/// grazing of classify_half_chord on the result. Accuracy (against the brute-force reference,
/// docs/SENSOR_PHYSICS.md): 8.4e-11 deg on the 1.5 deg square with 1 ms of lag; within 5e-7 deg on
/// 128 of 146 random scenes, the rest `invalid` before the workspace grew or the slope locator's
/// (three fixed since, four the reference's limits at a kink or cusp of s'; off by 5.9e-6 deg on
/// one, not explained, and 1.4e-3 deg on one, of a class found since at a circle's tangency with
/// the surface under a broad limb: within 7e-8 deg now); of a second scan's 182 scenes, three
/// missed peaks fixed since and two flat-topped slopes of a wide field on a sharp limb off by
/// 3e-6 to 5e-6 deg; of 80 more, three fixed since (the reference's, and a circle's tangency with
/// a sharp knee) and a flat-topped slope off by 1.4e-6 deg; of 80 drawn 6600 to 42 200 km from
/// the centre, four fixed since (the geometry's panels, a merged window's peak) and wide fields'
/// slopes off by 1e-6 to 2e-5 deg; the reductions of MODEL §12 to 1e-12 deg.
template <class T, class Surface>
crossings<T> sensor_physics_crossings(const sensor_physics_head<T>& head,
                                      const scan_circle<T>& circle, const Surface& surface,
                                      const T& sin_sun_declination, const crossings<T>& geometric,
                                      sensor_physics_workspace<T>& work) noexcept {
  using namespace physics_detail;
  work.peak_part = -1;
  const status checked = row_status(head, circle, surface, sin_sun_declination, geometric);
  if (checked != status::ok)
    return geometric.state != status::ok && checked == geometric.state
               ? geometric
               : crossings<T>::failed(checked);
  const sensor_physics_settings<T>& s = head.settings;
  const radiance_context<T> radiance{&head.profile, s.plateau, s.season_amplitude,
                                     sin_sun_declination};
  bool merged = false;
  const status built = build_pulse(work, head, circle, surface, radiance, geometric, merged);
  if (built != status::ok) return crossings<T>::failed(built);
  const exact_height_source<T, Surface> source{&head, &circle, &surface, &radiance,
                                               probe_of(surface)};
  // The slope locator polishes a field's extremum on the exact mean, read in a wider scalar
  // where there is one (polish_scalar).
  polish_source<T, Surface> polish{};
  const bool polished = s.locator.kind == locator_kind::slope && s.field.fov_rad > T(0);
  if constexpr (polish_is_wider<T>)
    if (polished) polish.bind(work.polish, head, circle, surface, radiance);
  bind_exact_sources(work, source, polish, polished);
  const pulse_window<T>& w0 = work.window[0];
  const pulse_window<T>& w1 = merged ? work.window[0] : work.window[1];
  if (s.locator.kind == locator_kind::slope) {
    const result<T> in = steepest_place(w0, head, 1), out = steepest_place(w1, head, -1);
    if (!in.ok() || !out.ok()) return crossings<T>::failed(status::miss);
    return crossings_from_azimuths(in.value, out.value, 0);
  }
  window_sampling<T> s0, s1;
  s0.sample(w0, head);
  s1.count = 0;
  if (!merged) s1.sample(w1, head);
  // The plateau between separated windows: the output relaxes from the in-window's end towards
  // the disk's field mean (varying with the season term).
  plateau_range<T> plateau{T(0), T(0), T(0)};
  pulse_values<T> in_end{};  // the output and mean at the in-window's end, where the plateau starts
  if (!merged) {
    in_end = evaluate_window(w0, head, w0.hi);
    plateau = plateau_of(head, circle, surface, radiance, w0.hi, w1.lo, in_end.output, in_end.mean);
  }
  const T peak = pulse_peak(w0, w1, merged, head, s0, s1, plateau, work.peak_part);
  const T level = locator_level(s.locator, peak);
  if (!(level > T(0))) return crossings<T>::failed(status::miss);
  // The plateau's crossings of the level, from the in-window's end to the out-window's locator
  // region (the field wholly on the disk: plateau_output), where a window's samples lack one.
  const auto passages = [&](const T& at_level) {
    return plateau_crossings_of(head, circle, surface, radiance, w0.hi, w1.root_lo, in_end.output,
                                at_level);
  };
  return locate_level(w0, w1, merged, head, s0, s1, plateau, level, passages);
}

}  // namespace conescan

// A brute-force reference of MODEL §12's chain, for the tests and the benchmark only. It shares no
// code with the production physics (include/conescan/sensor_physics/: field, height, profile,
// detector, locator and the chain): every step is written again from the definitions, in long
// double, the simple robust way. It uses the core's vec3, misaligned_cone_angle (MODEL §4's psi)
// and crossings<T> only.
//
// The scene, heights, season term, profile and the field's mean are in
// sensor_physics_reference_field.hpp; this file holds the detector, the locators and the
// crossings. Frames and units as there: the head's scan frame, the satellite at the origin,
// metres, radians, radiance in units of L0 = 1.
//  - detector: Lambda y' = s - y in phi (Lambda = omega tau), on a grid of step h over the whole
//    turn from y = s opposite the pulse. The grid is uniform within runs, and runs end where s
//    is not smooth or sharp: a pencil's jumps (the cut, a step: nodes with their two one-sided
//    values) and, with lag, the knee levels delta50 + k H through a pencil's line, the contacts
//    of a field's corners (square) or extreme points (disk) with the levels (0, delta50 for a
//    step: kinks of the area fraction; the knee levels), each run at least 0.04 deg / h cells
//    (a disk's runs at a contact on Chebyshev nodes: its fraction grows as t^(3/2) there). Each
//    cell is the ODE's exact solution for s the cubic through the four nodes about it, within
//    the stretch between kinks (a cubic hold: a first-order hold's error inside a cell, O(h^3 /
//    Lambda), is not smooth in h and left 1e-7 deg after the extrapolation), summed as weights
//    J_n(x / Lambda) of the cubic's terms that keep their digits in cells far shorter than
//    Lambda; crossings and the peak refined in that closed form; the crossings from the grids of
//    h and 2h (every other node) extrapolated (Richardson, h^4). So H = 1 mm is resolved at any
//    h. Without lag there is no grid error at all: y = s, the crossings by regula falsi on the
//    exact signal (a jump that straddles the level is the crossing), the peak by golden section
//    on it; the grid only brackets them;
//  - statuses: multiple where the grid's output passes the level upward more than once (a dip
//    narrower than the grid's step is not seen), miss where it never does;
//  - locators: normalised (k times the largest output), fixed (T), slope: the extremum of dy/dphi
//    of its continuous part. A pencil without lag: the root of s'' on the sky's side (s'' by the
//    chain rule, delta' and delta'' by 4th-order differences of the exact heights, walked in
//    steps of a quarter of the knee's width), or the jump at the cut where the continuous part is
//    steeper there than at that root, or where there is no such root;
//    with H = 0 the step where delta50 > 0 (the continuous part's extremum in the limit H -> 0),
//    else the cut. A field without lag: the root of s'' (differences of step 1e-5 rad on the exact
//    signal) next to each cell whose mean slope is a local maximum within a tenth of the
//    largest, or the contact (a corner or extreme point on a level where L jumps: a kink of s')
//    where that root moves as the step shrinks (beyond what its roughness moves it); the steepest
//    of them by one-sided differences (a cusp of s' is narrower than a cell). With lag (y
//    continuous): the root of Lambda y'' = s' - y' next to the grid's extreme node (the step
//    shrunk while the root moves, beside a contact), or a jump of s where y' is extreme on its
//    side (a step: the crossing is the step itself).
//
// Own error (tests/core/test_sensor_physics_closed_forms.cpp, measured by convergence and against
// closed forms):
//  - the field mean: 3e-18 of L0 (sensor_physics_reference_field.hpp);
//  - without lag: normalised and fixed crossings to ~1e-15 deg (H = 1e-6 km is the step's to
//    1e-17 deg); the slope of a field ~4e-11 deg (its differences); of a pencil ~1e-13 deg;
//  - with lag, the grid (h against h/2, extrapolated): a pencil 5e-10 deg at h = 0.01 deg
//    (H = 7 km), 1e-10 (H = 1 m), exact for a step (s piecewise constant); H = 1 mm is the
//    step's plus (gamma_E + ln ln 2) H to 1e-12 deg; 1.5 deg fields with H = 7 km at h = 0.02
//    deg: a square 7e-10 deg (normalised), 4e-10 (fixed), 5e-9 (slope), a disk 7e-11, 2e-10,
//    9e-10; a 1 deg disk on a step 7e-9 deg at 0.02 deg, 2e-10 at 0.01 deg;
//  - outside the domain: a square on a step has a flat-topped slope (no single extremum); a scan
//    whose lowest height stays above delta50 + 36 H sees no pulse (miss).
// Cost (CPU, -O2, one core): a field mean 2-25 ms where the patch meets the profile (1.5 deg, H =
// 7 km: 3-8 ms; H of a metre: up to 25 ms), ~10 us where it does not; a row without lag 0.05-0.3 s
// (bracketing grid h = 0.25 deg), 2-4 s for the slope of a field; with lag, a pencil 0.1-0.3 s at
// h = 0.01-0.005 deg, a 1-1.5 deg field 1.5-5 s at h = 0.02 deg, 3-8 s at 0.01 deg (20 s for H of
// a metre, whose knee costs 25 ms a node).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "conescan/crossings.hpp"
#include "support/sensor_physics_reference_field.hpp"

namespace conescan_test {

/// The result of the reference: crossings (ok, or miss), the peak, and the level.
struct reference_result {
  conescan::crossings<ld> crossings;
  ld peak;
  ld level;
};

namespace reference_detail {

/// A jump of a pencil's signal: where the line crosses the surface or the step.
struct signal_jump {
  ld phi;
  bool surface;  ///< the cut (else the step)
  bool falling;  ///< the height falls through it (Earth-in side)
};

/// The signal over one turn from phi_middle - pi: nodes uniform within runs (an even number of
/// cells in each, so that every other node is the grid of 2 h), the signal's one-sided values at
/// each node (equal except at a jump). Runs end at a pencil's jumps and, with lag, where the
/// signal bends sharply (a knee level through a pencil's line; a level through a field's corner
/// or extreme point, where a step's or a sharp knee's area fraction has a kink), so that the
/// cubic hold sees a smooth signal in every run whatever H.
struct turn_signal {
  std::vector<ld> phi, left, right;
  std::vector<bool> coarse, jump;
  std::vector<bool> hard;  ///< a jump or a contact (a kink of s): the cubic hold's stencils stop
  std::vector<std::size_t> run_start;  ///< first node of each run (the last run ends at the end)
  std::vector<signal_jump> jumps;
};

/// Bisection to the last digit of where probe (one of its values) crosses level between a and b;
/// returns the bracket's ends.
template <class Probe>
void bisect_probe(const Probe& probe, std::size_t j, ld level, ld& a, ld& b) {
  std::vector<ld> v;
  probe(a, v);
  const bool below_a = v[j] < level;
  for (int it = 0; it < 200; ++it) {
    const ld m = (a + b) / 2;
    if (!(m > a && m < b)) break;
    probe(m, v);
    if ((v[j] < level) == below_a)
      a = m;
    else
      b = m;
  }
}

/// Where any of the probe's values crosses any level over the turn, sampled every h where the
/// line of sight's height lies within `margin` of the levels' range.
template <class Probe>
void probe_crossings(const reference_scene& s, const Probe& probe, ld start, ld h,
                     const std::vector<ld>& levels, ld margin, std::vector<ld>& lo,
                     std::vector<ld>& hi, std::vector<bool>* below_after = nullptr) {
  const std::size_t n = static_cast<std::size_t>(std::ceil(2 * reference_pi / h));
  const ld top = *std::max_element(levels.begin(), levels.end()) + margin;
  const ld bottom = *std::min_element(levels.begin(), levels.end()) - margin;
  std::vector<ld> previous, current;
  bool have_previous = false;
  for (std::size_t k = 0; k <= n; ++k) {
    const ld phi = start + 2 * reference_pi * k / n;
    const ld centre = tangent(s, reference_line_of_sight(s, phi), false).height;
    if (centre > top || centre < bottom) {
      have_previous = false;
      continue;
    }
    probe(phi, current);
    if (have_previous)
      for (std::size_t j = 0; j < current.size(); ++j)
        for (ld level : levels) {
          const bool below_a = previous[j] < level, below_b = current[j] < level;
          if (below_a == below_b) continue;
          ld a = start + 2 * reference_pi * (k - 1) / n, b = phi;
          bisect_probe(probe, j, level, a, b);
          lo.push_back(a);
          hi.push_back(b);
          if (below_after) below_after->push_back(below_b);
        }
    previous = current;
    have_previous = true;
  }
}

/// The probes of a field's bends: the heights of the square's corners, or of the disk's highest
/// and lowest boundary points (golden section about the height gradient's direction).
inline void field_probe(const reference_scene& s, const reference_settings& p, ld phi,
                        std::vector<ld>& v) {
  const reference_patch_axes f = reference_patch_axes_at(s, phi);
  const ld r = p.fov / 2;
  auto height = [&](ld x, ld y) {
    return tangent(s, reference_patch_direction(f, x, y), false).height;
  };
  v.clear();
  if (!p.circle) {
    for (int i = -1; i <= 1; i += 2)
      for (int j = -1; j <= 1; j += 2) v.push_back(height(i * r, j * r));
    return;
  }
  const ld e = r * 1e-3L;
  const ld up = std::atan2(height(0, e) - height(0, -e), height(e, 0) - height(-e, 0));
  for (int sign = 1; sign >= -1; sign -= 2) {
    const ld centre = sign > 0 ? up : up + reference_pi;
    ld where = centre;
    const ld extreme =
        golden_maximum([&](ld a) { return sign * height(r * std::cos(a), r * std::sin(a)); },
                       centre - 0.6L, centre + 0.6L, where);
    v.push_back(sign * extreme);
  }
}

/// The runs' ends: a pencil's jumps (with their brackets, one-sided values at lo and hi); with
/// lag, the bends (continuous: lo = hi). Sorted by azimuth.
struct run_end {
  ld phi, lo, hi;
  bool jump;
  bool contact;  ///< a field's corner or extreme point meets a level where L jumps (0, a step)
};

inline std::vector<run_end> run_ends(const reference_scene& s, const reference_settings& p,
                                     ld start, ld h, std::vector<signal_jump>& jumps) {
  std::vector<run_end> ends;
  auto height = [&](ld phi, std::vector<ld>& v) {
    v.assign(1, tangent(s, reference_line_of_sight(s, phi), false).height);
  };
  std::vector<ld> lo, hi;
  std::vector<bool> below;
  if (p.fov == 0) {
    for (ld level : jump_levels(p)) {
      const std::size_t first = lo.size();
      probe_crossings(s, height, start, h, {level}, 1e30L, lo, hi, &below);
      for (std::size_t i = first; i < lo.size(); ++i) {
        jumps.push_back({hi[i], level == 0, below[i]});
        ends.push_back({hi[i], lo[i], hi[i], true, false});
      }
    }
  }
  if (p.lag > 0) {
    std::vector<ld> levels = bend_levels(p);
    const std::size_t jumping = jump_levels(p).size();  // the first of bend_levels
    for (int part = 0; part < 2; ++part) {              // the levels where L jumps, then the knees
      const std::vector<ld> some(part == 0 ? levels.begin() : levels.begin() + jumping,
                                 part == 0 ? levels.begin() + jumping : levels.end());
      if (some.empty() || (p.fov == 0 && part == 0)) continue;  // a pencil's jumps are above
      lo.clear();
      hi.clear();
      if (p.fov == 0) {
        probe_crossings(s, height, start, h, some, 1e30L, lo, hi);
      } else {
        auto probe = [&](ld phi, std::vector<ld>& v) { field_probe(s, p, phi, v); };
        probe_crossings(s, probe, start, h, some, conescan::norm(s.centre) * p.fov, lo, hi);
      }
      for (std::size_t i = 0; i < lo.size(); ++i)
        ends.push_back({hi[i], hi[i], hi[i], false, part == 0});
    }
  }
  std::sort(ends.begin(), ends.end(),
            [](const run_end& a, const run_end& b) { return a.phi < b.phi; });
  return ends;
}

/// A run's smooth signal at any azimuth: a field's exact mean; a pencil's radiance on the run's
/// branch of the profile (the disk, either side of a step, or the limb's formula with the signed
/// height, continued across the run's ends so that differences near a jump see its side only).
struct run_signal {
  const reference_scene* scene;
  const reference_settings* settings;
  quadrature_options q;
  int branch;  ///< -1 a field; a pencil: 0 the disk, 1 below a step (L0), 2 above it, 3 the limb

  ld operator()(ld phi) const {
    const reference_settings& p = *settings;
    if (branch < 0) return field_mean(*scene, p, phi, q);
    const reference_height h =
        tangent(*scene, reference_line_of_sight(*scene, phi), p.amplitude != 0);
    const ld l0 = reference_plateau(*scene, p, h.sin_latitude);
    if (branch < 3) return branch == 0 ? l0 * p.disk : branch == 1 ? l0 : 0;
    const ld z = (h.height - p.offset_m) / p.scale_m;
    return z > 36 ? 0 : l0 * -std::expm1(-std::log(2.0L) * std::exp(-z));
  }
};

/// The run's signal about azimuth phi (a point inside the run).
inline run_signal run_signal_at(const reference_scene& s, const reference_settings& p,
                                const quadrature_options& q, ld phi) {
  if (p.fov > 0) return {&s, &p, q, -1};
  const ld height = tangent(s, reference_line_of_sight(s, phi), false).height;
  const int branch = height < 0 ? 0 : p.scale_m > 0 ? 3 : height < p.offset_m ? 1 : 2;
  return {&s, &p, q, branch};
}

/// Appends the run from `from` to e.phi: `cells` cells (uniform, or on the Chebyshev points when
/// `graded`), the signal at its nodes and a jump's one-sided values at its end: `before` and
/// `after`, the runs' own branches at the bracket's ends (the signal itself there could be the
/// step's middle value, L0 / 2 exactly at delta50: an end's height rounds onto the level).
template <class Signal>
void append_run(turn_signal& g, const Signal& signal, ld from, const run_end& e, std::size_t cells,
                bool graded, bool last, const run_signal& before, const run_signal& after) {
  g.run_start.push_back(g.phi.size() - 1);
  const ld length = e.phi - from;
  for (std::size_t i = 1; i <= cells; ++i) {
    const ld u = static_cast<ld>(i) / static_cast<ld>(cells);
    g.phi.push_back(i == cells ? e.phi
                    : graded   ? from + length * (1 - std::cos(reference_pi * u)) / 2
                               : from + length * u);
    g.coarse.push_back(i % 2 == 0);
    const bool jump = i == cells && e.jump;
    g.jump.push_back(jump);
    g.hard.push_back(i == cells && (e.jump || e.contact || last));
    g.left.push_back(jump ? before(e.lo) : signal(g.phi.back()));
    g.right.push_back(jump ? after(e.hi) : g.left.back());
  }
}

inline turn_signal turn_signal_of(const reference_scene& s, const reference_settings& p,
                                  ld phi_middle, ld h, const quadrature_options& q) {
  turn_signal g;
  const ld start = phi_middle - reference_pi, end = phi_middle + reference_pi;
  std::vector<run_end> kept;  // ends closer than 1e-15 rad to another are one (a jump is kept)
  for (const run_end& e : run_ends(s, p, start, h, g.jumps)) {
    if (!kept.empty() && e.phi - kept.back().phi < 1e-15L) {
      if (e.jump) kept.back() = e;
      continue;
    }
    kept.push_back(e);
  }
  kept.push_back({end, end, end, false, false});
  // A run has at least ceil(0.04 deg / h) cells each way: with h the runs' cells shrink, so that
  // the grids of h and 2 h keep their ratio and the extrapolation holds.
  const std::size_t fewest =
      std::max<std::size_t>(4, static_cast<std::size_t>(std::ceil(0.04L * reference_pi / 180 / h)));
  auto signal = [&](ld phi) { return field_mean(s, p, phi, q); };
  g.phi.push_back(start);
  g.left.push_back(signal(start));
  g.right.push_back(g.left.back());
  g.coarse.push_back(true);
  g.jump.push_back(false);
  g.hard.push_back(true);
  // A disk's area fraction grows as t^(3/2) from its first contact with a level where L jumps:
  // the runs at such a contact are graded (a cubic hold's error there ~(1/N^2)^(5/2) instead of
  // N^(-5/2); every other node is again such a grid).
  ld from = start;
  bool from_contact = false;
  for (std::size_t k = 0; k < kept.size(); ++k) {
    const run_end& e = kept[k];
    // A graded run's cubic hold errs as N^-5 (N its cells): at least 32 of them (10 cells
    // across a 0.09 deg disk passing a knee of 7.8 m, 31 600 km out, left y 1.5e-6 of L0 off
    // and its crossings 2.5e-6 deg: the extrapolation from h and 2 h assumes h^4).
    const bool graded = p.circle && (from_contact || e.contact);
    const std::size_t cells =
        2 * std::max(graded ? std::max<std::size_t>(fewest, 16) : fewest,
                     static_cast<std::size_t>(std::ceil((e.phi - from) / (2 * h))));
    const ld next = k + 1 < kept.size() ? kept[k + 1].phi : end;
    append_run(g, signal, from, e, cells, graded, e.phi >= end,
               run_signal_at(s, p, q, (from + e.phi) / 2),
               run_signal_at(s, p, q, (e.phi + next) / 2));
    from = e.phi;
    from_contact = e.contact;
  }
  // A bend between runs whose cells differ by more than 2x (a sharp knee's short runs beside long
  // ones) is hard too: a cubic through such unequal cells would swing between its nodes.
  for (std::size_t k : g.run_start) {
    if (k == 0 || k + 1 >= g.phi.size()) continue;
    const ld before = g.phi[k] - g.phi[k - 1], after = g.phi[k + 1] - g.phi[k];
    if (std::max(before, after) > 2 * std::min(before, after)) g.hard[k] = true;
  }
  return g;
}

/// The nodes of the grid of h (all) or 2 h (every other node of each run).
inline std::vector<std::size_t> grid_nodes(const turn_signal& g, bool coarse) {
  std::vector<std::size_t> nodes;
  for (std::size_t k = 0; k < g.phi.size(); ++k)
    if (!coarse || g.coarse[k]) nodes.push_back(k);
  return nodes;
}

/// The detector on one grid: y at its nodes, from y = s at the start, and the stretch each cell
/// belongs to (between hard nodes: the signal's jumps and a field's contacts; s smooth inside).
struct lagged {
  std::vector<std::size_t> node;  ///< indices into the turn_signal
  std::vector<ld> y;
  std::vector<std::size_t> first, last;  ///< per cell: its stretch's first and last node (here)
};

/// The signal at lagged node j as its run sees it (a jump's one-sided value).
inline ld run_value(const turn_signal& g, const lagged& l, std::size_t j, std::size_t first) {
  return j == first ? g.right[l.node[j]] : g.left[l.node[j]];
}

/// J_n(r) = r int_0^1 t^n e^(-r (1 - t)) dt for n = 0 .. 3: the weights of the exact lag of u^n
/// over a cell, int_0^x u^n e^(-(x - u)/Lambda) du / Lambda = x^n J_n(x / Lambda). Below r = 1 by
/// their series r sum_k (-r)^k n! / (n + k + 1)! (no cancellation however small the cell), above
/// by the recurrence J_n = 1 - n J_(n-1) / r from J_0 = 1 - e^-r.
inline void lag_weights(ld r, ld (&j)[4]) {
  if (r >= 1) {
    j[0] = -std::expm1(-r);
    for (int n = 1; n < 4; ++n) j[n] = 1 - n * j[n - 1] / r;
    return;
  }
  for (int n = 0; n < 4; ++n) {
    ld term = r, sum = 0;  // r (-r)^k n! / (n + k + 1)!, from k = 0: r / (n + 1)
    term /= n + 1;
    for (int k = 0; k < 60 && std::fabs(term) > 1e-22L * std::fabs(sum); ++k) {
      sum += term;
      term *= -r / (n + k + 2);
    }
    j[n] = sum;
  }
}

/// y inside cell i at offset x in [0, h_i]: the exact solution of Lambda y' = s - y from y_i for s
/// the cubic through the four nodes about the cell in its stretch (a cubic hold: its error per
/// cell is O(h^5 / Lambda), where a first-order hold's is O(h^3 / Lambda), not smooth in h):
/// with s(u) = sum c_n u^n about the cell's start, y = y_i e^(-x/Lambda) + sum c_n x^n J_n(x /
/// Lambda), every term bounded, so that cells far shorter than Lambda keep their digits.
inline ld cell_output(const turn_signal& g, const lagged& l, std::size_t i, ld lag, ld x) {
  const std::size_t first = l.first[i], last = l.last[i];
  const std::size_t j0 = std::clamp<std::size_t>(i >= 1 ? i - 1 : 0, first, last - 3);
  const ld origin = g.phi[l.node[i]];
  ld t[4], a[4];
  for (std::size_t k = 0; k < 4; ++k) {
    t[k] = g.phi[l.node[j0 + k]] - origin;
    a[k] = run_value(g, l, j0 + k, first);
  }
  for (std::size_t k = 1; k < 4; ++k)  // Newton's divided differences
    for (std::size_t m = 3; m >= k; --m) a[m] = (a[m] - a[m - 1]) / (t[m] - t[m - k]);
  ld c[4] = {a[3], 0, 0, 0};  // monomial coefficients, by Horner on the Newton form
  for (int k = 2; k >= 0; --k) {
    for (int m = 3; m >= 1; --m) c[m] = c[m - 1] - t[k] * c[m];
    c[0] = a[k] - t[k] * c[0];
  }
  ld j[4];
  lag_weights(x / lag, j);
  ld sum = 0, power = 1;
  for (int n = 0; n < 4; ++n) {
    sum += c[n] * power * j[n];
    power *= x;
  }
  return l.y[i] * std::exp(-x / lag) + sum;
}

inline lagged lag_on(const turn_signal& g, const std::vector<std::size_t>& nodes, ld lag) {
  const std::size_t n = nodes.size();
  lagged r{nodes, std::vector<ld>(n), std::vector<std::size_t>(n - 1),
           std::vector<std::size_t>(n - 1)};
  for (std::size_t i = 0, first = 0; i + 1 < n; ++i) {
    if (g.hard[nodes[i]]) first = i;
    r.first[i] = first;
  }
  for (std::size_t i = n - 1, last = n - 1; i-- > 0;) {
    r.last[i] = last;
    if (g.hard[nodes[i]]) last = i;
  }
  r.y[0] = g.right[nodes[0]];
  for (std::size_t i = 0; i + 1 < n; ++i)
    r.y[i + 1] = cell_output(g, r, i, lag, g.phi[nodes[i + 1]] - g.phi[nodes[i]]);
  return r;
}

/// The largest output on a lagged grid: its largest node, refined in the two cells about it.
inline ld lagged_peak(const turn_signal& g, const lagged& l, ld lag) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < l.y.size(); ++i)
    if (l.y[i] > l.y[best]) best = i;
  ld peak = l.y[best], where = 0;
  for (std::size_t i = best > 0 ? best - 1 : 0; i <= best && i + 1 < l.y.size(); ++i) {
    const ld h = g.phi[l.node[i + 1]] - g.phi[l.node[i]];
    peak = std::max(
        peak, golden_maximum([&](ld x) { return cell_output(g, l, i, lag, x); }, 0, h, where));
  }
  return peak;
}

/// Where the lagged output passes `level`: rising (first cell from below) or falling (last cell
/// from above), bisected on the cell's closed form; false when it never does.
inline bool lagged_crossing(const turn_signal& g, const lagged& l, ld lag, ld level, bool rising,
                            ld& at) {
  const std::size_t n = l.y.size();
  for (std::size_t j = 0; j + 1 < n; ++j) {
    const std::size_t i = rising ? j : n - 2 - j;
    const bool passes =
        rising ? l.y[i] < level && l.y[i + 1] >= level : l.y[i] >= level && l.y[i + 1] < level;
    if (!passes) continue;
    ld a = 0, b = g.phi[l.node[i + 1]] - g.phi[l.node[i]];
    for (int it = 0; it < 200; ++it) {
      const ld m = (a + b) / 2;
      if (!(m > a && m < b)) break;
      if ((cell_output(g, l, i, lag, m) < level) == rising)
        a = m;
      else
        b = m;
    }
    at = g.phi[l.node[i]] + (a + b) / 2;
    return true;
  }
  return false;
}

/// Without lag: the largest value of the exact signal, from the largest node value (a jump's
/// one-sided value as it is), refined by golden section on the signal in the cells about it.
template <class Signal>
ld exact_peak(const turn_signal& g, const Signal& signal) {
  std::size_t best = 0;
  ld peak = g.left[0];
  for (std::size_t k = 0; k < g.phi.size(); ++k)
    if (std::max(g.left[k], g.right[k]) > peak) {
      peak = std::max(g.left[k], g.right[k]);
      best = k;
    }
  const bool jump = g.left[best] != g.right[best];
  if (jump || best == 0 || best + 1 == g.phi.size()) return peak;
  ld where = 0;
  return std::max(peak, golden_maximum(signal, g.phi[best - 1], g.phi[best + 1], where));
}

/// Without lag: where the exact signal passes `level`, rising (the first passage) or falling (the
/// last): inside a cell by regula falsi on the signal (continuous there), at a jump whose
/// one-sided values straddle it the jump itself.
template <class Signal>
bool exact_crossing(const turn_signal& g, const Signal& signal, ld level, bool rising, ld& at) {
  const std::size_t n = g.phi.size();
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t k = rising ? j : n - 1 - j;
    // At node k (a jump), then in the cell that ends (rising) or starts (falling) there.
    if (rising ? g.left[k] < level && g.right[k] >= level
               : g.left[k] >= level && g.right[k] < level) {
      at = g.phi[k];
      return true;
    }
    if (k == (rising ? n - 1 : 0)) continue;
    const std::size_t a = rising ? k : k - 1, b = a + 1;
    if (!(rising ? g.right[a] < level && g.left[b] >= level
                 : g.right[a] >= level && g.left[b] < level))
      continue;
    at = bracketed_root([&](ld phi) { return signal(phi) - level; }, g.phi[a], g.phi[b],
                        g.right[a] - level, g.left[b] - level);
    return true;
  }
  return false;
}

/// How often values in the turn's order pass `level` upward: more than once is two pulses, MODEL
/// §12's `multiple` (the turn starts on the sky, below any level).
inline int rising_passages(const std::vector<ld>& values, ld level) {
  int passages = 0;
  for (std::size_t k = 0; k + 1 < values.size(); ++k)
    if (values[k] < level && values[k + 1] >= level) ++passages;
  return passages;
}

/// A grid's values in the turn's order, each node's one-sided values in turn (a jump's two).
inline std::vector<ld> turn_values(const turn_signal& g) {
  std::vector<ld> values;
  for (std::size_t k = 0; k < g.phi.size(); ++k) {
    values.push_back(g.left[k]);
    values.push_back(g.right[k]);
  }
  return values;
}

/// 4th-order central differences of f at x with step e: first and second derivatives.
template <class F>
void differences(const F& f, ld x, ld e, ld& first, ld& second) {
  const ld m2 = f(x - 2 * e), m1 = f(x - e), c = f(x), p1 = f(x + e), p2 = f(x + 2 * e);
  first = (m2 - 8 * m1 + 8 * p1 - p2) / (12 * e);
  second = (-m2 + 16 * m1 - 30 * c + 16 * p1 - p2) / (12 * e * e);
}

/// y at any azimuth of a lagged grid (its cell's cubic hold).
inline ld lagged_output(const turn_signal& g, const lagged& l, ld lag, ld phi) {
  std::size_t lo = 0, hi = l.node.size() - 1;
  while (hi - lo > 1) {
    const std::size_t m = (lo + hi) / 2;
    (g.phi[l.node[m]] <= phi ? lo : hi) = m;
  }
  return cell_output(g, l, lo, lag, phi - g.phi[l.node[lo]]);
}

/// Where sign * q changes from + to - on [lo, hi] (the extremum of a derivative whose own
/// derivative is q): lo or hi when it does not (the extremum at an end).
template <class Q>
ld extremum_root(const Q& q, ld lo, ld hi, int sign, bool& at_end) {
  const ld q_lo = sign * q(lo), q_hi = sign * q(hi);
  at_end = !(q_lo > 0 && q_hi < 0);
  if (at_end) return q_lo <= 0 ? lo : hi;
  return bracketed_root([&](ld x) { return sign * q(x); }, lo, hi, q_lo, q_hi);
}

/// The extremum's root `at`, found with differences of step e (q(phi, e): the slope's own
/// derivative by differences), refined where the slope has a kink at or near it: a field's corner
/// or extreme point meeting a level where L jumps gives s'' a jump (infinite on one side), and
/// without lag the slope's extremum sits on the kink; with lag the root of s' = y' lies close
/// beside it (a narrow field on a sharp limb). Differences of step e smear a kink over +-2 e, so
/// the root moves with e: e shrinks by 8 while the root moves by more than 1e-10 rad and by more
/// than four times what the signal's roughness moves it at the finer step (`roughness(step)`: q's
/// rounding at that step, over q's slope across the bracket), down to 1e-9 rad; a smooth
/// extremum moves by ~e^4 and the roughness (2e-11 rad at 1.25e-6 rad): the first root is kept.
/// The roughness's rule keeps a sharp but smooth extremum off the noise (a square's corner
/// passing a knee of H = 21 m, 25 000 km out, the extremum 10 H before it: the steps went on to
/// 2.4e-9 rad, where s'' carries ~2 of noise, and the root moved 5.8e-8 rad to the bracket's end).
/// `last_step`: the last step whose root was taken (0 when the first root is kept).
template <class Q, class Roughness>
ld refined_at_kink(const Q& q, const Roughness& roughness, ld at, ld e, int sign, ld& last_step) {
  last_step = 0;
  for (ld step = e / 8; step >= 1e-9L; step /= 8) {
    const ld reach = 3 * 8 * step;  // the last step's smear, and some
    auto q_step = [&](ld phi) { return q(phi, step); };
    bool at_end = false;
    const ld next = extremum_root(q_step, at - reach, at + reach, sign, at_end);
    if (at_end || std::fabs(next - at) <= 1e-10L) break;
    const ld rate = std::fabs(q_step(at + reach) - q_step(at - reach)) / (2 * reach);
    if (std::fabs(next - at) <= 4 * roughness(step) / rate) break;
    at = next;
    last_step = step;
  }
  return at;
}

/// The field mean's roughness, of L0 (3e-18, sensor_physics_reference_field.hpp, rounded up).
inline constexpr ld mean_roughness = 4e-18L;

/// That roughness in 4th-order differences of step e: their first derivative (coefficients'
/// magnitudes 18 / 12 e) and second (64 / 12 e^2).
inline ld first_difference_roughness(ld e) {
  return mean_roughness * 18 / (12 * e);
}
inline ld second_difference_roughness(ld e) {
  return mean_roughness * 64 / (12 * e * e);
}

/// Whether phi lies on the crossing's half of the turn (MODEL §12): Earth-in's (sign 1) before its
/// middle, Earth-out's after it. A disk dimmer than the limb rises again towards Earth-out, and a
/// rise there steeper than the limb's at Earth-in is not the Earth-in crossing.
inline bool on_crossing_side(const turn_signal& g, ld phi, int sign) {
  const ld middle = (g.phi.front() + g.phi.back()) / 2;
  return sign > 0 ? phi < middle : phi > middle;
}

/// The slope locator on a lagged grid: the extremum of y' = (s - y)/Lambda. Per stretch between
/// the signal's jumps, the node of the extreme y' (a jump's one-sided value at the stretch's
/// ends), then the root of y'' = (s' - y')/Lambda between its neighbours (s' by differences of
/// step e on the stretch's exact signal, y by the cubic hold): its error is the grid's, O(h^4);
/// at a stretch's end that is a jump, the jump.
inline bool lagged_slope(const reference_scene& s, const reference_settings& p,
                         const turn_signal& g, const lagged& l, int sign, ld e, ld& at) {
  bool found = false;
  ld best = 0;
  for (std::size_t i0 = 0; i0 + 1 < l.node.size();) {
    std::size_t i1 = i0 + 1;  // the stretch's last node (lagged indices)
    while (i1 + 1 < l.node.size() && !g.jump[l.node[i1]]) ++i1;
    std::size_t b = i1 + 1;  // the extreme node on the crossing's side of the turn, if any
    std::vector<ld> v;
    for (std::size_t i = i0; i <= i1; ++i) {
      const std::size_t k = l.node[i];
      v.push_back(((i == i1 ? g.left[k] : g.right[k]) - l.y[i]) / p.lag);
      if (on_crossing_side(g, g.phi[k], sign) && (b > i1 || sign * v.back() > sign * v[b - i0]))
        b = i;
    }
    const std::size_t first = i0, last = i1;
    i0 = i1;
    if (b > last || last - first < 2 || (found && sign * v[b - first] <= sign * best)) continue;
    found = true;
    best = v[b - first];
    const run_signal signal =
        run_signal_at(s, p, quadrature_options{}, (g.phi[l.node[first]] + g.phi[l.node[last]]) / 2);
    auto curvature_of_step = [&](ld phi, ld step) {  // Lambda y'' = s' - y'
      ld first_derivative = 0, second_derivative = 0;
      differences(signal, phi, step, first_derivative, second_derivative);
      return first_derivative - (signal(phi) - lagged_output(g, l, p.lag, phi)) / p.lag;
    };
    auto curvature = [&](ld phi) { return curvature_of_step(phi, e); };
    // The bracket: the extreme node's neighbours, widened node by node (the cells differ from
    // run to run) until y'' changes sign across it or the stretch ends.
    std::size_t lo = b > first ? b - 1 : first, hi = std::min(b + 1, last);
    while (lo > first && sign * curvature(g.phi[l.node[lo]]) <= 0) --lo;
    while (hi < last && sign * curvature(g.phi[l.node[hi]]) >= 0) ++hi;
    bool at_end = false;
    at = extremum_root(curvature, g.phi[l.node[lo]], g.phi[l.node[hi]], sign, at_end);
    ld last_step = 0;
    if (!at_end)
      at = refined_at_kink(
          curvature_of_step,
          [&](ld step) { return first_difference_roughness(step) + mean_roughness / p.lag; }, at, e,
          sign, last_step);
  }
  return found;
}

/// s'' of a pencil's continuous part s = L0(phi) l(z), z = (delta(phi) - delta50)/H, continued
/// across the surface (H > 0), by the chain rule: l_z = -u e^-u, l_zz = u e^-u (1 - u), u = ln 2
/// e^-z; delta', delta'', L0', L0'' by differences of step 1e-3 rad (error ~1e-12 relative).
inline void pencil_derivatives(const reference_scene& s, const reference_settings& p, ld phi,
                               ld& slope, ld& curvature) {
  auto height = [&](ld x) { return tangent(s, reference_line_of_sight(s, x), false).height; };
  auto plateau = [&](ld x) {
    return reference_plateau(s, p, tangent(s, reference_line_of_sight(s, x), true).sin_latitude);
  };
  const ld e = 1e-3L;
  ld d1, d2, l1 = 0, l2 = 0;
  differences(height, phi, e, d1, d2);
  const ld l0 = p.amplitude != 0 ? plateau(phi) : p.plateau;
  if (p.amplitude != 0) differences(plateau, phi, e, l1, l2);
  const ld z = (height(phi) - p.offset_m) / p.scale_m, z1 = d1 / p.scale_m, z2 = d2 / p.scale_m;
  // Far below the knee (z < -40: u > 1e17) l = 1 and its derivatives vanish; u e^-u there would
  // overflow to inf * 0 (H of metres, the surface tens of km below delta50).
  const ld u = z < -40 ? 0 : std::log(2.0L) * std::exp(-z);
  const ld lz = z < -40 ? 0 : -u * std::exp(-u), lzz = -lz * (1 - u);
  const ld l = z < -40 ? 1 : -std::expm1(-u);
  slope = l1 * l + l0 * lz * z1;
  curvature = l2 * l + 2 * l1 * lz * z1 + l0 * (lzz * z1 * z1 + lz * z2);
}

inline ld pencil_curvature(const reference_scene& s, const reference_settings& p, ld phi) {
  ld slope = 0, curvature = 0;
  pencil_derivatives(s, p, phi, slope, curvature);
  return curvature;
}

inline ld pencil_slope_at(const reference_scene& s, const reference_settings& p, ld phi) {
  ld slope = 0, curvature = 0;
  pencil_derivatives(s, p, phi, slope, curvature);
  return slope;
}

/// The slope locator for a pencil without lag (MODEL §12): on each side the extremum of the
/// continuous part's slope on the sky's side of the cut, or the cut (the jump) where that
/// extremum lies beyond it: no root of s'' on the sky's side below the profile's top, or a
/// continuous part steeper at the cut than at the root (the season term's L0' where the limb
/// lies just above the surface). H = 0: the step where delta50 > 0 (the continuous part's extremum
/// in the limit H -> 0), else the cut. The cut is the jump nearest the pulse's middle on that side;
/// a scan that never meets the surface uses the height's lowest node instead.
inline bool pencil_slope(const reference_scene& s, const reference_settings& p,
                         const turn_signal& g, ld phi_middle, ld h, bool rising, ld& at) {
  bool have_cut = false, have_step = false;
  ld cut = 0, step = 0;
  for (const signal_jump& j : g.jumps) {
    if (j.falling != rising) continue;
    ld& where = j.surface ? cut : step;
    bool& have = j.surface ? have_cut : have_step;
    if (!have || (rising ? j.phi > where : j.phi < where)) where = j.phi;
    have = true;
  }
  if (p.scale_m == 0) {
    at = have_step ? step : cut;
    return have_step || have_cut;
  }
  if (!have_cut) {  // the lowest height's node on this side of the middle
    ld lowest = 1e300L;
    for (std::size_t k = 0; k < g.phi.size(); ++k) {
      if (rising ? g.phi[k] > phi_middle : g.phi[k] < phi_middle) continue;
      const ld height = tangent(s, reference_line_of_sight(s, g.phi[k]), false).height;
      if (height < lowest) {
        lowest = height;
        cut = g.phi[k];
      }
    }
  }
  // The sky's sign of s'' is +: the slope grows towards the Earth. Walking from the cut towards
  // the sky, the limb's extremum is where s'' turns from - to +; s'' may first be + near the cut
  // (the season term's L0'' where the limb lies many H above the surface). The crossing is the
  // steeper of that place and the cut (MODEL §12: the jump only where the continuous part's
  // extremum lies below the cut); the cut where there is no such place and s'' is + at the cut.
  const ld direction = rising ? -1 : 1;  // from the cut towards the sky
  const bool cut_negative = pencil_curvature(s, p, cut) < 0;
  at = cut;
  // Steps of at most a quarter of the knee's width along the scan (H of metres seen from far
  // away is narrower than the grid), until the height passes the profile's top.
  ld rate = 0, unused = 0;
  differences([&](ld x) { return tangent(s, reference_line_of_sight(s, x), false).height; }, cut,
              1e-3L, rate, unused);
  const ld walk = std::min(h, p.scale_m / std::max<ld>(std::fabs(rate), 1) / 4);
  const ld top = p.offset_m + 40 * p.scale_m;
  ld near = cut;
  bool seen_negative = cut_negative;
  for (long k = 1; k <= static_cast<long>(reference_pi / walk); ++k) {
    const ld far = cut + direction * k * walk;
    if (tangent(s, reference_line_of_sight(s, far), false).height > top) break;
    if (pencil_curvature(s, p, far) <= 0) {
      seen_negative = true;
      near = far;
      continue;
    }
    if (!seen_negative) continue;
    ld a = near, b = far;  // s''(a) < 0 < s''(b)
    for (int it = 0; it < 200; ++it) {
      const ld m = (a + b) / 2;
      if (!(m != a && m != b)) break;
      if (pencil_curvature(s, p, m) < 0)
        a = m;
      else
        b = m;
    }
    const ld limb = (a + b) / 2;
    if (std::fabs(pencil_slope_at(s, p, limb)) > std::fabs(pencil_slope_at(s, p, cut))) at = limb;
    return true;
  }
  return !cut_negative;
}

/// The contact (a field's corner or extreme point on a level where L jumps) within `reach` of phi,
/// to the last digit (a kink of s' located by differences is only within their step of it); phi
/// where there is none.
inline ld contact_near(const reference_scene& s, const reference_settings& p, ld phi, ld reach) {
  const std::vector<ld> levels = jump_levels(p);
  auto probe = [&](ld x, std::vector<ld>& v) { field_probe(s, p, x, v); };
  std::vector<ld> before, after;
  probe(phi - reach, before);
  probe(phi + reach, after);
  for (std::size_t j = 0; j < before.size(); ++j)
    for (ld level : levels)
      if ((before[j] < level) != (after[j] < level)) {
        ld a = phi - reach, b = phi + reach;
        bisect_probe(probe, j, level, a, b);
        return (a + b) / 2;
      }
  return phi;
}

/// sign s' at phi, a field without lag: the larger of its one-sided differences of 1e-8 rad (at
/// a kink, the extremum's own side; the quadrature's roughness ~4e-18 costs ~4e-10 of it).
inline ld field_slope_value(const reference_scene& s, const reference_settings& p, ld phi,
                            int sign) {
  const quadrature_options q;
  const ld step = 1e-8L, here = field_mean(s, p, phi, q);
  const ld left = (here - field_mean(s, p, phi - step, q)) / step;
  const ld right = (field_mean(s, p, phi + step, q) - here) / step;
  return std::max(sign * left, sign * right);
}

/// A field's candidates for the extremum of the slope near the grid's cell b (no lag), appended to
/// `places`: each root of s'' (differences of step e on the exact signal) between the cell's
/// neighbours, refined where it sits on a kink (refined_at_kink, contact_near): no grid error;
/// where s'' falls through 0 nowhere, the bracket's end. The bracket is widened while s'' keeps its
/// sign at its ends, and it can then hold two maxima of s': a cusp where the field touches a level
/// where L jumps and a broad maximum beside it (far seed 111's scene 37: a 0.39 deg circle whose
/// edge meets the dimmer disk at s' = 134.02 and a broad maximum of 133.75 0.027 deg later; far
/// seed 30's scene 9). One root of the whole bracket took either; s'' is now sampled at eight
/// places a cell and every fall through 0 is a candidate (field_slope keeps the steepest).
inline void field_slope_candidates(const reference_scene& s, const reference_settings& p,
                                   const turn_signal& g, std::size_t b, int sign, ld e,
                                   std::vector<ld>& places) {
  const run_signal signal = run_signal_at(s, p, quadrature_options{}, g.phi[b]);
  auto curvature_of_step = [&](ld phi, ld step) {
    ld first = 0, second = 0;
    differences(signal, phi, step, first, second);
    return second;
  };
  auto curvature = [&](ld phi) { return curvature_of_step(phi, e); };
  std::size_t lo = b > 0 ? b - 1 : 0, hi = std::min(b + 2, g.phi.size() - 1);
  while (lo > 0 && sign * curvature(g.phi[lo]) <= 0) --lo;
  while (hi + 1 < g.phi.size() && sign * curvature(g.phi[hi]) >= 0) ++hi;
  auto refine = [&](ld at) {
    ld last_step = 0;
    const ld refined =
        refined_at_kink(curvature_of_step, second_difference_roughness, at, e, sign, last_step);
    return last_step == 0 ? at : contact_near(s, p, refined, 6 * last_step);
  };
  constexpr int places_a_cell = 8;
  const std::size_t before = places.size();
  ld x0 = g.phi[lo], q0 = sign * curvature(x0);
  for (std::size_t j = lo; j < hi; ++j)
    for (int k = 1; k <= places_a_cell; ++k) {
      const ld x1 = g.phi[j] + (g.phi[j + 1] - g.phi[j]) * k / places_a_cell;
      const ld q1 = sign * curvature(x1);
      if (q0 > 0 && q1 < 0)
        places.push_back(
            refine(bracketed_root([&](ld x) { return sign * curvature(x); }, x0, x1, q0, q1)));
      x0 = x1;
      q0 = q1;
    }
  if (places.size() > before) return;
  bool at_end = false;  // no fall through 0: the extremum at an end of the bracket
  places.push_back(extremum_root(curvature, g.phi[lo], g.phi[hi], sign, at_end));
}

/// The slope locator for a field without lag: every local maximum of the cells' mean slopes
/// (sign s', the grid's differences over the cell's width; the runs are graded), within a tenth of
/// the largest, refined (field_slope_candidates), and the steepest candidate kept. The largest cell
/// alone is not enough: a level where L jumps (the surface under a brighter limb) gives s' a cusp
/// where it touches the field, a maximum narrower than the cells that averaging flattens below a
/// broad one (found by a random scan: a 0.91 deg circle on H = 2.6 m, the broad maximum 4e-4 of
/// itself less steep than the cusp 0.19 deg away). (A square on a step has a flat-topped s': its
/// extremum is not a point, outside this reference's domain.)
inline ld field_slope(const reference_scene& s, const reference_settings& p, const turn_signal& g,
                      int sign, ld e) {
  const std::size_t n = g.phi.size();
  auto cell = [&](std::size_t k) {
    return sign * (g.left[k + 1] - g.right[k]) / (g.phi[k + 1] - g.phi[k]);
  };
  ld largest = -1;
  for (std::size_t k = 0; k + 1 < n; ++k)
    if (on_crossing_side(g, g.phi[k], sign)) largest = std::max(largest, cell(k));
  std::vector<ld> places;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (!on_crossing_side(g, g.phi[k], sign) || cell(k) < largest * 0.9L) continue;
    if ((k > 0 && cell(k - 1) > cell(k)) || (k + 2 < n && cell(k + 1) > cell(k))) continue;
    field_slope_candidates(s, p, g, k, sign, e, places);
  }
  ld best_place = g.phi[0], best = -std::numeric_limits<ld>::infinity();
  for (const ld place : places) {
    const ld value = field_slope_value(s, p, place, sign);
    if (value > best) {
      best = value;
      best_place = place;
    }
  }
  return best_place;
}

/// One grid's crossings with lag (normalised, fixed or slope); e: the slope's difference step;
/// `two_pulses` where the output passes a level upward more than once.
inline bool lagged_crossings(const reference_scene& s, const reference_settings& p,
                             const turn_signal& g, bool coarse, ld e, ld& in, ld& out, ld& peak,
                             ld& level, bool& two_pulses) {
  const lagged l = lag_on(g, grid_nodes(g, coarse), p.lag);
  peak = lagged_peak(g, l, p.lag);
  if (p.locator == 2) {
    level = 0;
    return peak > 0 && lagged_slope(s, p, g, l, 1, e, in) && lagged_slope(s, p, g, l, -1, e, out);
  }
  level = p.locator == 0 ? p.threshold * peak : p.threshold;
  two_pulses = rising_passages(l.y, level) > 1;
  return lagged_crossing(g, l, p.lag, level, true, in) &&
         lagged_crossing(g, l, p.lag, level, false, out);
}

/// Richardson's extrapolation of an error ~h^order from the grids of h and 2 h.
inline conescan::crossings<ld> extrapolated(ld in, ld out, ld in_2h, ld out_2h, int order) {
  const ld f = std::ldexp(1.0L, order) - 1;
  return {in + (in - in_2h) / f, out + (out - out_2h) / f, conescan::status::ok, 0};
}

}  // namespace reference_detail

/// MODEL §12's floor: a pulse whose every radiance is fainter than 1e-3 of L0 (the brighter of the
/// disk and the limb at the surface, l(0), times the season factor's least value) is miss.
inline bool too_faint(const reference_scene& s, const reference_settings& p) {
  const ld limb_at_surface = p.scale_m > 0
                                 ? 1 - std::exp(-std::log(2.0L) * std::exp(p.offset_m / p.scale_m))
                                 : (p.offset_m > 0    ? 1.0L
                                    : p.offset_m == 0 ? 0.5L
                                                      : 0.0L);
  const ld pi = 3.14159265358979323846264338327950288L;
  const ld least_season = 1 - std::fabs(p.amplitude * s.sin_sun) / std::sin(23.44L * pi / 180);
  return !(std::max(p.disk, limb_at_surface) * least_season >= 1e-3L);
}

/// The reference crossings of one head and row (MODEL §12's chain). phi_middle: any azimuth inside
/// the Earth's pulse (the geometric crossings' mean); the turn runs from phi_middle - pi, where y =
/// s. h_rad: the grid's step: with lag (and for the slope locator with a field) the result's grid
/// error ~h^2 after the extrapolation; otherwise the grid only brackets the crossings and the peak,
/// which come from the exact signal (h ~ 0.05-0.2 deg is enough). Status ok; multiple where the
/// grid's output passes a level upward more than once over the turn (two pulses: a dip of the
/// disk below a fixed threshold); or miss when the output never passes the level (or has no
/// pulse).
inline reference_result reference_crossings(const reference_scene& s, const reference_settings& p,
                                            ld phi_middle, ld h_rad) {
  using namespace reference_detail;
  const quadrature_options q;
  const turn_signal g = turn_signal_of(s, p, phi_middle, h_rad, q);
  auto signal = [&](ld phi) { return field_mean(s, p, phi, q); };
  reference_result r{conescan::crossings<ld>::failed(conescan::status::miss), 0, 0};
  if (too_faint(s, p)) return r;
  // The slope's difference step: 1e-5 rad, where a field's truncation (~e^4) and its signal's
  // roughness (~4e-18: the quadrature's splits appear and move with phi, ~1/e^2) each cost ~2e-11
  // deg of the extremum (measured); for a pencil, below its profile's width H / |p| by 1e3.
  const ld e = p.fov == 0 && p.scale_m > 0
                   ? std::min(1e-5L, 1e-3L * p.scale_m / conescan::norm(s.centre))
                   : 1e-5L;
  ld in = 0, out = 0, in_2h = 0, out_2h = 0, peak_2h = 0, level_2h = 0;
  if (p.lag > 0) {
    bool two_pulses = false, two_pulses_2h = false;
    if (lagged_crossings(s, p, g, false, e, in, out, r.peak, r.level, two_pulses) &&
        lagged_crossings(s, p, g, true, e, in_2h, out_2h, peak_2h, level_2h, two_pulses_2h))
      r.crossings = two_pulses ? conescan::crossings<ld>::failed(conescan::status::multiple)
                               : extrapolated(in, out, in_2h, out_2h, 4);
    return r;
  }
  r.peak = exact_peak(g, signal);
  if (!(r.peak > 0)) return r;
  if (p.locator == 2 && p.fov == 0) {
    if (pencil_slope(s, p, g, phi_middle, h_rad, true, in) &&
        pencil_slope(s, p, g, phi_middle, h_rad, false, out))
      r.crossings = {in, out, conescan::status::ok, 0};
    return r;
  }
  if (p.locator == 2) {
    r.crossings = {field_slope(s, p, g, 1, e), field_slope(s, p, g, -1, e), conescan::status::ok,
                   0};
    return r;
  }
  r.level = p.locator == 0 ? p.threshold * r.peak : p.threshold;
  if (exact_crossing(g, signal, r.level, true, in) &&
      exact_crossing(g, signal, r.level, false, out))
    r.crossings = rising_passages(turn_values(g), r.level) > 1
                      ? conescan::crossings<ld>::failed(conescan::status::multiple)
                      : conescan::crossings<ld>{in, out, conescan::status::ok, 0};
  return r;
}

}  // namespace conescan_test

// The field's mean along the scan (MODEL §12, "Field of view"), by G modelled in the level and the
// scan azimuth together: field_mean.hpp computes G, the patch's share below a level, at each
// piece's model nodes in u (the level's place between two of G's breaks: the square's corners'
// heights, the circle's extremes) for every azimuth it is asked. In those coordinates G follows the
// patch's heights, smooth on the scale of a radian, so over a segment of azimuths G's values at
// the u nodes, the breaks and G above every height are a Chebyshev interpolant in phi: a segment's
// sweep_nodes patches computed exactly give the field's mean at every azimuth inside from the
// level-set sum alone (the density's integral on the interpolated pieces), with no exact height.
//
// A segment is modelled only where G keeps its structure over it (the breaks' count, which are
// singular, the order of the square's corners: a swap is a kink of the sorted breaks in phi),
// checked at its nodes and its end, the segment cut back before the first azimuth that differs;
// and where the last two Chebyshev coefficients in phi of every quantity fall below
// sweep_tolerance (1e-13 of the plateau; of the heights' span, or their rounding, for the
// breaks). A segment that does not converge shrinks by its excess (sweep_shrink) down to the
// caller's narrowest width; below it, where the structure changes, at the step (H = 0) and where
// a mean would read a piece the nodes do not hold, the mean is field_mean_at's.
// Domain: field_mean_at's; where no model holds (a structure that does not fit a node: more than
// sweep_breaks breaks; a patch within sweep_behind_margin of the satellite's horizontal, whose
// heights are flat behind it) the mean is field_mean_at's, never an extrapolation. Accuracy:
// against field_mean_at on random scenes, squares within 5e-14 of L0, circles within 4.8e-13
// (field_mean_at's own accuracy for a circle: 5e-13), the step bit for bit
// (tests/core/test_sensor_physics_field_mean.cpp). Cost: docs/SENSOR_PHYSICS.md, "Cost".
#pragma once

#include <cmath>
#include <limits>

#include "conescan/sensor_physics/field_mean.hpp"

namespace conescan {

namespace field_detail {

inline constexpr int sweep_nodes = 16;  ///< Chebyshev nodes in phi per segment
inline constexpr int sweep_breaks = 8;  ///< G's breaks a modelled segment holds, at most
inline constexpr int sweep_values = (sweep_breaks - 1) * fine_model_nodes;  ///< G's values at the
                                                                            ///< pieces' u nodes

/// How near the satellite's horizontal (in ahead()'s units) a modelled segment's patches may
/// come: lines behind it have flat heights (field_mean.hpp, behind_quadrature), which G's model
/// cannot follow. A patch's ahead() moves by at most |probe| per rad of scan (the first probe: the
/// unit nadir, or the ellipsoid's q, |q| ~ |p| / a_eq), so |probe| / 16 keeps a segment's stretch
/// between its nodes (0.02 rad at most) clear of it as well.
template <class T, class Surface>
T sweep_behind_margin(const field_patch<T, Surface>& patch) noexcept {
  return norm(patch.probe.first) / T(16);
}

/// G's structure and values at one azimuth: the breaks (merged within 1e-9 of the heights'
/// span), G times the area above them all, at each piece's first-kind u nodes (piece i's at
/// values[i * nodes + k]), and a key of the structure.
template <class T>
struct level_node {
  int count;  ///< breaks
  long key;   ///< count, singular flags, the square's corners' ranks
  T at[sweep_breaks];
  bool singular[sweep_breaks];
  T whole;
  T values[sweep_values];
};

/// G's structure on the patch's level sets into the node (its breaks and key, no values); false
/// when it does not fit a node.
template <class T>
bool level_structure_of(const boundary<T>& edges, const monotone_runs<T>& runs,
                        level_node<T>& node) noexcept {
  T breaks[max_breaks];
  bool singular[max_breaks];
  const int nb = height_breaks(edges, runs, breaks, singular);
  const T close = (breaks[nb - 1] - breaks[0]) / T(1000000000);
  node.count = 0;
  for (int i = 0; i < nb; ++i) {
    if (node.count > 0 && !(breaks[i] - node.at[node.count - 1] > close)) {
      node.singular[node.count - 1] = node.singular[node.count - 1] || singular[i];
      continue;
    }
    if (node.count == sweep_breaks) return false;
    node.at[node.count] = breaks[i];
    node.singular[node.count++] = singular[i];
  }
  const bool circle = edges.shape == field_shape::circle;
  if (node.count < 2) return false;
  node.key = node.count;
  for (int i = 0; i < node.count; ++i) node.key = node.key * 2 + (node.singular[i] ? 1 : 0);
  if (!circle)
    for (int p = 0; p < boundary_pieces; ++p) {
      int rank = 0;
      for (int q = 0; q < boundary_pieces; ++q)
        if (edges.values[q][0] < edges.values[p][0]) ++rank;
      node.key = node.key * 4 + rank;
    }
  return true;
}

/// Whether the level-set sum reads G on the piece [p, q] of heights: it holds the surface (G(0))
/// or meets the heights where the profile's density is not 0, from the surface or the saturated
/// limb's top (x_saturated) to the cut 40 H above delta50.
template <class T>
bool piece_read(const radiance_profile<T>& profile, const T& p, const T& q) noexcept {
  const T saturated = profile.offset_m + profile.x_saturated * profile.scale_m;
  const T low = saturated > T(0) ? saturated : T(0);
  const T cut = profile.offset_m + T(40) * profile.scale_m;
  return (!(p > T(0)) && !(q < T(0))) || (q > low && p < cut);
}

/// The level node of a patch, on exact heights, with G above every height and G's values at
/// `nodes` u nodes on the pieces `read` marks (null: its structure alone, from the boundary's
/// heights); false when its structure does not fit a node.
template <class T, class Surface>
bool level_node_of(const field_patch<T, Surface>& patch, const field_radiance<T>& radiance,
                   const field_rules<T>& rules, const bool* read, int nodes,
                   level_node<T>& node) noexcept {
  if (patch_near_behind(patch, sweep_behind_margin(patch))) return false;
  if (!read) {
    const boundary<T> edges = boundary_of(patch, rules.tables);
    return level_structure_of(edges, monotone_runs_of(edges), node);
  }
  const level_sets<T, Surface> s = level_sets_of(patch, radiance, rules);
  if (!level_structure_of(s.edges, s.runs, node)) return false;
  node.whole = s.whole;
  for (int i = 0; i + 1 < node.count; ++i)
    if (read[i])
      piece_values(
          s, height_piece<T>{node.at[i], node.at[i + 1], node.singular[i], node.singular[i + 1]},
          nodes, rules.tables.first_kind(nodes), &node.values[i * nodes]);
  return true;
}

}  // namespace field_detail

/// One line's sweep: the current segment [from, to] of azimuths and its nodes; `modelled` when
/// they passed the checks (else the segment's means are field_mean_at's). Start each line with
/// field_sweep_start.
template <class T>
struct field_sweep {
  bool built, modelled;
  T from, to;
  T width;  ///< the next segment's width (rad): doubled after a modelled one, up to `widest`
  T widest, narrowest;
  field_shape shape;
  T half;           ///< the patch's half-width
  int model_nodes;  ///< G's u nodes per piece (model_nodes_of, or fine_model_nodes)
  field_detail::level_node<T> node[field_detail::sweep_nodes];
  bool read[field_detail::sweep_breaks];     ///< the pieces whose models the nodes hold
  T at[field_detail::sweep_nodes];           ///< the nodes' azimuths
  T barycentric[field_detail::sweep_nodes];  ///< their weights (-1)^k sin((k + 1/2) pi / n)
  T excess;  ///< the last build's sweep_excess (0 where it failed before: a structure)
};

template <class T>
void field_sweep_start(field_sweep<T>& sweep, const T& widest, const T& narrowest) noexcept {
  sweep.built = false;
  sweep.modelled = false;
  sweep.width = widest;
  sweep.widest = widest;
  sweep.narrowest = narrowest;
}

namespace field_detail {

/// The barycentric weights at phi of the segment's nodes (node j exactly: 1 there).
template <class T>
void sweep_weights(const field_sweep<T>& sweep, const T& phi, T* weight) noexcept {
  T sum = T(0);
  for (int k = 0; k < sweep_nodes; ++k) {
    if (phi == sweep.at[k]) {
      for (int j = 0; j < sweep_nodes; ++j) weight[j] = T(j == k ? 1 : 0);
      return;
    }
    weight[k] = sweep.barycentric[k] / (phi - sweep.at[k]);
    sum += weight[k];
  }
  for (int k = 0; k < sweep_nodes; ++k) weight[k] = weight[k] / sum;
}

/// The field's mean at phi on a modelled segment: the node (its pieces' series) interpolated,
/// then the level-set sum;
/// false (and no mean) where the sum reads a piece the nodes do not hold.
template <class T>
bool swept_mean(const field_sweep<T>& sweep, const field_radiance<T>& radiance,
                const field_rules<T>& rules, const T& phi, T& mean) noexcept {
  T weight[sweep_nodes];
  sweep_weights(sweep, phi, weight);
  const level_node<T>& first = sweep.node[0];
  const int nodes = sweep.model_nodes;
  level_node<T> n{};
  n.count = first.count;
  const int values = (n.count - 1) * nodes;
  for (int k = 0; k < sweep_nodes; ++k) {
    const level_node<T>& m = sweep.node[k];
    for (int i = 0; i < n.count; ++i) n.at[i] += weight[k] * m.at[i];
    n.whole += weight[k] * m.whole;
    for (int i = 0; i < values; ++i)
      if (sweep.read[i / nodes]) n.values[i] += weight[k] * m.values[i];
  }
  for (int i = 0; i < n.count; ++i) n.singular[i] = first.singular[i];
  for (int i = 0; i + 1 < n.count; ++i)
    if (!sweep.read[i] && piece_read(*radiance.profile, n.at[i], n.at[i + 1])) return false;
  auto model = [&](int i, const height_piece<T>& piece) {
    piece_model<T> m{piece, nodes, {}};
    for (int j = 0; j < nodes; ++j) m.series[j] = n.values[i * nodes + j];
    return m;
  };
  auto below = [&](const T& zeta) {  // G(zeta) times the area, on the pieces' models
    if (!(zeta > n.at[0])) return T(0);
    for (int i = 0; i + 1 < n.count; ++i)
      if (zeta < n.at[i + 1]) {
        const height_piece<T> piece{n.at[i], n.at[i + 1], n.singular[i], n.singular[i + 1]};
        return model(i, piece).at(piece.u_of(zeta));
      }
    return n.whole;
  };
  const T area = patch_area(sweep.shape, sweep.half);
  mean = level_set_sum(*radiance.profile, n.at, n.singular, n.count, n.whole, below, model,
                       rules.density) /
         area;
  return true;
}

/// The largest error a modelled segment may leave in G (times the area, in units of the plateau
/// times the area) and in its breaks (in units of the heights' span): below the exact means' own
/// accuracy (docs/SENSOR_PHYSICS.md, "The field").
template <class T>
T sweep_tolerance() noexcept {
  const T floor = T(64) * std::numeric_limits<T>::epsilon();
  const T target = T(1) / T(10000000000000LL);  // 1e-13
  return floor > target ? floor : target;
}

/// The size of the last two Chebyshev coefficients in phi of a quantity from its values at the
/// segment's nodes: the interpolant's error estimate.
template <class T>
T sweep_tail(const T* values, const T (&cosines)[2][sweep_nodes]) noexcept {
  using std::abs;
  T tail = T(0);
  for (int j = 0; j < 2; ++j) {
    T sum = T(0);
    for (int k = 0; k < sweep_nodes; ++k) sum += values[k] * cosines[j][k];
    tail += abs(sum);
  }
  return tail * T(2) / T(sweep_nodes);
}

/// The largest ratio, over the quantities of the segment's nodes (breaks, G above them, G at the
/// u nodes), of the tail of their Chebyshev coefficients in phi to its limit (sweep_tolerance):
/// converged where it is at most 1.
template <class T>
T sweep_excess(const field_sweep<T>& sweep, const field_radiance<T>& radiance) noexcept {
  using std::cos;
  T cosines[2][sweep_nodes];
  for (int j = 0; j < 2; ++j)
    for (int k = 0; k < sweep_nodes; ++k)
      cosines[j][k] = cos(pi<T>() * T(sweep_nodes - 1 - j) * (T(k) + T(1) / T(2)) / T(sweep_nodes));
  const level_node<T>& first = sweep.node[0];
  const T area = patch_area(sweep.shape, sweep.half);
  const T g_limit = sweep_tolerance<T>() * radiance.plateau * area;
  // The breaks, to the tolerance of the heights' span, or to their rounding (4 ulps of the
  // 1e7 m the heights are computed from), which the exact means carry as well.
  const T h_limit = sweep_tolerance<T>() * (first.at[first.count - 1] - first.at[0]) +
                    T(40000000) * std::numeric_limits<T>::epsilon();
  T column[sweep_nodes];
  T worst = T(0);
  auto measure = [&](auto member, const T& limit) {
    for (int k = 0; k < sweep_nodes; ++k) column[k] = member(sweep.node[k]);
    const T ratio = sweep_tail(column, cosines) / limit;
    if (!(ratio <= worst)) worst = ratio;  // NaN too
  };
  for (int i = 0; i < first.count; ++i)
    measure([&](const level_node<T>& n) { return n.at[i]; }, h_limit);
  measure([](const level_node<T>& n) { return n.whole; }, g_limit);
  const int nodes = sweep.model_nodes;
  for (int i = 0; i < (first.count - 1) * nodes; ++i)
    if (sweep.read[i / nodes])
      measure([&](const level_node<T>& n) { return n.values[i]; }, g_limit);
  return worst;
}

/// The nodes' values on the pieces they hold turned into each piece's Chebyshev series in u
/// (piece_model_from), which the interpolation in phi carries as it would the values.
template <class T>
void sweep_series(field_sweep<T>& sweep, const field_rules<T>& rules) noexcept {
  const int nodes = sweep.model_nodes;
  const auto& cosines = rules.tables.first_kind(nodes);
  for (level_node<T>& node : sweep.node)
    for (int i = 0; i + 1 < node.count; ++i) {
      if (!sweep.read[i]) continue;
      const height_piece<T> piece{node.at[i], node.at[i + 1], node.singular[i],
                                  node.singular[i + 1]};
      const piece_model<T> m = piece_model_from(piece, nodes, &node.values[i * nodes], cosines);
      for (int j = 0; j < nodes; ++j) node.values[i * nodes + j] = m.series[j];
    }
}

/// The factor a segment that did not converge shrinks by: its tail falls as the width to the
/// nodes' count (an analytic function's Chebyshev coefficients), so excess^(-1/n) with a margin
/// of 0.9, within [1/4, 0.9]; a half where it failed before (a structure).
template <class T>
T sweep_shrink(const T& excess) noexcept {
  using std::pow;
  if (!(excess > T(1))) return T(1) / T(2);
  const T factor = T(9) / T(10) * pow(excess, T(-1) / T(sweep_nodes));
  return factor < T(1) / T(4) ? T(1) / T(4) : factor;
}

/// Node k of the segment [a, b] (first kind; k = 0 nearest b).
template <class T>
T sweep_node_at(const T& a, const T& b, int k) noexcept {
  using std::cos;
  const T angle = pi<T>() * (T(k) + T(1) / T(2)) / T(sweep_nodes);
  return (a + b) / T(2) + (b - a) / T(2) * cos(angle);
}

/// The key of G's structure at phi, -1 where it does not fit a node.
template <class T, class PatchAt>
long sweep_key_at(const PatchAt& patch_at, const field_radiance<T>& radiance,
                  const field_rules<T>& rules, const T& phi) noexcept {
  level_node<T> node;
  return level_node_of(patch_at(phi), radiance, rules, nullptr, 0, node) ? node.key : -1;
}

/// G's structure at the nodes of [a, b] (into the sweep's nodes) and at b, in increasing phi;
/// true when all are `key`, else `kept` is the last place before the first that is not (a: none).
template <class T, class PatchAt>
bool sweep_structures(field_sweep<T>& sweep, const PatchAt& patch_at,
                      const field_radiance<T>& radiance, const field_rules<T>& rules, const T& a,
                      const T& b, long key, T& kept) noexcept {
  kept = a;
  for (int i = 0; i <= sweep_nodes; ++i) {
    const int k = sweep_nodes - 1 - i;
    const T phi = k >= 0 ? sweep_node_at(a, b, k) : b;
    level_node<T> end;
    level_node<T>& node = k >= 0 ? sweep.node[k] : end;
    if (!level_node_of(patch_at(phi), radiance, rules, nullptr, 0, node) || node.key != key)
      return false;
    kept = phi;
  }
  return true;
}

/// The end of a segment from a, at most b, whose nodes and end keep G's structure at a (`key`),
/// their structures in the sweep's nodes: [a, b] shortened to the last place that kept it before
/// the first that did not, until all do (a when eight tries did not find one).
template <class T, class PatchAt>
T sweep_structured_end(field_sweep<T>& sweep, const PatchAt& patch_at,
                       const field_radiance<T>& radiance, const field_rules<T>& rules, const T& a,
                       const T& b, long key) noexcept {
  T end = b;
  for (int attempt = 0; attempt < 8 && end > a; ++attempt) {
    T kept;
    if (sweep_structures(sweep, patch_at, radiance, rules, a, end, key, kept)) return end;
    end = kept;
  }
  return a;
}

/// G's values at every node of the sweep's segment, on its pieces that are read and on
/// sweep.model_nodes u nodes each; false where a node's structure is not `key`.
template <class T, class PatchAt>
bool sweep_values_of(field_sweep<T>& sweep, const PatchAt& patch_at,
                     const field_radiance<T>& radiance, const field_rules<T>& rules,
                     long key) noexcept {
  for (int k = 0; k < sweep_nodes; ++k) {
    const auto patch = patch_at(sweep.at[k]);
    if (!level_node_of(patch, radiance, rules, sweep.read, sweep.model_nodes, sweep.node[k]) ||
        sweep.node[k].key != key)
      return false;
  }
  return true;
}

/// Whether every node's models of G in u, on the pieces read, converged (model_converged, as
/// field_mean_at asks of each of its pieces).
template <class T>
bool sweep_models_converged(const field_sweep<T>& sweep, const field_radiance<T>& radiance,
                            const field_rules<T>& rules) noexcept {
  const int nodes = sweep.model_nodes;
  if (nodes >= fine_model_nodes) return true;
  for (const level_node<T>& node : sweep.node)
    for (int i = 0; i + 1 < node.count; ++i) {
      if (!sweep.read[i]) continue;
      const height_piece<T> piece{node.at[i], node.at[i + 1], node.singular[i],
                                  node.singular[i + 1]};
      if (!model_converged(&node.values[i * nodes], nodes, rules.tables.first_kind(nodes),
                           piece_weight(*radiance.profile, piece), node.whole))
        return false;
    }
  return true;
}

}  // namespace field_detail

/// Builds the segment [a, b] (patch_at(phi): the patch at an azimuth) on G's structure `key`
/// (`structured`: the sweep's nodes hold it already); true when modelled: every node of that
/// structure, and converged (sweep_converged). G's values are computed on the pieces the sum
/// reads at some node (piece_read).
template <class T, class PatchAt>
bool field_sweep_build(field_sweep<T>& sweep, const PatchAt& patch_at,
                       const field_radiance<T>& radiance, const field_rules<T>& rules, const T& a,
                       const T& b, long key, bool structured) noexcept {
  using namespace field_detail;
  using std::cos;
  using std::sin;
  sweep.built = true;
  sweep.modelled = false;
  sweep.from = a;
  sweep.to = b;
  sweep.excess = T(0);
  for (int k = 0; k < sweep_nodes; ++k) {
    const T angle = pi<T>() * (T(k) + T(1) / T(2)) / T(sweep_nodes);
    sweep.at[k] = sweep_node_at(a, b, k);
    sweep.barycentric[k] = (k % 2 == 0 ? T(1) : T(-1)) * sin(angle);
  }
  T kept;
  if (!structured && !sweep_structures(sweep, patch_at, radiance, rules, a, b, key, kept))
    return false;
  const int count = sweep.node[0].count;
  for (int i = 0; i + 1 < count; ++i) {
    sweep.read[i] = false;
    for (int k = 0; k < sweep_nodes; ++k)
      sweep.read[i] = sweep.read[i] ||
                      piece_read(*radiance.profile, sweep.node[k].at[i], sweep.node[k].at[i + 1]);
  }
  const auto patch = patch_at(a);
  sweep.shape = patch.shape;
  sweep.half = patch.half;
  sweep.model_nodes = model_nodes_of(patch.shape);
  if (!sweep_values_of(sweep, patch_at, radiance, rules, key)) return false;
  if (!sweep_models_converged(sweep, radiance, rules)) {
    sweep.model_nodes = fine_model_nodes;
    if (!sweep_values_of(sweep, patch_at, radiance, rules, key)) return false;
  }
  sweep.excess = sweep_excess(sweep, radiance);
  if (!(sweep.excess <= T(1))) return false;
  sweep_series(sweep, rules);
  sweep.modelled = true;
  return true;
}

/// The field's mean at phi, for azimuths asked in increasing order along a line that ends at
/// `end`: on the current segment's model where it holds, else on a new segment from phi (the
/// sweep's width, shortened to where G keeps its structure, halved until modelled), else, over
/// the sweep's narrowest width, field_mean_at's. The step profile (H = 0) is always the latter.
template <class T, class PatchAt>
T field_sweep_mean(field_sweep<T>& sweep, const PatchAt& patch_at,
                   const field_radiance<T>& radiance, const field_rules<T>& rules, const T& phi,
                   const T& end) noexcept {
  using namespace field_detail;
  if (!(sweep.built && phi >= sweep.from && phi <= sweep.to)) {
    sweep.built = true;
    sweep.modelled = false;
    const long key = radiance.profile->scale_m > T(0) && end - phi >= sweep.narrowest
                         ? sweep_key_at(patch_at, radiance, rules, phi)
                         : -1;
    T b = key < 0
              ? phi
              : sweep_structured_end(sweep, patch_at, radiance, rules, phi,
                                     T(phi + sweep.width < end ? T(phi + sweep.width) : end), key);
    // A segment of the narrowest width, less rounding, is still one.
    const T shortest = sweep.narrowest * (T(1) - T(1) / T(1000000));
    const bool structural = !(b - phi >= shortest);
    bool structured = true;
    while (b - phi >= shortest) {
      if (field_sweep_build(sweep, patch_at, radiance, rules, phi, b, key, structured)) {
        sweep.width = T(2) * (b - phi) < sweep.widest ? T(T(2) * (b - phi)) : sweep.widest;
        break;
      }
      b = phi + (b - phi) * sweep_shrink(sweep.excess);
      sweep.width = b - phi > sweep.narrowest ? T(b - phi) : sweep.narrowest;
      structured = false;
    }
    // Left to the exact means: up to where G's structure changes (at least a quarter of the
    // narrowest width), or the narrowest width where a model did not converge.
    if (!sweep.modelled) {
      const T quarter = phi + sweep.narrowest / T(4);
      sweep.from = phi;
      sweep.to = structural ? T(b > quarter ? b : quarter) : T(phi + sweep.narrowest);
    }
  }
  T mean;
  if (sweep.modelled && swept_mean(sweep, radiance, rules, phi, mean)) return mean;
  return field_mean_at(patch_at(phi), radiance, rules);
}

}  // namespace conescan

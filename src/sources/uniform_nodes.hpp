// Four-point (cubic) Lagrange interpolation on equally spaced nodes, as the sources' tracks use it
// (scene_frame.hpp's frame_track, sun_moon.hpp's sun_moon_track).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace conescan::sources {

/// The four nodes first, first + 1, first + 2, first + 3 around a query and their weights.
struct cubic_window {
  std::size_t first = 0;
  double weight[4] = {0, 0, 0, 0};
};

/// The window for a query x, in node units from node 0 (x = seconds from node 0 / spacing), of a
/// series of node_count >= 4 nodes: the nodes k - 1 .. k + 2 around x in [k, k + 1], shifted
/// inwards at the ends (x outside [1, node_count - 2] is extrapolated by the end cubic).
/// Interpolation error of a function f: |f''''| h^4 (9/16) / 24 at most, at the middle interval's
/// centre.
inline cubic_window cubic_window_at(double x, std::size_t node_count) noexcept {
  const auto last_start = static_cast<double>(node_count - 4);
  const double start = std::clamp(std::floor(x) - 1.0, 0.0, last_start);
  const double u = x - start;  // the nodes sit at 0, 1, 2, 3
  return {static_cast<std::size_t>(start),
          {-(u - 1) * (u - 2) * (u - 3) / 6, u * (u - 2) * (u - 3) / 2, -u * (u - 1) * (u - 3) / 2,
           u * (u - 1) * (u - 2) / 6}};
}

/// Nodes that cover [0, span_s] at `spacing_s` with one node more on either side: at least 4.
inline std::size_t nodes_covering(double span_s, double spacing_s) noexcept {
  return std::max<std::size_t>(4, static_cast<std::size_t>(std::ceil(span_s / spacing_s)) + 3);
}

}  // namespace conescan::sources

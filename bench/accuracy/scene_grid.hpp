// The grid of scenes over which accuracy is measured: every combination of the axes below,
// covering the whole valid input domain of a head (MODEL §4, §7), in the user's units.
#pragma once

#include <cstddef>
#include <vector>

namespace conescan::accuracy {

/// One scene of one head, zero true attitude (degrees, km).
struct scene_point {
  double alpha_deg;  ///< mounting elevation of the spin axis, (-90, 90); beta is 90 deg
  double alt_km;     ///< orbit radius minus WGS84 a
  double gamma_deg;  ///< half-apex cone angle, (0, 90)
  double sigma_deg;  ///< misalignment, [0, gamma)
  double phi_a_deg;  ///< azimuth of the misalignment about S
  double lat_deg;    ///< geocentric latitude of the satellite (the ellipsoid method only)
};

/// The values taken on each axis.
struct grid_axes {
  std::vector<double> alpha_deg;
  std::vector<double> alt_km;
  std::vector<double> gamma_deg;
  std::vector<double> sigma_deg;
  std::vector<double> phi_a_deg;
  /// Latitudes are not a grid axis (that would multiply the cost by their number for one
  /// method): scene k takes lat_deg[k % size], so every latitude meets every other axis.
  std::vector<double> lat_deg;
};

/// The benchmark's grid: alpha from near -90 to near +90 (spin axis near zenith to near nadir),
/// low Earth orbit to geostationary, cones from 2 to 88 deg, misalignments from none to 3 deg,
/// both symmetric (0, 180 deg) and asymmetric misalignment azimuths.
inline grid_axes benchmark_grid_axes() {
  return {{-85, -60, -35, -10, 0, 10, 20, 35, 50, 65, 80, 89},
          {200, 400, 800, 1500, 3000, 8000, 20000, 35786},
          {2, 10, 25, 45, 60, 75, 88},
          {0, 0.001, 0.02, 0.5, 3},
          {0, 135, 180, 270},
          {0, 30, 55, 80, -45}};
}

/// A coarser grid of the same extent for the unit tests (a multiprecision reference of the scan
/// models costs milliseconds per scene).
inline grid_axes test_grid_axes() {
  return {{-60, -20, 0, 20, 45, 85},
          {300, 900, 6000, 35786},
          {5, 30, 45, 70},
          {0, 0.02, 2},
          {0, 135},
          {0, 40, 75}};
}

/// Every combination of the axes with sigma < gamma (MODEL §7: the cone must enclose S).
inline std::vector<scene_point> scene_grid(const grid_axes& axes) {
  std::vector<scene_point> scenes;
  for (double alpha : axes.alpha_deg)
    for (double alt : axes.alt_km)
      for (double gamma : axes.gamma_deg)
        for (double sigma : axes.sigma_deg)
          for (double phi_a : axes.phi_a_deg) {
            if (!(sigma < gamma)) continue;
            const double lat = axes.lat_deg[scenes.size() % axes.lat_deg.size()];
            scenes.push_back({alpha, alt, gamma, sigma, phi_a, lat});
          }
  return scenes;
}

}  // namespace conescan::accuracy

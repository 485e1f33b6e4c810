// The Earth figure of the accuracy scenes, from the orbit layer's WGS84 (MODEL §3).
#pragma once

#include "accuracy/head_sample.hpp"
#include "orbit/wgs84.hpp"

namespace conescan::accuracy {

/// Sphere of radius WGS84 a; ellipsoid a, b with horizon height 0.
inline earth_figure wgs84_figure() {
  const orbit::earth_constants& w = orbit::wgs84();
  return {w.a_m, w.a_m, w.b_m};
}

}  // namespace conescan::accuracy

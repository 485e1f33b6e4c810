#include "orbit/wgs84.hpp"

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/NormalGravity.hpp>

namespace conescan::orbit {

const earth_constants& wgs84() noexcept {
  static const earth_constants values = [] {
    using GeographicLib::Constants;
    const double a = Constants::WGS84_a();
    const double f = Constants::WGS84_f();
    return earth_constants{a, f, a * (1 - f), Constants::WGS84_GM(),
                           GeographicLib::NormalGravity::WGS84().DynamicalFormFactor(2)};
  }();
  return values;
}

}  // namespace conescan::orbit

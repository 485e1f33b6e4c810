// The truth for accuracy: the same core templates instantiated with 50 decimal digits.
#pragma once

#include <boost/multiprecision/cpp_bin_float.hpp>

namespace conescan::accuracy {

/// Boost.Multiprecision's cpp_bin_float_50 (expression templates off, so the core's rule "no
/// auto for scalar intermediates" is not even needed for it). With 50 digits its rounding is
/// ~1e-50, so every difference measured against it is the tested precision's own error.
using reference_scalar = boost::multiprecision::cpp_bin_float_50;

}  // namespace conescan::accuracy

// A position and velocity, SI units, in one frame (the frame is said where the state is used).
#pragma once

#include "conescan/vector.hpp"

namespace conescan::sources {

struct cartesian_state {
  vec3<double> r_m{0.0};
  vec3<double> v_m_s{0.0};
};

}  // namespace conescan::sources

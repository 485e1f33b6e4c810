// Sensor physics (MODEL §12): the crossings that a head's radiance, field of view, detector lag
// and locator produce, in place of the geometric crossings of MODEL §5. Its steps live in
// include/conescan/sensor_physics/, one file each (docs/SENSOR_PHYSICS.md has the map).
#pragma once

#include "conescan/sensor_physics/chain.hpp"

// conescan core: everything a flight-software prototype needs, header-only, GLM and the standard
// library only, templated on the scalar type.
#pragma once

#include "conescan/attitude.hpp"
#include "conescan/bias_model.hpp"
#include "conescan/cone_angle.hpp"
#include "conescan/crossings.hpp"
#include "conescan/earth_disk.hpp"
#include "conescan/ellipsoid_horizon.hpp"
#include "conescan/half_chord.hpp"
#include "conescan/horizon_vector.hpp"
#include "conescan/measurement_errors.hpp"
#include "conescan/nadir_angle.hpp"
#include "conescan/orbital_frame.hpp"
#include "conescan/processing.hpp"
#include "conescan/root_finding.hpp"
#include "conescan/scalar.hpp"
#include "conescan/scan_frame.hpp"
#include "conescan/scan_model.hpp"
#include "conescan/scan_model_iterative.hpp"
#include "conescan/sensor_head.hpp"
#include "conescan/status.hpp"
#include "conescan/vector.hpp"

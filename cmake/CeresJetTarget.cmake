# Ceres serves conescan only through its automatic-differentiation scalar ceres::Jet (the
# calibration's Jacobians through the forward model and the sensor physics): a header of
# libceres-dev over Eigen's. This wraps the two into one header-only target, here and nowhere
# else, so no program links libceres or its solvers' dependencies.
#   CONESCAN_CERES_JET_REQUIRED ON: a missing header is an error (the calibration needs it);
#   otherwise the target is simply not made (the tests of the core alone use it where it is).
find_package(Eigen3 3.3 QUIET NO_MODULE)
find_path(CERES_JET_INCLUDE_DIR ceres/jet.h)
if(NOT TARGET CeresJet::CeresJet AND Eigen3_FOUND AND CERES_JET_INCLUDE_DIR)
  add_library(CeresJet::CeresJet INTERFACE IMPORTED)
  set_target_properties(CeresJet::CeresJet PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${CERES_JET_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES Eigen3::Eigen)
endif()
if(CONESCAN_CERES_JET_REQUIRED AND NOT TARGET CeresJet::CeresJet)
  message(FATAL_ERROR "ceres/jet.h or Eigen 3 not found (Debian: apt-get install libceres-dev; "
                      "scripts/setup.sh does)")
endif()

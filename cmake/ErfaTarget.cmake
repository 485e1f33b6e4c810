# Debian's liberfa-dev (ERFA 2.0.0) ships <erfa.h> and liberfa but no CMake package and no
# pkg-config use here: find both and wrap them into one imported target, here and nowhere else.
find_path(ERFA_INCLUDE_DIR erfa.h)
find_library(ERFA_LIBRARY erfa)
if(NOT ERFA_INCLUDE_DIR OR NOT ERFA_LIBRARY)
  message(FATAL_ERROR "ERFA not found (Debian: apt-get install liberfa-dev; scripts/setup.sh does)")
endif()
if(NOT TARGET ERFA::ERFA)
  add_library(ERFA::ERFA UNKNOWN IMPORTED)
  set_target_properties(ERFA::ERFA PROPERTIES
    IMPORTED_LOCATION "${ERFA_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${ERFA_INCLUDE_DIR}")
endif()

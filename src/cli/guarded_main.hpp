// Both programs' main(): memory that runs out anywhere (a huge sweep's summary, a fit's
// matrices) ends the program with a message and status 1, never std::terminate's abort.
#pragma once

#include <cstdio>
#include <new>

namespace conescan::cli {

/// run(argc, argv), or status 1 with "PROGRAM: out of memory" on standard error when it throws
/// std::bad_alloc.
inline int guarded_main(const char* program, int (*run)(int, char**), int argc,
                        char** argv) noexcept {
  try {
    return run(argc, argv);
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "%s: out of memory\n", program);
    return 1;
  }
}

}  // namespace conescan::cli

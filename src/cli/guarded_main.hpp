// Both programs' main(): memory that runs out anywhere (a huge sweep's summary, a fit's
// matrices) ends the program with a message and status 1, never std::terminate's abort.
#pragma once

#include <cstdio>
#include <new>

#include "text/out_of_memory.hpp"

namespace conescan::cli {

/// run(argc, argv), or status 1 with "PROGRAM: out of memory" on standard error when it throws
/// std::bad_alloc ("PROGRAM: --OPTION: FILE: out of memory while reading it" when a reader's
/// text::naming_input said what it read).
inline int guarded_main(const char* program, int (*run)(int, char**), int argc,
                        char** argv) noexcept {
  try {
    return run(argc, argv);
  } catch (const text::out_of_memory_reading& reading) {
    std::fprintf(stderr, "%s: %s: out of memory while reading it\n", program, reading.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "%s: out of memory\n", program);
    return 1;
  }
}

}  // namespace conescan::cli

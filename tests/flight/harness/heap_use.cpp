// A program that uses the heap, as a core function that allocated would: on the target it must
// not link (no _sbrk: the harness links no system calls), so that no allocation reaches flight
// code unnoticed. ctest flight.no_heap expects the link to fail for this reason.
#include <cstdlib>

extern "C" int main() {
  void* volatile p = std::malloc(64);
  return p == nullptr ? 1 : 0;
}

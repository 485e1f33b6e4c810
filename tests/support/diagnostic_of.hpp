// For tests that check the parts of a refusal: the diagnostic a checked value holds.
#pragma once

#include "text/diagnostic.hpp"

/// The diagnostic `r` holds, or nullptr when it holds a value.
template <class T>
const conescan::diagnostic* error_of(const conescan::checked<T>& r) {
  return r.ok() ? nullptr : &r.error();
}

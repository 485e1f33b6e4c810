// Turns a fuzzer's bytes into choices and scalars. Header-only and dependency-free, so that the
// Catch2 suite (built by g++, without libFuzzer) replays the corpus through the same harnesses.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "conescan/half_chord.hpp"
#include "conescan/scalar.hpp"

namespace conescan_fuzz {

/// Reads bytes from the front; past the end every byte is 0, so any input is a valid one.
class byte_reader {
 public:
  byte_reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t byte() { return used_ < size_ ? data_[used_++] : std::uint8_t{0}; }

  std::uint64_t u64() {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v = (v << 8) | byte();
    return v;
  }

  /// An integer in [0, n), n in [1, 256].
  unsigned pick(unsigned n) { return static_cast<unsigned>(byte()) % n; }

  /// The inputs drawn so far, for the failure message.
  std::vector<long double>& drawn() { return drawn_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t used_ = 0;
  std::vector<long double> drawn_;
};

/// Values on or next to the edges of MODEL §7's domains, and IEEE's own.
template <class T>
T special_value(unsigned k) {
  using lim = std::numeric_limits<T>;
  using std::nextafter;
  const T pi = conescan::pi<T>();
  const T graze = conescan::grazing_half_chord_min<T>();
  switch (k) {
    case 0:
      return T(0);
    case 1:
      return -T(0);
    case 2:
      return lim::denorm_min();
    case 3:
      return -lim::denorm_min();
    case 4:
      return lim::min();
    case 5:
      return lim::max();
    case 6:
      return lim::lowest();
    case 7:
      return lim::epsilon();
    case 8:
      return lim::infinity();
    case 9:
      return -lim::infinity();
    case 10:
      return lim::quiet_NaN();
    case 11:
      return T(1);
    case 12:
      return T(-1);
    case 13:
      return pi / T(2);
    case 14:
      return nextafter(pi / T(2), T(0));
    case 15:
      return nextafter(pi / T(2), T(4));
    case 16:
      return pi;
    case 17:
      return nextafter(pi, T(0));
    case 18:
      return nextafter(pi, T(4));
    case 19:
      return T(2) * pi;
    case 20:
      return -pi;
    case 21:
      return graze;
    case 22:
      return nextafter(graze, T(0));
    case 23:
      return pi - graze;
    case 24:
      return nextafter(T(pi - graze), T(4));
    case 25:
      return pi / T(4);
    case 26:
      return conescan::deg_to_rad(T(1) / T(50));  // the paper's sigma
    case 27:
      return T(1) / T(1 << 20);
    case 28:
      return T(65536) * T(65536) * T(65536);  // 2^48: angles whose ulp is large
    case 29:
      return T(7280000);  // the paper's a, m
    case 30:
      return T(6378137);  // WGS84 a, m
    default:
      return T(6356752);  // WGS84 b, m (rounded)
  }
}
inline constexpr unsigned special_value_count = 32;

/// Any bit pattern of T (NaN payloads, infinities, denormals).
template <class T>
T raw_value(byte_reader& in) {
  if constexpr (sizeof(T) == sizeof(float)) {
    std::uint32_t bits = static_cast<std::uint32_t>(in.u64());
    T v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  } else {
    // double's bit patterns; long double holds every one of them exactly.
    std::uint64_t bits = in.u64();
    double d;
    std::memcpy(&d, &bits, sizeof d);
    return T(d);
  }
}

/// A scalar for a core routine: a raw bit pattern, a special value, a value spread over
/// [-4, 4] (where the angles of the model live), or a few ulp away from a special value.
template <class T>
T draw(byte_reader& in) {
  T v = T(0);
  switch (in.pick(4)) {
    case 0:
      v = raw_value<T>(in);
      break;
    case 1:
      v = special_value<T>(in.pick(special_value_count));
      break;
    case 2: {
      const std::uint64_t u = in.u64() >> 11;  // 53 bits
      v = T(static_cast<double>(u) * 0x1p-53 * 8.0 - 4.0);
      break;
    }
    default: {
      v = special_value<T>(in.pick(special_value_count));
      const unsigned steps = in.pick(8);
      const T toward =
          in.pick(2) ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity();
      for (unsigned i = 0; i < steps; ++i) v = std::nextafter(v, toward);
      break;
    }
  }
  in.drawn().push_back(static_cast<long double>(v));
  return v;
}

/// "<routine> <type>: <what> (inputs: ...)", the text a failed invariant reports.
inline std::string failure(const char* routine, const char* type, const std::string& what,
                           const std::vector<long double>& inputs) {
  std::ostringstream s;
  s.precision(21);
  s << routine << " <" << type << ">: " << what << " (inputs:";
  for (long double x : inputs) s << ' ' << x;
  s << ')';
  return s.str();
}

}  // namespace conescan_fuzz

// src/text/shortest_double.hpp: the CSV's number text must be std::to_chars' byte for byte
// (MODEL §9: round-trip exact, shortest). Its table and its fixed-point logarithms are checked
// against exact integers (Boost's cpp_int); its output against std::to_chars on every exponent,
// both sides of every layout boundary, and millions of random values.
#include <boost/multiprecision/cpp_int.hpp>
#include <catch2/catch.hpp>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "text/shortest_double.hpp"

namespace {

using boost::multiprecision::cpp_int;
namespace fmt = conescan::text;

cpp_int power(int base, int exponent) {
  return boost::multiprecision::pow(cpp_int(base), exponent);
}

std::string ours(double value) {
  char buffer[fmt::shortest_double_room];
  return std::string(buffer, fmt::write_shortest_double(buffer, value));
}

std::string standard(double value) {
  char buffer[64];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

double from_bits(std::uint64_t bits) {
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

/// Counts the values whose text differs from std::to_chars' or does not read back, and reports
/// the first few (a failure names the value).
struct comparison {
  long checked = 0, mismatches = 0;
  void check(double value) {
    ++checked;
    const std::string text = ours(value);
    double back = 0;
    std::from_chars(text.data(), text.data() + text.size(), back);
    const bool reads_back = std::isnan(value) ? std::isnan(back) : back == value;
    if (text == standard(value) && reads_back && text.size() <= 24) return;
    if (++mismatches <= 5) {
      char hex[64];
      std::snprintf(hex, sizeof hex, "%a", value);
      UNSCOPED_INFO(hex << ": ours " << text << ", std::to_chars " << standard(value));
    }
  }
  void check_with_neighbours(double value) {
    check(value);
    check(std::nextafter(value, 0.0));
    check(std::nextafter(value, std::numeric_limits<double>::infinity()));
    check(-value);
  }
};

}  // namespace

TEST_CASE("shortest_double: the 126-bit powers of ten are exact", "[format]") {
  // g(k) = floor(10^-k 2^-r) + 1 with 2^125 <= floor(10^-k 2^-r) < 2^126 (Schubfach, 9.8.3).
  for (int k = fmt::detail::pow10_k_min; k <= fmt::detail::pow10_k_max; ++k) {
    const int r = fmt::detail::floor_log2_pow10(-k) - 125;
    cpp_int floor_beta;
    if (k <= 0) {
      const cpp_int ten_to_minus_k = power(10, -k);
      floor_beta = r >= 0 ? cpp_int(ten_to_minus_k >> r) : cpp_int(ten_to_minus_k << -r);
    } else {
      floor_beta = (cpp_int(1) << -r) / power(10, k);
    }
    REQUIRE(floor_beta >= (cpp_int(1) << 125));
    REQUIRE(floor_beta < (cpp_int(1) << 126));
    const cpp_int g = floor_beta + 1;
    const auto& entry = fmt::detail::pow10_table[k - fmt::detail::pow10_k_min];
    INFO("k = " << k);
    CHECK(cpp_int(entry.g1) == (g >> 63));
    CHECK(cpp_int(entry.g0) == (g & ((cpp_int(1) << 63) - 1)));
  }
}

TEST_CASE("shortest_double: the fixed-point logarithms are floors over the doubles' exponents",
          "[format]") {
  // 10^k <= x < 10^(k+1) with x = 2^e (or 3/4 2^e), and 2^k <= 10^e < 2^(k+1), by exact
  // integers: both sides scaled by the powers with negative exponents.
  auto log10_floor_ok = [](int k, cpp_int num, cpp_int den) {  // x = num / den
    const cpp_int lower = k >= 0 ? power(10, k) * den : den;
    const cpp_int lower_x = k >= 0 ? num : num * power(10, -k);
    const cpp_int upper = k + 1 >= 0 ? power(10, k + 1) * den : den;
    const cpp_int upper_x = k + 1 >= 0 ? num : num * power(10, -(k + 1));
    return lower <= lower_x && upper_x < upper;
  };
  for (int e = -2000; e <= 2000; ++e) {  // the range the header states
    INFO("e = " << e);
    const cpp_int two_num = e >= 0 ? power(2, e) : cpp_int(1);
    const cpp_int two_den = e >= 0 ? cpp_int(1) : power(2, -e);
    CHECK(log10_floor_ok(fmt::detail::floor_log10_pow2(e), two_num, two_den));
    CHECK(
        log10_floor_ok(fmt::detail::floor_log10_three_quarters_pow2(e), 3 * two_num, 4 * two_den));
  }
  for (int e = -2000; e <= 2000; ++e) {
    INFO("e = " << e);
    const int k = fmt::detail::floor_log2_pow10(e);
    // 2^k <= 10^e < 2^(k+1); for e < 0 (then k < 0) with T = 10^-e: 2^-(k+1) < T <= 2^-k.
    const cpp_int ten = power(10, e >= 0 ? e : -e);
    if (e >= 0) {
      CHECK(power(2, k) <= ten);
      CHECK(ten < power(2, k + 1));
    } else {
      CHECK(ten <= power(2, -k));
      CHECK(power(2, -(k + 1)) < ten);
    }
  }
}

TEST_CASE("shortest_double: every power of two and ten, and their neighbours", "[format]") {
  comparison c;
  for (int e = -1074; e <= 1023; ++e) c.check_with_neighbours(std::ldexp(1.0, e));
  for (int e = -323; e <= 308; ++e)
    c.check_with_neighbours(std::strtod(("1e" + std::to_string(e)).c_str(), nullptr));
  CHECK(c.mismatches == 0);
}

TEST_CASE("shortest_double: both sides of every layout and path boundary", "[format]") {
  comparison c;
  const double two_53 = 9007199254740992.0;
  for (double v :
       {0.0, -0.0, 1.0, 0.5, 0.1, 0.2, 0.3, 1.0 / 3, 2.0 / 3, 100.0, 123.456,
        // fixed "0.001" against scientific "1e-04": the fixed/scientific switch
        1e-3, 1e-4, 1.5e-4, 1.25e-3, 0.0001234, 0.00012345678901234,
        // integers, up to and past 2^53 where std::to_chars prints exact digits
        1e15, 1e16, 123456789012345.0, 1234567890123456.0, two_53, two_53 - 1, two_53 + 2,
        1.2345678901234568e20, 1e21, 1e22, 1e23,
        // the limits and the subnormals (std::to_chars' own path)
        std::numeric_limits<double>::min(), std::numeric_limits<double>::max(),
        std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::epsilon(),
        std::numeric_limits<double>::min() - std::numeric_limits<double>::denorm_min(),
        std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN(),
        // the paper scene's columns (MODEL §8)
        7280.0, 6552.0, 901.86300000000006, 61.177534646913955, 137.6061228613589,
        5.8086553383535196e-05, -0.0064692930856724727})
    c.check_with_neighbours(v);
  for (int exponent = -5; exponent <= 17; ++exponent) {  // every decimal point position
    for (double digits : {1.0, 1.5, 1.25, 9.875, 1.2345678901234567, 9.9999999999999982}) {
      c.check_with_neighbours(digits * std::pow(10.0, exponent));
    }
  }
  CHECK(c.mismatches == 0);
}

TEST_CASE("shortest_double: millions of random values match std::to_chars", "[format]") {
  comparison c;
  std::mt19937_64 random(20261122);
  std::uniform_real_distribution<double> decade(-30, 30);
  for (int i = 0; i < 1'000'000; ++i) c.check(from_bits(random()));  // every exponent
  // 10^-30 .. 10^30: the fast path below 2^53 (about 60 %), std::to_chars above it.
  for (int i = 0; i < 1'000'000; ++i) c.check(std::pow(10.0, decade(random)));
  for (std::int64_t i = 0; i < 200'000; ++i) {  // short decimals: times, steps, angles
    const double n = static_cast<double>(i);
    c.check(n);
    c.check(n / 10);
    c.check(n / 100);
    c.check(n * 0.01);
  }
  INFO(c.checked << " values");
  CHECK(c.mismatches == 0);
}

// The shortest decimal text of a double that reads back to the same double: byte for byte what
// std::to_chars(first, last, value) writes (C++17 [charconv.to.chars]: the fewest characters,
// fixed notation on a tie; among the shortest digit strings the one nearest the value, ties to
// even), in about half the instructions of libstdc++'s (~290 against ~530 per number) and 0.70
// of its time on conescan-sim's numbers (bench/format_speed.cpp, docs/PERFORMANCE.md).
//
// Why: MODEL §9 asks for round-trip exact numbers, and libstdc++'s std::to_chars was half of
// conescan-sim's time per row. The digits come from Schubfach (R. Giulietti, "The Schubfach way
// to render doubles", 2020; the algorithm of Java 19's Double.toString), which needs one 126-bit
// power of ten per call (src/text/pow10_table.hpp) and three 64x128-bit products.
//
// Domain: every double. The fast path covers zero and the normal doubles below 2^53 in
// magnitude, which is every number conescan-sim writes in practice; subnormals, |x| >= 2^53
// (where to_chars may print the exact integer digits of a fixed-notation value), infinities and
// NaN go to std::to_chars itself. tests/text/test_shortest_double.cpp compares the two byte for
// byte on about 3 million values over every exponent; tests/fuzz/fuzz_shortest_double.cpp does the
// same on any bit pattern (115 million runs clean), and an independent review compared 1.07
// billion values (every exponent, 10^9 random fast-path values, the neighbours of every power
// of ten) without a mismatch.
#pragma once

#include <charconv>
#include <cstdint>
#include <cstring>

#include "text/pow10_table.hpp"

namespace conescan::text {

/// The room write_shortest_double needs at `first`. The text itself is at most 24 characters
/// ("-2.2250738585072014e-308"); the rest is scratch for fixed-size copies.
inline constexpr int shortest_double_room = 40;

namespace detail {

__extension__ using uint128 = unsigned __int128;

/// The decimal significand and exponent of a double's shortest form: value = significand
/// 10^exponent.
struct decimal {
  std::uint64_t significand;
  int exponent;
};

// floor(log10(2^e)), floor(log10(3/4 2^e)) and floor(log2(10^e)) by fixed-point products,
// exact for |e| <= 2000 (Schubfach, section 9.8.1; checked in the tests against cpp_int).
constexpr int floor_log10_pow2(int e) noexcept {
  return static_cast<int>(e * 661'971'961'083LL >> 41);
}
constexpr int floor_log10_three_quarters_pow2(int e) noexcept {
  return static_cast<int>((e * 661'971'961'083LL - 274'743'187'321LL) >> 41);
}
constexpr int floor_log2_pow10(int e) noexcept {
  return static_cast<int>(e * 913'124'641'741LL >> 38);
}
// The fast path's binary exponents, -1074 <= q <= 0, stay inside the table.
static_assert(floor_log10_pow2(-1074) >= pow10_k_min && floor_log10_pow2(0) <= pow10_k_max);
static_assert(floor_log10_three_quarters_pow2(-1073) >= pow10_k_min &&
              floor_log10_three_quarters_pow2(0) <= pow10_k_max);

/// round-to-odd of cp g 2^-127, g = g1 2^63 + g0 (Schubfach, section 9.9, figure 8): the
/// product's integer part with the discarded fraction kept as a sticky bit, which is all the
/// interval tests below need.
inline std::uint64_t round_to_odd(std::uint64_t g1, std::uint64_t g0, std::uint64_t cp) noexcept {
  const auto x1 = static_cast<std::uint64_t>((uint128{g0} * cp) >> 64);
  const uint128 y = uint128{g1} * cp;
  const auto y0 = static_cast<std::uint64_t>(y);
  const auto y1 = static_cast<std::uint64_t>(y >> 64);
  const std::uint64_t z = (y0 >> 1) + x1;
  constexpr std::uint64_t mask63 = (std::uint64_t{1} << 63) - 1;
  return (y1 + (z >> 63)) | (((z & mask63) + mask63) >> 63);
}

/// The shortest decimal in the rounding interval of c 2^q, nearest to it, ties to even
/// (Schubfach, figure 7). c: a normal double's 53-bit significand; q: its binary exponent.
inline decimal schubfach(std::uint64_t c, int q) noexcept {
  constexpr std::uint64_t c_min = std::uint64_t{1} << 52;
  const std::uint64_t out = c & 1;  // an even significand's interval includes its bounds
  const std::uint64_t cb = c << 2;
  const std::uint64_t cbr = cb + 2;
  std::uint64_t cbl;
  int k;
  if (c != c_min || q == -1074) {  // regular spacing (the smallest normal binade borders the
                                   // subnormals, which are spaced alike)
    cbl = cb - 2;
    k = floor_log10_pow2(q);
  } else {  // a power of two: the interval below is half as wide
    cbl = cb - 1;
    k = floor_log10_three_quarters_pow2(q);
  }
  const int h = q + floor_log2_pow10(-k) + 2;
  // k <= 0 on the fast path (q <= 0): the table stops at pow10_k_max = 0.
  const pow10_entry& g = pow10_table[k - pow10_k_min];
  const std::uint64_t vb = round_to_odd(g.g1, g.g0, cb << h);
  const std::uint64_t vbl = round_to_odd(g.g1, g.g0, cbl << h);
  const std::uint64_t vbr = round_to_odd(g.g1, g.g0, cbr << h);

  const std::uint64_t s = vb >> 2;
  if (s >= 100) {  // one digit fewer: at most one multiple of 10 10^k lies in the interval
    const std::uint64_t sp10 = s / 10 * 10;
    const std::uint64_t tp10 = sp10 + 10;
    const bool upin = vbl + out <= sp10 << 2;
    const bool wpin = (tp10 << 2) + out <= vbr;
    if (upin != wpin) return {upin ? sp10 : tp10, k};
  }
  const std::uint64_t t = s + 1;
  const bool uin = vbl + out <= s << 2;
  const bool win = (t << 2) + out <= vbr;
  if (uin != win) return {uin ? s : t, k};
  // Both s 10^k and t 10^k round to the double: the nearer, ties to even.
  const auto cmp = static_cast<std::int64_t>(vb - ((s + t) << 1));
  return {cmp < 0 || (cmp == 0 && (s & 1) == 0) ? s : t, k};
}

/// The digits of two 4-digit groups, fours = g_first | g_second << 32 (each < 10^4), one per
/// byte (0..9, not yet ASCII), the most significant in the lowest byte, which comes first in
/// memory on x86-64. SWAR: each 32-bit lane splits into two 2-digit lanes of 16 bits (x / 100 as
/// x 10486 >> 20, exact for x < 10^4), each into two 1-digit bytes (x / 10 as x 103 >> 10, exact
/// for x < 100).
inline std::uint64_t digit_bytes_of_fours(std::uint64_t fours) noexcept {
  static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "digits are laid out little-endian");
  const std::uint64_t hundreds = (fours * 10'486 >> 20) & 0x0000'007f'0000'007fu;
  const std::uint64_t twos = hundreds | (fours - hundreds * 100) << 16;
  const std::uint64_t tens = (twos * 103 >> 10) & 0x000f'000f'000f'000fu;
  return tens | (twos - tens * 10) << 8;
}

inline constexpr char digit_pairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

inline constexpr std::uint64_t ascii_zeros = 0x3030'3030'3030'3030u;

inline void store_16(char* out, uint128 bytes) noexcept {
  const auto low = static_cast<std::uint64_t>(bytes),
             high = static_cast<std::uint64_t>(bytes >> 64);
  std::memcpy(out, &low, 8);
  std::memcpy(out + 8, &high, 8);
}

inline constexpr std::uint64_t powers_of_ten[] = {1,
                                                  10,
                                                  100,
                                                  1'000,
                                                  10'000,
                                                  100'000,
                                                  1'000'000,
                                                  10'000'000,
                                                  100'000'000,
                                                  1'000'000'000,
                                                  10'000'000'000,
                                                  100'000'000'000,
                                                  1'000'000'000'000,
                                                  10'000'000'000'000,
                                                  100'000'000'000'000,
                                                  1'000'000'000'000'000,
                                                  10'000'000'000'000'000,
                                                  100'000'000'000'000'000,
                                                  1'000'000'000'000'000'000,
                                                  10'000'000'000'000'000'000u};

/// The number of decimal digits of n > 0.
inline int decimal_digit_count(std::uint64_t n) noexcept {
  const int bits = 64 - __builtin_clzll(n);
  const int lower = bits * 1233 >> 12;  // floor(bits log10 2): the count is lower or lower + 1
  return lower + (n >= powers_of_ten[lower]);
}

/// Room that write_decimal may use past `out`: it writes 16 digits at a time from registers and
/// lets later writes and the end of the text cut them short, which is cheaper than copies of the
/// exact length (and never reads back what it wrote). The farthest write is the fraction of
/// ddd.ddd, 16 characters from offset e + 2 <= 17.
inline constexpr int write_decimal_room = 33;
static_assert(write_decimal_room + 1 <= shortest_double_room, "the sign comes first");

/// Lays out significand 10^exponent (0 < significand < 10^17, which Schubfach guarantees) as
/// std::to_chars does: fixed or scientific, whichever is shorter, fixed on a tie; the exponent
/// with a sign and at least two digits. Uses up to write_decimal_room characters at `out`;
/// returns the end of the text. Precondition: the value is below 10^17 (e <= 16), which the
/// caller's |x| < 2^53 guarantees: fixed notation of a larger value would need zeros past the
/// 17 digits written here.
inline char* write_decimal(char* out, decimal d) noexcept {
  const int count = decimal_digit_count(d.significand);
  const int e = d.exponent + count - 1;  // value = d.ddd 10^e
  // The 17 digit places of the significand, leading zeros included: `top` (the 17th place), then
  // four groups of 4 digits, each a quotient by a power of ten of the significand itself. Why
  // not first scale the significand to 17 digits by its digit count: that puts the count, a
  // product and three dependent divisions ahead of the digits, and the formatter is bound by
  // that chain's latency, not by its instructions (27 % less time per number, measured in
  // docs/PERFORMANCE.md). The leading zeros are shifted out at the end instead.
  const std::uint64_t sig = d.significand;
  const std::uint64_t q4 = sig / 10'000, q8 = sig / 100'000'000, q12 = sig / 1'000'000'000'000,
                      top = sig / 10'000'000'000'000'000;
  const std::uint64_t g0 = sig - q4 * 10'000, g1 = q4 - q8 * 10'000, g2 = q8 - q12 * 10'000,
                      g3 = q12 - top * 10'000;
  const uint128 places =
      (uint128{digit_bytes_of_fours(g1 | g0 << 32)} << 64) | digit_bytes_of_fours(g3 | g2 << 32);
  // 17 digits: `top` is the first and `places` the other 16. Fewer: `places` holds them all
  // after 16 - count zero bytes; the first is the lowest byte once those are shifted out, and
  // the rest follow it, zero-filled on the right.
  const uint128 from_first = count >= 17 ? places : places >> (8 * (16 - count));
  const std::uint64_t first = count >= 17 ? top : static_cast<std::uint64_t>(from_first) & 0xff;
  const uint128 rest = count >= 17 ? from_first : from_first >> 8;
  const auto upper = static_cast<std::uint64_t>(rest),
             lower = static_cast<std::uint64_t>(rest >> 64);
  const uint128 digits = rest + ((uint128{ascii_zeros} << 64) | ascii_zeros);
  // The significant digits: 17 less the zero bytes at the top (the last digits).
  const int trailing_zeros =
      lower != 0 ? __builtin_clzll(lower) / 8 : 8 + (upper != 0 ? __builtin_clzll(upper) / 8 : 8);
  const int n = 17 - trailing_zeros;

  const int scientific_chars = n + (n > 1) + 2 + (e <= -100 || e >= 100 ? 3 : 2);
  const int fixed_chars = e < 0 ? n + 1 - e : (n <= e + 1 ? e + 1 : n + 1);
  if (fixed_chars <= scientific_chars) {
    if (e < 0) {  // 0.000ddd: at most 4 zeros, or scientific would be shorter
      std::memcpy(out, "0.000000", 8);
      out[1 - e] = static_cast<char>('0' + first);
      store_16(out + 2 - e, digits);
      return out + fixed_chars;
    }
    out[0] = static_cast<char>('0' + first);
    store_16(out + 1, digits);
    // ddd000 (e + 1 >= n): e <= 16 (the precondition), so the zeros are among the 17 digits
    // written above (zero-filled to 17 places). ddd.ddd: the point, then the fraction again.
    if (e + 1 >= n) return out + fixed_chars;
    out[e + 1] = '.';
    store_16(out + e + 2, digits >> (8 * e));
    return out + fixed_chars;
  }
  out[0] = static_cast<char>('0' + first);
  out[1] = '.';
  store_16(out + 2, digits);
  out += n > 1 ? n + 1 : 1;
  *out++ = 'e';
  *out++ = e < 0 ? '-' : '+';
  const int magnitude = e < 0 ? -e : e;
  if (magnitude >= 100) *out++ = static_cast<char>('0' + magnitude / 100);
  std::memcpy(out, digit_pairs + 2 * (magnitude % 100), 2);
  return out + 2;
}

}  // namespace detail

/// Writes the shortest round-trip text of `value` at `first`, exactly as
/// std::to_chars(first, first + shortest_double_room, value) would, and returns its end.
/// `first` must have room for shortest_double_room characters. Never fails.
inline char* write_shortest_double(char* first, double value) noexcept {
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  const int biased_exponent = static_cast<int>((bits >> 52) & 0x7ff);
  if (biased_exponent == 0 && fraction == 0) {  // +-0
    if (bits >> 63) *first++ = '-';
    *first = '0';
    return first + 1;
  }
  // Normal and below 2^53 (biased exponent 1023 + 52): the fast path. The rest: to_chars.
  if (biased_exponent == 0 || biased_exponent > 1075) {
    return std::to_chars(first, first + shortest_double_room, value).ptr;
  }
  if (bits >> 63) *first++ = '-';
  const std::uint64_t c = fraction | (std::uint64_t{1} << 52);
  const int q = biased_exponent - 1075;  // value = c 2^q, -1074 <= q <= 0
  // An integer: its digits are its shortest form (Schubfach, section 8.3), and the same
  // significand would otherwise cost the full algorithm.
  if (-q < 53 && ((c >> -q) << -q) == c) return detail::write_decimal(first, {c >> -q, 0});
  return detail::write_decimal(first, detail::schubfach(c, q));
}

}  // namespace conescan::text

// Random numbers whose sequence the project defines: the same draws on every machine, compiler
// and standard library, and the same draw for the same (seed, run, row, head, which) whatever
// else the simulation computes, in whatever order (a counter-based generator: no hidden state).
//
// std::normal_distribution and the std engines' adaptors are not used because the standard fixes
// the engines' sequences (mt19937_64 is defined bit for bit) but not the distributions': libstdc++,
// libc++ and MSVC draw different normals from the same engine.
//
// Algorithms:
//  - splitmix64: G. L. Steele Jr., D. Lea, C. H. Flood, "Fast splittable pseudorandom number
//    generators", OOPSLA 2014 (doi:10.1145/2660193.2660195), in the 64-bit form of S. Vigna's
//    reference implementation splitmix64.c (https://prng.di.unimi.it/splitmix64.c): the state
//    advances by the golden-ratio increment 0x9e3779b97f4a7c15 and each output is the state
//    passed through a bijective mixer (D. Stafford's "Mix13" variant of the MurmurHash3
//    finaliser). From state 0 its first outputs are 0xe220a8397b1dcdaf, 0x6e789e6aa1b965f4,
//    0x06c45d188009454f (checked in tests/test_random.cpp).
//  - Stream key: the five integers are absorbed one by one, h <- splitmix64 output from state
//    (h ^ x), starting from the output from state `seed`. Each absorption is a bijection of h for
//    a fixed x and of x for a fixed h, so two draws that differ in one integer never share a key.
//  - Uniforms in (0, 1): 52 random bits k give (2k + 1) 2^-53, the odd multiples of 2^-53 (on the
//    53-bit grid of a double in [0.5, 1)): never 0 or 1, exactly symmetric about 1/2, every value
//    exact. ((bits >> 11) + 0.5) 2^-53 would round its largest value up to exactly 1.
//  - Normal: Box-Muller (G. E. P. Box, M. E. Muller, Ann. Math. Statist. 29, 610 (1958)),
//    z = sqrt(-2 ln u1) cos(2 pi u2), with u1, u2 the first two outputs of splitmix64 from the
//    stream key. |z| < 8.6 (u1 >= 2^-53).
//
// Bit-exactness: the integer parts (keys, uniforms) are exact everywhere. The normal is defined
// up to the last-bit behaviour of the C library's std::log, std::cos and std::sqrt (sqrt is
// correctly rounded by IEEE 754; log and cos are within an ulp or so on glibc, musl, macOS and
// MSVC but not required to agree bit for bit), so two platforms may differ by an ulp in a draw.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

namespace conescan::scene {

/// splitmix64's state increment: 2^64 / golden ratio, odd.
inline constexpr std::uint64_t splitmix64_increment = 0x9e3779b97f4a7c15ULL;

/// splitmix64's output function: a bijection of the 64-bit integers (Stafford's Mix13).
constexpr std::uint64_t splitmix64_mix(std::uint64_t z) noexcept {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// One step of the splitmix64 generator: advances `state` and returns the next output.
constexpr std::uint64_t splitmix64_next(std::uint64_t& state) noexcept {
  state += splitmix64_increment;
  return splitmix64_mix(state);
}

/// The first output of splitmix64 from state x: a 64-bit hash of x (bijective).
constexpr std::uint64_t splitmix64_hash(std::uint64_t x) noexcept {
  return splitmix64_mix(x + splitmix64_increment);
}

/// The key of the stream (seed, run, row, head, which): splitmix64_hash(seed), then each of run,
/// row, head, which absorbed as h <- splitmix64_hash(h ^ x).
///   seed: the scene's seed; run: Monte Carlo run; row: time row; head: sensor head (or 0 for a
///   quantity of the whole row); which: which random quantity of that head and row.
constexpr std::uint64_t stream_key(std::uint64_t seed, std::uint64_t run, std::uint64_t row,
                                   std::uint64_t head, std::uint64_t which) noexcept {
  std::uint64_t h = splitmix64_hash(seed);
  h = splitmix64_hash(h ^ run);
  h = splitmix64_hash(h ^ row);
  h = splitmix64_hash(h ^ head);
  return splitmix64_hash(h ^ which);
}

/// A uniform double in the open interval (0, 1) from 64 random bits: (2k + 1) 2^-53 with k the
/// top 52 bits. Smallest 2^-53, largest 1 - 2^-53, all exact; never 0 or 1.
inline double uniform_open01(std::uint64_t bits) noexcept {
  const std::uint64_t odd = ((bits >> 12) << 1) | 1U;  // < 2^53: exact in a double
  return static_cast<double>(odd) * 0x1p-53;
}

/// One standard normal draw (mean 0, variance 1) of the stream (seed, run, row, head, which):
/// Box-Muller with u1, u2 = uniform_open01 of the first two splitmix64 outputs from the state
/// stream_key(seed, run, row, head, which). The same arguments give the same value on every
/// machine (to the last-bit behaviour of std::log and std::cos; see the top of this file).
inline double standard_normal(std::uint64_t seed, std::uint64_t run, std::uint64_t row,
                              std::uint64_t head, std::uint64_t which) noexcept {
  std::uint64_t state = stream_key(seed, run, row, head, which);
  const double u1 = uniform_open01(splitmix64_next(state));
  const double u2 = uniform_open01(splitmix64_next(state));
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace conescan::scene

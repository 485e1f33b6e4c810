// Random numbers whose sequence the project defines: the same draws on every machine, compiler
// and standard library, and the same draw for the same (seed, run, row, head, which) whatever else
// the simulation computes, in whatever order (a counter-based generator: no hidden state). Why not
// the standard library's distributions: docs/DECISIONS.md, "Campaigns".
//
// Algorithms (each function below states its part): splitmix64, G. L. Steele Jr., D. Lea,
// C. H. Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014
// (doi:10.1145/2660193.2660195), as S. Vigna's splitmix64.c (https://prng.di.unimi.it/); from
// state 0 its first outputs are 0xe220a8397b1dcdaf, 0x6e789e6aa1b965f4, 0x06c45d188009454f
// (tests/simulation/test_random.cpp). Box-Muller, G. E. P. Box, M. E. Muller, Ann. Math. Statist.
// 29, 610 (1958); |z| < 8.6. Bit-exactness: keys and uniforms are exact everywhere; a normal draw
// is defined up to the last bit of the C library's std::log and std::cos (within an ulp or so on
// glibc, musl, macOS and MSVC, not required to agree), so two platforms may differ by an ulp.
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
/// row, head, which absorbed as h <- splitmix64_hash(h ^ x). Each absorption is a bijection of h
/// for a fixed x and of x for a fixed h, so two draws that differ in one integer never share a key.
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
/// top 52 bits, the odd multiples of 2^-53. Smallest 2^-53, largest 1 - 2^-53, all exact, exactly
/// symmetric about 1/2; never 0 or 1 (((bits >> 11) + 0.5) 2^-53 would round its largest to 1).
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

// An enum's words: one table of (enumerator, name) pairs that both prints an enumerator and reads
// it back, so no enum is spelled out again in a switch. Used for the core's statuses (MODEL §9's
// CSV words) and by every tier above for the words it prints or parses. Header-only, constexpr,
// no heap, no I/O: freestanding like the rest of the core.
#pragma once

#include <array>
#include <cstddef>

namespace conescan {

/// One enumerator and its name.
template <class E>
struct enum_name {
  E value;
  const char* name;
};

/// An enum's table: every enumerator that is printed or parsed, with its name.
template <class E, std::size_t N>
using enum_names = std::array<enum_name<E>, N>;

/// The name of `value` in `names`; `fallback` for a value the table does not hold.
template <class E, std::size_t N>
constexpr const char* name_of(const enum_names<E, N>& names, E value,
                              const char* fallback = nullptr) noexcept {
  for (const enum_name<E>& n : names)
    if (n.value == value) return n.name;
  return fallback;
}

/// The enumerator that `text` names in `names` (compared by `text == name`, so a
/// std::string_view or a std::string outside the core), or nullptr.
template <class E, std::size_t N, class Text>
constexpr const E* value_named(const enum_names<E, N>& names, const Text& text) noexcept {
  for (const enum_name<E>& n : names)
    if (text == n.name) return &n.value;
  return nullptr;
}

/// True when `names` lists E(0), E(1), ..., E(N - 1) in order, each named: a table that
/// covers an enum whose values are 0, 1, ... and whose last is E(N - 1).
template <class E, std::size_t N>
constexpr bool in_enum_order(const enum_names<E, N>& names) noexcept {
  for (std::size_t i = 0; i < N; ++i)
    if (static_cast<std::size_t>(names[i].value) != i || names[i].name == nullptr) return false;
  return true;
}

}  // namespace conescan

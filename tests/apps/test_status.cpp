// The status list of MODEL §7 is written once (status.hpp): every table indexed by a status takes
// its size from status_count, and every list of names comes from all_statuses and to_string.
#include <catch2/catch.hpp>
#include <set>
#include <string>

#include "conescan/enum_names.hpp"
#include "conescan/status.hpp"
#include "simulation/summary.hpp"
#include "support/cli.hpp"

using conescan::status;

TEST_CASE("status layout: every status in order, each with its own spelling", "[status]") {
  std::set<std::string> spellings;
  for (std::size_t i = 0; i < conescan::status_count; ++i) {
    const status s = conescan::all_statuses[i];
    CHECK(conescan::status_index(s) == i);
    REQUIRE(conescan::to_string(s) != nullptr);
    spellings.insert(conescan::to_string(s));
  }
  CHECK(spellings.size() == conescan::status_count);
  CHECK(conescan::to_string(static_cast<status>(conescan::status_count)) == nullptr);
  // MODEL §7's statuses and the system's `none` are all there.
  for (const char* name :
       {"ok", "miss", "engulfed", "grazing", "multiple", "fold", "invalid", "none"})
    CHECK(spellings.count(name) == 1);
}

TEST_CASE("status layout: the summary counts every status, the last one included", "[status]") {
  conescan::scene::error_statistics stats;
  for (status s : conescan::all_statuses) stats.add(0.0, 0.0, s);
  stats.add(0.0, 0.0, conescan::all_statuses.back());
  CHECK(stats.rows == conescan::status_count + 1);
  CHECK(stats.status_counts.size() == conescan::status_count);
  CHECK(stats.status_counts.back() == 2);
  CHECK(stats.ok_rows() == 1);
}

TEST_CASE("status layout: the summary's header names every status in order",
          "[status][cli][summary]") {
  const auto run = conescan_test::run_sim("--duration-s 0 --summary");
  REQUIRE(run.exit_status == 0);
  std::string expected = "source,rows";
  for (status s : conescan::all_statuses) expected += std::string(",") + conescan::to_string(s);
  CHECK(run.out.compare(0, expected.size(), expected) == 0);
  CHECK(run.out.at(expected.size()) == ',');
}

TEST_CASE("enum names: one table prints an enumerator and reads it back", "[status]") {
  // Every status's spelling reads back to the status; a word no status has, and a prefix or a
  // case variant of one, read back to nothing.
  for (status s : conescan::all_statuses) {
    const status* back = conescan::value_named(conescan::status_names, std::string(to_string(s)));
    REQUIRE(back != nullptr);
    CHECK(*back == s);
  }
  for (const char* word : {"", "OK", "ok ", "miss_", "engulf", "nonee"})
    CHECK(conescan::value_named(conescan::status_names, std::string(word)) == nullptr);
  // A value outside the table gives the fallback; a table out of the enum's order is caught.
  enum class two { a, b };
  constexpr conescan::enum_names<two, 2> in_order{{{two::a, "a"}, {two::b, "b"}}};
  constexpr conescan::enum_names<two, 2> swapped{{{two::b, "b"}, {two::a, "a"}}};
  constexpr conescan::enum_names<two, 1> partial{{{two::b, "b"}}};
  STATIC_REQUIRE(conescan::in_enum_order(in_order));
  STATIC_REQUIRE_FALSE(conescan::in_enum_order(swapped));
  STATIC_REQUIRE_FALSE(conescan::in_enum_order(partial));
  CHECK(std::string(conescan::name_of(partial, two::a, "fallback")) == "fallback");
  CHECK(conescan::name_of(partial, two::a) == nullptr);
  CHECK(std::string(conescan::name_of(swapped, two::a)) == "a");
}

// The status list of MODEL §7 is written once (status.hpp): every table indexed by a status takes
// its size from status_count, and every list of names comes from all_statuses and to_string.
#include <catch2/catch.hpp>
#include <set>
#include <string>

#include "conescan/status.hpp"
#include "scene/summary.hpp"
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

// Documentation that must stay true to the code (a review found API.md silent on two headers).
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "support/temp_file.hpp"

TEST_CASE("docs: API.md names every public header of the core", "[docs]") {
  const std::filesystem::path root = std::filesystem::path(CONESCAN_TEST_DATA) / ".." / "..";
  const std::string api = conescan_test::read_file((root / "docs" / "API.md").string());
  REQUIRE(!api.empty());
  int headers = 0;
  for (const auto& entry : std::filesystem::directory_iterator(root / "include" / "conescan")) {
    const std::string name = entry.path().filename().string();
    ++headers;
    INFO(name);
    CHECK(api.find(name) != std::string::npos);
  }
  CHECK(headers >= 17);
}

// A scene as a user types its options, for tests (Catch2: a plan the options cannot build fails
// the test, with the plan's message).
#pragma once

#include <catch2/catch.hpp>
#include <string>
#include <utility>
#include <vector>

#include "scene/loaded_scene.hpp"
#include "scene/scene_plan.hpp"

namespace conescan_test {

/// The plan built from options as a user types them ({"e", "0"}, {"head", "sigma=0"}, ...).
inline conescan::scene::scene_plan plan_of(
    const std::vector<std::pair<std::string, std::string>>& options) {
  std::vector<conescan::scene::option_value> entries;
  for (const auto& [name, text] : options)
    entries.push_back({name, text, conescan::origin::command_line()});
  conescan::checked<conescan::scene::scene_plan> plan = conescan::scene::build_scene_plan(entries);
  INFO((plan.ok() ? std::string() : plan.error().text()));
  REQUIRE(plan.ok());
  return std::move(plan).value();
}

/// Its first scene, with its files loaded.
inline conescan::scene::loaded_scene scene_of(
    const std::vector<std::pair<std::string, std::string>>& options) {
  return plan_of(options).scene(0);
}

/// A scene built in a test, its files loaded (load_scene; a file that cannot be read fails the
/// test, with its message).
inline conescan::scene::loaded_scene loaded(const conescan::scene::scene_config& scene) {
  conescan::checked<conescan::scene::loaded_scene> made = conescan::scene::load_scene(scene);
  INFO((made.ok() ? std::string() : made.error().text()));
  REQUIRE(made.ok());
  return std::move(made).value();
}

}  // namespace conescan_test

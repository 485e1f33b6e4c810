// conescan-sim --omm FILE: an element set as a CCSDS OMM (KVN, XML) or CelesTrak's CSV or JSON,
// end to end: the four formats of one set write the rows of its TLE, byte for byte; one orbit
// source; bad files refused with exit 2 and one message naming the file, place and field.
#include <catch2/catch.hpp>
#include <string>

#include "support/cli.hpp"

using conescan_test::run_sim;
using conescan_test::temp_file;

namespace {

const std::string data = CONESCAN_TEST_DATA;
const std::string tle_file = data + "/tle/delta-1-deb.tle";
const std::string omm_base = data + "/omm/delta-1-deb.";

void check_refused(const std::string& args, std::initializer_list<std::string> names) {
  const auto run = run_sim(args);
  INFO("conescan-sim " << args << "\nstderr: " << run.err);
  CHECK(run.exit_status == 2);
  CHECK(run.out.empty());
  CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  for (const std::string& name : names) CHECK(run.err.find(name) != std::string::npos);
}

}  // namespace

TEST_CASE("omm: each format of a set writes the rows of its TLE", "[cli][omm]") {
  const std::string scene = " --step-s 60 --earth wgs84 --model scan --epoch 2006-06-26T00:00:00";
  const auto tle = run_sim("--tle " + tle_file + scene);
  REQUIRE(tle.exit_status == 0);
  for (const char* format : {"kvn", "xml", "csv", "json"}) {
    const auto omm = run_sim("--omm " + omm_base + format + scene);
    INFO(format << ": " << omm.err);
    REQUIRE(omm.exit_status == 0);
    CHECK(omm.out == tle.out);
  }
  // Without --epoch the OMM's epoch is t = 0, as the TLE's; --write-oem names the set.
  const temp_file written("", ".oem");
  REQUIRE(run_sim("--omm " + omm_base + "json --duration-s 600 --write-oem " + written.path)
              .exit_status == 0);
  const std::string oem = conescan_test::read_file(written.path);
  CHECK(oem.find("OBJECT_NAME = DELTA 1 DEB") != std::string::npos);
  CHECK(oem.find("REF_FRAME = TOD") != std::string::npos);
  CHECK(oem.find("START_TIME = 2006-06-25T19:46:43.980") != std::string::npos);
}

TEST_CASE("omm: one orbit source, and bad OMMs refused naming file, place and field",
          "[cli][omm]") {
  check_refused("--omm " + omm_base + "kvn --tle " + tle_file, {"--omm", "--tle"});
  check_refused("--omm " + omm_base + "kvn --oem " + data + "/ccsds/paper-orbit.oem",
                {"--omm", "--oem"});
  check_refused("--omm " + omm_base + "xml --i-deg 40", {"--i-deg", "the orbit comes from --omm"});
  // From a scene file, the command line's orbit source wins over the file's.
  const temp_file scene("omm = \"" + omm_base + "csv\"\n");
  CHECK(run_sim("--config " + scene.path + " --tle " + tle_file).out ==
        run_sim("--tle " + tle_file).out);
  check_refused("--omm " + tle_file,
                {"--omm", "not an OMM", "a two-line element set is read with --tle"});
  check_refused("--omm " + data + "/ccsds/paper-orbit.oem", {"an OEM is read with --oem"});
  const temp_file xp(
      "CCSDS_OMM_VERS = 3.0\nOBJECT_NAME = X\nCENTER_NAME = EARTH\n"
      "REF_FRAME = TEME\nTIME_SYSTEM = UTC\nMEAN_ELEMENT_THEORY = SGP4-XP\n",
      ".kvn");
  check_refused("--omm " + xp.path, {xp.path + ":6:23: --omm: MEAN_ELEMENT_THEORY: 'SGP4-XP'"});
  const temp_file underground(
      "[{\"EPOCH\":\"2006-06-25T19:46:43.980096\",\"MEAN_MOTION\":17.5,\"ECCENTRICITY\":0.3,"
      "\"INCLINATION\":58,\"RA_OF_ASC_NODE\":54,\"ARG_OF_PERICENTER\":139,\"MEAN_ANOMALY\":221,"
      "\"BSTAR\":0.0001,\"NORAD_CAT_ID\":270001}]",
      ".json");
  check_refused("--omm " + underground.path, {"--omm: the osculating perigee radius at the epoch"});
  // A BSTAR SGP4 cannot propagate: said so, never a NaN in the message.
  const temp_file overflowing(
      "[{\"EPOCH\":\"2006-06-25T19:46:43.980096\",\"MEAN_MOTION\":15.5,\"ECCENTRICITY\":0.003,"
      "\"INCLINATION\":58,\"RA_OF_ASC_NODE\":54,\"ARG_OF_PERICENTER\":139,\"MEAN_ANOMALY\":221,"
      "\"BSTAR\":1e308,\"NORAD_CAT_ID\":270001}]",
      ".json");
  check_refused(
      "--omm " + overflowing.path + " --duration-s 0",
      {"--omm: " + overflowing.path + ": the elements give no finite state at the scene's epoch"});
  const temp_file missing(
      "[{\"EPOCH\":\"2006-06-25T19:46:43.980096\",\"MEAN_MOTION\":15.5,\"ECCENTRICITY\":0.003,"
      "\"INCLINATION\":58,\"RA_OF_ASC_NODE\":54,\"ARG_OF_PERICENTER\":139,\"MEAN_ANOMALY\":221}]",
      ".json");
  check_refused("--omm " + missing.path,
                {"--omm: " + missing.path + ": [0]: missing BSTAR: SGP4 needs EPOCH"});
}

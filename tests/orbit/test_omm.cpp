// OMM element sets (src/orbit/omm.hpp) in CCSDS KVN and XML and CelesTrak's CSV and JSON:
// against python-sgp4's own OMM reader, its sample files and SGP4-VER.TLE converted to every
// format (tests/support/omm_oracle.py writes them and the oracle's states at test time); the
// formats against each other; and every refusal naming the file, the place and the field.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "orbit/omm.hpp"
#include "orbit/sgp4.hpp"
#include "orbit/tle.hpp"
#include "support/text_file.hpp"
#include "text/text_lines.hpp"

using namespace conescan::orbit;
using conescan_test::replaced;
using conescan_test::text_file;

namespace {

/// The oracle's output, line by line (it writes its OMM files into `directory`).
std::vector<std::string> run_oracle(const std::string& directory) {
  const std::string command = std::string(CONESCAN_DEBIAN_PYTHON) + " " +
                              CONESCAN_TEST_SUPPORT "/omm_oracle.py " + directory;
  std::FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) FAIL("cannot run " << command);
  std::vector<std::string> lines(1);
  for (int c = std::fgetc(pipe); c != EOF; c = std::fgetc(pipe)) {
    if (c == '\n')
      lines.emplace_back();
    else
      lines.back().push_back(static_cast<char>(c));
  }
  lines.pop_back();
  if (pclose(pipe) != 0)
    FAIL(command << " failed: is Debian's python3-sgp4 installed? (scripts/setup.sh)");
  return lines;
}

std::vector<omm_element_set> sets_of(const std::string& path) {
  const conescan::checked<std::string> text = conescan::text::read_bounded_file(path, 1 << 26, "");
  REQUIRE(text.ok());
  const conescan::checked<std::vector<omm_element_set>> sets = read_omm_sets(text.value(), path);
  if (!sets.ok()) FAIL(sets.error().text());
  return sets.value();
}

/// The OMM of `text` (one set), or the error's text.
std::string error_of(const std::string& name, const std::string& text) {
  const text_file file(name, text);
  const conescan::checked<omm_element_set> set = read_omm(file.path(), tle_selection::only_one);
  if (set.ok()) return "read";
  const std::string message = set.error().text();
  return message.substr(message.find(name) + name.size());  // without the directory
}

bool same_elements(const omm_element_set& a, const omm_element_set& b) {
  const tle &x = a.elements, &y = b.elements;
  return x.name == y.name && x.catalog_number == y.catalog_number &&
         x.satellite_number == y.satellite_number && x.classification == y.classification &&
         x.international_designator == y.international_designator && x.epoch.year == y.epoch.year &&
         x.epoch.day_of_year == y.epoch.day_of_year &&
         x.epoch.fraction_of_day == y.epoch.fraction_of_day &&
         x.mean_motion_rev_day == y.mean_motion_rev_day && x.eccentricity == y.eccentricity &&
         x.inclination_deg == y.inclination_deg && x.raan_deg == y.raan_deg &&
         x.argument_of_perigee_deg == y.argument_of_perigee_deg &&
         x.mean_anomaly_deg == y.mean_anomaly_deg &&
         x.bstar_per_earth_radius == y.bstar_per_earth_radius &&
         x.mean_motion_dot_rev_day2 == y.mean_motion_dot_rev_day2 &&
         x.element_set_number == y.element_set_number &&
         x.revolution_number == y.revolution_number &&
         a.epoch_days_since_1950 == b.epoch_days_since_1950;
}

// One set of the CCSDS standard's kind, hand-made (the ISS, 2024), for the format checks.
const std::string iss_kvn =
    "CCSDS_OMM_VERS = 3.0\n"
    "COMMENT written by hand for conescan's tests\n"
    "CREATION_DATE = 2024-05-01T00:00:00\n"
    "ORIGINATOR = CONESCAN\n"
    "\n"
    "OBJECT_NAME = ISS (ZARYA)\n"
    "OBJECT_ID = 1998-067A\n"
    "CENTER_NAME = EARTH\n"
    "REF_FRAME = TEME\n"
    "TIME_SYSTEM = UTC\n"
    "MEAN_ELEMENT_THEORY = SGP4\n"
    "\n"
    "EPOCH = 2024-122T12:00:00.000\n"
    "MEAN_MOTION = 15.50103472 [rev/day]\n"
    "ECCENTRICITY = .0004879\n"
    "INCLINATION = 51.6393 [deg]\n"
    "RA_OF_ASC_NODE = 160.4574 [deg]\n"
    "ARG_OF_PERICENTER = 140.6673 [deg]\n"
    "MEAN_ANOMALY = 205.7250 [deg]\n"
    "\n"
    "EPHEMERIS_TYPE = 0\n"
    "CLASSIFICATION_TYPE = U\n"
    "NORAD_CAT_ID = 25544\n"
    "ELEMENT_SET_NO = 999\n"
    "REV_AT_EPOCH = 45151\n"
    "BSTAR = .20214E-3 [1/ER]\n"
    "MEAN_MOTION_DOT = .00010708 [rev/day**2]\n"
    "MEAN_MOTION_DDOT = 0 [rev/day**3]\n";

const std::string iss_xml =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<omm id=\"CCSDS_OMM_VERS\" version=\"3.0\">\n"
    "  <header><CREATION_DATE>2024-05-01T00:00:00</CREATION_DATE>"
    "<ORIGINATOR>CONESCAN</ORIGINATOR></header>\n"
    "  <body>\n"
    "    <segment>\n"
    "      <metadata>\n"
    "        <OBJECT_NAME>ISS (ZARYA)</OBJECT_NAME>\n"
    "        <OBJECT_ID>1998-067A</OBJECT_ID>\n"
    "        <CENTER_NAME>EARTH</CENTER_NAME>\n"
    "        <REF_FRAME>TEME</REF_FRAME>\n"
    "        <TIME_SYSTEM>UTC</TIME_SYSTEM>\n"
    "        <MEAN_ELEMENT_THEORY>SGP4</MEAN_ELEMENT_THEORY>\n"
    "      </metadata>\n"
    "      <data>\n"
    "        <COMMENT>mean elements</COMMENT>\n"
    "        <meanElements>\n"
    "          <EPOCH>2024-05-01T12:00:00.000</EPOCH>\n"
    "          <MEAN_MOTION units=\"rev/day\">15.50103472</MEAN_MOTION>\n"
    "          <ECCENTRICITY>.0004879</ECCENTRICITY>\n"
    "          <INCLINATION units=\"deg\">51.6393</INCLINATION>\n"
    "          <RA_OF_ASC_NODE>160.4574</RA_OF_ASC_NODE>\n"
    "          <ARG_OF_PERICENTER>140.6673</ARG_OF_PERICENTER>\n"
    "          <MEAN_ANOMALY>205.7250</MEAN_ANOMALY>\n"
    "        </meanElements>\n"
    "        <tleParameters>\n"
    "          <EPHEMERIS_TYPE>0</EPHEMERIS_TYPE>\n"
    "          <CLASSIFICATION_TYPE>U</CLASSIFICATION_TYPE>\n"
    "          <NORAD_CAT_ID>25544</NORAD_CAT_ID>\n"
    "          <ELEMENT_SET_NO>999</ELEMENT_SET_NO>\n"
    "          <REV_AT_EPOCH>45151</REV_AT_EPOCH>\n"
    "          <BSTAR>.20214E-3</BSTAR>\n"
    "          <MEAN_MOTION_DOT>.00010708</MEAN_MOTION_DOT>\n"
    "          <MEAN_MOTION_DDOT>0</MEAN_MOTION_DDOT>\n"
    "        </tleParameters>\n"
    "      </data>\n"
    "    </segment>\n"
    "  </body>\n"
    "</omm>\n";

// The refusal of a file of several without --object (orbit/catalogue.hpp), before its list.
const std::string second_set =
    "a second element set begins here: the file is a catalogue of several; choose one with "
    "--object and its NORAD catalogue number, international designator (1998-067A) or name: ";

const std::string csv_header =
    "OBJECT_NAME,OBJECT_ID,EPOCH,MEAN_MOTION,ECCENTRICITY,INCLINATION,RA_OF_ASC_NODE,"
    "ARG_OF_PERICENTER,MEAN_ANOMALY,EPHEMERIS_TYPE,CLASSIFICATION_TYPE,NORAD_CAT_ID,"
    "ELEMENT_SET_NO,REV_AT_EPOCH,BSTAR,MEAN_MOTION_DOT,MEAN_MOTION_DDOT\n";
const std::string iss_csv = csv_header +
                            "ISS (ZARYA),1998-067A,2024-05-01T12:00:00.000000,15.50103472,"
                            ".0004879,51.6393,160.4574,140.6673,205.7250,0,U,25544,999,45151,"
                            ".20214E-3,.00010708,0\n";

// Space-Track's gp class: numbers as strings, extra members, the set's TLE lines.
const std::string iss_json =
    "[{\"CCSDS_OMM_VERS\":\"3.0\",\"OBJECT_NAME\":\"ISS (ZARYA)\",\"OBJECT_ID\":\"1998-067A\","
    "\"CENTER_NAME\":\"EARTH\",\"REF_FRAME\":\"TEME\",\"TIME_SYSTEM\":\"UTC\","
    "\"MEAN_ELEMENT_THEORY\":\"SGP4\",\"EPOCH\":\"2024-05-01T12:00:00.000000\","
    "\"MEAN_MOTION\":\"15.50103472\",\"ECCENTRICITY\":\".0004879\",\"INCLINATION\":51.6393,"
    "\"RA_OF_ASC_NODE\":160.4574,\"ARG_OF_PERICENTER\":140.6673,\"MEAN_ANOMALY\":205.725,"
    "\"EPHEMERIS_TYPE\":0,\"CLASSIFICATION_TYPE\":\"U\",\"NORAD_CAT_ID\":25544,"
    "\"ELEMENT_SET_NO\":999,\"REV_AT_EPOCH\":\"45151\",\"BSTAR\":0.00020214,"
    "\"MEAN_MOTION_DOT\":0.00010708,\"MEAN_MOTION_DDOT\":0,\"DECAY_DATE\":null,"
    "\"PERIOD\":\"92.897\",\"TLE_LINE1\":\"1 25544U 98067A   24122.50000000  .00010708  00000-0 "
    " 20214-3 0  9994\",\"TLE_LINE2\":\"2 25544  51.6393 160.4574 0004879 140.6673 205.7250 "
    "15.50103472451516\"}]\n";

}  // namespace

TEST_CASE("omm: python-sgp4's sample files and SGP4-VER as OMMs agree with its OMM reader",
          "[omm][oracle]") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("conescan_omm_oracle_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::vector<std::string> lines = run_oracle(dir.string());
  std::map<std::string, std::vector<omm_element_set>> read;
  // States of the same model from two implementations: rounding grown by the propagation.
  // Measured: 4.4e-10 km and 2.0e-13 km/s at worst over the 1272 states of the 68 sets
  // (samples over 7 days, SGP4-VER over its verification spans, up to 3 years for deep space;
  // relative beyond 1e5 km, where the sets flung far out go).
  const double tolerance_r = 1e-8, tolerance_v = 1e-10;
  double worst_r = 0, worst_v = 0;
  std::size_t states = 0, sets = 0;
  std::optional<sgp4_propagator> model;
  for (const std::string& line : lines) {
    std::istringstream in(line);
    std::string kind;
    in >> kind;
    if (kind == "SET") {
      std::string path;
      std::size_t index = 0;
      in >> path >> index;
      if (!read.count(path)) read[path] = sets_of(path);
      REQUIRE(index < read[path].size());
      model.emplace(mean_elements(read[path][index]));
      ++sets;
      continue;
    }
    double t = 0, r[3], v[3];
    int error = 0;
    in >> t >> error >> r[0] >> r[1] >> r[2] >> v[0] >> v[1] >> v[2];
    const teme_state s = model->state_at(t);
    INFO(line);
    REQUIRE(static_cast<int>(s.status) == error);
    if (error != 0) continue;
    const double scale = std::max(1.0, std::hypot(r[0], r[1], r[2]) / 1e5);
    for (int k = 0; k < 3; ++k) {
      worst_r = std::max(worst_r, std::abs(s.r_teme_km[k] - r[k]) / scale);
      worst_v = std::max(worst_v, std::abs(s.v_teme_km_s[k] - v[k]) / scale);
    }
    ++states;
  }
  WARN("OMM vs python-sgp4's OMM reader: " << sets << " sets, " << states << " states; worst "
                                           << worst_r << " km, " << worst_v << " km/s");
  CHECK(sets == 2 + 2 * 33);
  CHECK(worst_r <= tolerance_r);
  CHECK(worst_v <= tolerance_v);
  // The four formats of the same 33 sets read to the same elements, bit for bit.
  const std::vector<omm_element_set> xml = sets_of((dir / "ver.xml").string());
  for (const char* other : {"ver.csv", "ver.json", "ver.kvn"}) {
    const std::vector<omm_element_set> sets_other = sets_of((dir / other).string());
    REQUIRE(sets_other.size() == 33);
    for (std::size_t i = 0; i < 33; ++i) {
      INFO(other << " set " << i);
      CHECK(same_elements(xml[i], sets_other[i]));
    }
  }
  CHECK(xml[0].format == omm_format::xml);
  std::filesystem::remove_all(dir);
}

TEST_CASE("omm: the four formats of one set read alike, and as the TLE of the set", "[omm]") {
  const std::vector<std::pair<std::string, std::string>> files = {
      {"iss.kvn", iss_kvn}, {"iss.xml", iss_xml}, {"iss.csv", iss_csv}, {"iss.json", iss_json}};
  std::vector<omm_element_set> sets;
  for (const auto& [name, content] : files) {
    const text_file file(name, content);
    const auto set = read_omm(file.path(), tle_selection::only_one);
    if (!set.ok()) FAIL(set.error().text());
    sets.push_back(set.value());
  }
  CHECK(sets[0].format == omm_format::kvn);
  CHECK(sets[3].format == omm_format::json);
  for (std::size_t i = 1; i < sets.size(); ++i) CHECK(same_elements(sets[0], sets[i]));
  const tle& t = sets[0].elements;
  CHECK(t.name == "ISS (ZARYA)");
  CHECK(t.international_designator == "98067A");
  CHECK(t.satellite_number == 25544);
  CHECK(t.epoch.year == 2024);
  CHECK(t.epoch.day_of_year == 122);
  CHECK(t.epoch.fraction_of_day == 0.5);
  CHECK(t.bstar_per_earth_radius == 0.20214e-3);
  // The same set as a TLE: the same elements, hence the same states (the epoch exactly 12:00,
  // where the TLE's Julian-date rounding of its epoch is exact too).
  const auto line =
      parse_tle("1 25544U 98067A   24122.50000000  .00010708  00000-0  20214-3 0  9994",
                "2 25544  51.6393 160.4574 0004879 140.6673 205.7250 15.50103472451516");
  REQUIRE(line.ok());
  const sgp4_propagator from_tle(line.value()), from_omm(mean_elements(sets[0]));
  for (double minutes : {0.0, 90.0, 1440.0, 4320.0}) {
    const teme_state a = from_tle.state_at(minutes), b = from_omm.state_at(minutes);
    CHECK(a.r_teme_km.x == b.r_teme_km.x);
    CHECK(a.v_teme_km_s.z == b.v_teme_km_s.z);
  }
}

TEST_CASE("omm: catalogue numbers beyond 99999, quoted CSV fields, one object, any case", "[omm]") {
  // Space-Track's TLE lines write 339999 as alpha-5 Z9999; NORAD_CAT_ID as digits.
  const text_file json(
      "big.json", replaced(replaced(iss_json, "\"NORAD_CAT_ID\":25544", "\"NORAD_CAT_ID\":339999"),
                           " 25544", " Z9999"));
  const auto big = read_omm(json.path(), tle_selection::only_one);
  REQUIRE(big.ok());
  CHECK(big.value().elements.satellite_number == 339999);
  CHECK(big.value().elements.catalog_number == "339999");
  // Nine digits, beyond any TLE; lower-case values and units; a CSV name in quotes with a comma
  // and a quote; a JSON object alone.
  const text_file kvn("nine.kvn",
                      replaced(replaced(replaced(iss_kvn, "25544", "123456789"), "[deg]", "[DEG]"),
                               "= TEME", "= teme"));
  const auto nine = read_omm(kvn.path(), tle_selection::only_one);
  REQUIRE(nine.ok());
  CHECK(nine.value().elements.satellite_number == 123456789);
  const text_file csv("quoted.csv",
                      replaced(iss_csv, "ISS (ZARYA),", "\"ISS, \"\"ZARYA\"\"\",") + "\n");
  const auto quoted = read_omm(csv.path(), tle_selection::only_one);
  REQUIRE(quoted.ok());
  CHECK(quoted.value().elements.name == "ISS, \"ZARYA\"");
  const text_file object("one.json", iss_json.substr(1, iss_json.size() - 3));
  CHECK(read_omm(object.path(), tle_selection::only_one).ok());
  // An <ndm> of two: the first is taken with tle_selection::first.
  const std::string body = iss_xml.substr(iss_xml.find("<omm"));
  const text_file two("two.xml", "<ndm>\n" + body + body + "</ndm>\n");
  CHECK(read_omm(two.path(), tle_selection::first).ok());
  CHECK(error_of("two.xml", "<ndm>\n" + body + body + "</ndm>\n") ==
        ":39:1: ndm/omm[2]: " + second_set + "ndm/omm[1] 'ISS (ZARYA)' (NORAD 25544, 1998-067A); " +
            "ndm/omm[2] 'ISS (ZARYA)' (NORAD 25544, 1998-067A)");
  // The theories SGP4 is named by.
  for (const char* theory : {"SGP/SGP4", "sgp4", "SDP4", "SGP4/SDP4"})
    CHECK(error_of("t.kvn", replaced(iss_kvn, "THEORY = SGP4",
                                     std::string("THEORY = ") + theory)) == "read");
}

TEST_CASE("omm: bad input is refused naming the file, the place and the field", "[omm]") {
  const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
      // KVN: file:line:column: keyword: message
      {"a.kvn", replaced(iss_kvn, "MEAN_MOTION = 15.50103472 [rev/day]\n", ""),
       ":1:1: missing MEAN_MOTION: SGP4 needs EPOCH, MEAN_MOTION, ECCENTRICITY, INCLINATION, "
       "RA_OF_ASC_NODE, ARG_OF_PERICENTER, MEAN_ANOMALY and BSTAR"},
      {"a.kvn", replaced(iss_kvn, "BSTAR = .20214E-3", "BSTAR = "),
       ":1:1: missing BSTAR: SGP4 needs EPOCH, MEAN_MOTION, ECCENTRICITY, INCLINATION, "
       "RA_OF_ASC_NODE, ARG_OF_PERICENTER, MEAN_ANOMALY and BSTAR"},
      {"a.kvn", replaced(iss_kvn, "= .0004879", "= 0,0004879"),
       ":15:16: ECCENTRICITY: '0,0004879' is not a number"},
      {"a.kvn", replaced(iss_kvn, "= .0004879", "= 1.5"),
       ":15:16: ECCENTRICITY: '1.5' is outside [0, 1)"},
      {"a.kvn", replaced(iss_kvn, "51.6393", "181"),
       ":16:15: INCLINATION: '181' is outside [0, 180]"},
      {"a.kvn", replaced(iss_kvn, "15.50103472", "-15.5"),
       ":14:15: MEAN_MOTION: '-15.5' is outside [0, inf]"},
      {"a.kvn", replaced(iss_kvn, "= TEME", "= EME2000"),
       ":9:13: REF_FRAME: 'EME2000': SGP4's elements are TEME"},
      {"a.kvn", replaced(iss_kvn, "= UTC", "= TAI"),
       ":10:15: TIME_SYSTEM: 'TAI': SGP4's elements are UTC"},
      {"a.kvn", replaced(iss_kvn, "= EARTH", "= MOON"),
       ":8:15: CENTER_NAME: 'MOON': SGP4's elements are EARTH"},
      {"a.kvn", replaced(iss_kvn, "TIME_SYSTEM = UTC\n", ""), ":1:1: missing TIME_SYSTEM (UTC)"},
      {"a.kvn", replaced(iss_kvn, "= SGP4\n", "= SGP4-XP\n"),
       ":11:23: MEAN_ELEMENT_THEORY: 'SGP4-XP': SGP4-XP elements are fitted to the SGP4-XP "
       "propagator, which conescan does not have; give SGP4 elements (CelesTrak's GP data)"},
      {"a.kvn", replaced(iss_kvn, "= SGP4\n", "= DSST\n"),
       ":11:23: MEAN_ELEMENT_THEORY: 'DSST' is not SGP4's theory (SGP4, SGP/SGP4, SDP4 or "
       "SGP4/SDP4)"},
      {"a.kvn", replaced(iss_kvn, "EPHEMERIS_TYPE = 0", "EPHEMERIS_TYPE = 4"),
       ":21:18: EPHEMERIS_TYPE: 4: SGP4-XP elements, which SGP4 cannot propagate (give SGP4 "
       "elements, type 0)"},
      {"a.kvn", replaced(iss_kvn, "BSTAR =", "BTERM = 0.01\nBSTAR ="),
       ":26:9: BTERM: a parameter of SGP4-XP's force model: these are SGP4-XP elements, which "
       "SGP4 cannot propagate"},
      {"a.kvn", replaced(iss_kvn, "\nEPOCH =", "\nSEMI_MAJOR_AXIS = 6790\nEPOCH ="),
       ":13:19: SEMI_MAJOR_AXIS: SGP4 takes MEAN_MOTION (rev/day), not SEMI_MAJOR_AXIS"},
      {"a.kvn", replaced(iss_kvn, "2024-122T12:00:00.000", "2024-122T23:59:60.000"),
       ":13:9: EPOCH: '2024-122T23:59:60.000' is not a UTC epoch YYYY-MM-DDThh:mm:ss[.f] or "
       "YYYY-DDDThh:mm:ss[.f] in 1900-2099 (no leap second: SGP4's days have 86400 s)"},
      {"a.kvn", replaced(iss_kvn, "2024-122T", "2023-366T"),
       ":13:9: EPOCH: '2023-366T12:00:00.000' is not a UTC epoch YYYY-MM-DDThh:mm:ss[.f] or "
       "YYYY-DDDThh:mm:ss[.f] in 1900-2099 (no leap second: SGP4's days have 86400 s)"},
      {"a.kvn", replaced(iss_kvn, "NORAD_CAT_ID = 25544", "NORAD_CAT_ID = -25544"),
       ":23:16: NORAD_CAT_ID: '-25544' is not a catalogue number (1 to 9 digits)"},
      {"a.kvn", replaced(iss_kvn, "[rev/day]", "[rad/s]"),
       ":14:15: MEAN_MOTION: units 'rad/s': MEAN_MOTION is in rev/day"},
      {"a.kvn", replaced(iss_kvn, "\nEPOCH =", "\nWRONG_KEYWORD = 1\nEPOCH ="),
       ":13:1: unknown keyword 'WRONG_KEYWORD': not an OMM keyword"},
      {"a.kvn", iss_kvn + "INCLINATION = 51\n",
       ":29:15: INCLINATION: given twice in one element set (first on line 16)"},
      {"a.kvn", replaced(iss_kvn, "ORIGINATOR = CONESCAN", "ORIGINATOR CONESCAN"),
       ":4: expected KEYWORD = value, not 'ORIGINATOR CONESCAN'"},
      {"a.kvn", iss_kvn + iss_kvn,
       ":29:1: " + second_set +
           "line 1 'ISS (ZARYA)' (NORAD 25544, 1998-067A); line 29 'ISS (ZARYA)' (NORAD 25544, "
           "1998-067A)"},
      // XML: file:line:column: element path: message
      {"a.xml", replaced(iss_xml, "          <BSTAR>.20214E-3</BSTAR>\n", ""),
       ":2:1: omm: missing BSTAR: SGP4 needs EPOCH, MEAN_MOTION, ECCENTRICITY, INCLINATION, "
       "RA_OF_ASC_NODE, ARG_OF_PERICENTER, MEAN_ANOMALY and BSTAR"},
      {"a.xml", replaced(iss_xml, ">51.6393<", ">51.6x<"),
       ":20:11: omm/body/segment/data/meanElements/INCLINATION: '51.6x' is not a number"},
      {"a.xml",
       replaced(iss_xml, "</meanElements>",
                "<GM units=\"km**3/s**2\">398600.8</GM></meanElements>"),
       "read"},
      {"a.xml", replaced(iss_xml, "<BSTAR>", "<BSTARS>1</BSTARS><BSTAR>"),
       ":31:11: omm/body/segment/data/tleParameters/BSTARS: unknown element: not an OMM field "
       "of <tleParameters>"},
      {"a.xml", replaced(iss_xml, "</omm>", ""), ":2:1: not well-formed XML: <omm> is not closed"},
      {"a.xml", replaced(iss_xml, "omm", "opm"),
       ":2:1: root element <opm>: an OMM's is <omm> or <ndm>"},
      {"a.xml", replaced(iss_xml, "units=\"deg\"", "units=\"rad\""),
       ":20:11: omm/body/segment/data/meanElements/INCLINATION: units 'rad': INCLINATION is in "
       "deg"},
      // CSV: file:line:column: column name: message
      {"a.csv", replaced(iss_csv, ",.20214E-3,", ",,"),
       ":2:1: missing BSTAR: SGP4 needs EPOCH, MEAN_MOTION, ECCENTRICITY, INCLINATION, "
       "RA_OF_ASC_NODE, ARG_OF_PERICENTER, MEAN_ANOMALY and BSTAR"},
      {"a.csv", replaced(iss_csv, ",160.4574,", ",400,"),
       ":2:79: RA_OF_ASC_NODE: '400' is outside [0, 360]"},
      {"a.csv", replaced(iss_csv, ",0\n", ",0,1\n"), ":2: 18 fields, the header has 17"},
      {"a.csv", replaced(iss_csv, "ISS (ZARYA)", "\"ISS"),
       ":2: unterminated quote in the field at column 1"},
      // JSON: file: member path: message (a syntax error at its line and column)
      {"a.json", replaced(iss_json, "\"MEAN_ANOMALY\":205.725,", ""),
       ": [0]: missing MEAN_ANOMALY: SGP4 needs EPOCH, MEAN_MOTION, ECCENTRICITY, INCLINATION, "
       "RA_OF_ASC_NODE, ARG_OF_PERICENTER, MEAN_ANOMALY and BSTAR"},
      {"a.json", replaced(iss_json, "\"MEAN_MOTION\":\"15.50103472\"", "\"MEAN_MOTION\":true"),
       ": [0].MEAN_MOTION: expected a number or a string, found true or false"},
      {"a.json", replaced(iss_json, "\"NORAD_CAT_ID\":25544", "\"NORAD_CAT_ID\":25545"),
       ": [0].TLE_LINE1: catalogue number 25544 (columns 3-7) disagrees with NORAD_CAT_ID 25545"},
      {"a.json", replaced(iss_json, "2 25544", "2 25543"),
       ": [0].TLE_LINE2: catalogue number 25543 (columns 3-7) disagrees with NORAD_CAT_ID 25544"},
      {"a.json", replaced(iss_json, "\"PERIOD\"", "\"BSTAR\""),
       ": [0].BSTAR: member given twice in one object"},
      {"a.json", replaced(iss_json, "}]", "},]"), ":1:"},
      {"a.json", "[1]\n", ": [0]: expected an object of OMM fields, found a number"},
      {"a.json", "[]\n", ": holds no element set (read as JSON)"},
      // Not an OMM at all.
      {"a.txt", "ISS\n1 25544U 98067A   24122.50000000  .00010708  00000-0  20214-3 0  9990\n",
       ":1: not an OMM: expected CCSDS KVN (CCSDS_OMM_VERS = ...), XML (<ndm> or <omm>), "
       "CelesTrak's CSV (a header naming EPOCH) or JSON ([{...}]); a two-line element set is "
       "read with --tle"},
      {"a.kvn", "OBJECT_NAME = X\n",
       ":1: not an OMM: expected CCSDS KVN (CCSDS_OMM_VERS = "
       "...), XML (<ndm> or <omm>), CelesTrak's CSV (a header naming EPOCH) or JSON ([{...}])"},
      {"a.csv", csv_header, ": holds no element set (read as CSV)"},
  };
  for (const auto& [name, content, expected] : cases) {
    INFO(name << ":\n" << content);
    const std::string got = error_of(name, content);
    if (expected == ":1:")
      CHECK(got.rfind(":1:", 0) == 0);
    else
      CHECK(got == expected);
  }
  CHECK(read_omm("/nonexistent/x.omm", tle_selection::only_one).error().text() ==
        "/nonexistent/x.omm: cannot open: No such file or directory");
}

// --- The third audit (docs/RELIABILITY.md): a value is all of its text; the frame of an XML
// document and the message's version are checked; a catalogue is read a set at a time --------

TEST_CASE("omm: an XML value is all of its text, comments, CDATA and PIs inside it too",
          "[omm][reliability][regression]") {
  const text_file plain("plain.xml", iss_xml);
  const auto expected = read_omm(plain.path(), tle_selection::only_one);
  REQUIRE(expected.ok());
  // Each was read as the text before the comment, section or instruction (15.50, 5): a
  // different orbit with exit 0. XML's text of an element is all of its character data.
  for (const auto& [from, to] :
       {std::pair{">15.50103472<", ">15.50<!-- x -->103472<"},
        std::pair{">51.6393<", ">5<!-- -->1.6393<"},
        std::pair{">51.6393<", ">5<![CDATA[1.63]]>93<"},
        std::pair{">.20214E-3<", "><?pi ?>.20214<?pi x?>E-3<"},
        std::pair{">2024-05-01T12:00:00.000<", ">2024-05-01T12<!--:-->:00:00.000<"}}) {
    INFO(to);
    const text_file split("split.xml", replaced(iss_xml, from, to));
    const auto read = read_omm(split.path(), tle_selection::only_one);
    REQUIRE(read.ok());
    CHECK(same_elements(read.value(), expected.value()));
  }
  // A value that is no number once whole is refused, naming the element and its line.
  CHECK(error_of("a.xml", replaced(iss_xml, ">15.50103472<", ">15.50 <!-- x --> 103472<")) ==
        ":18:11: omm/body/segment/data/meanElements/MEAN_MOTION: '15.50  103472' is not a number");
  CHECK(error_of("a.xml", replaced(iss_xml, ">15.50103472<", ">15.5<X/>0103472<")) ==
        ":18:11: omm/body/segment/data/meanElements/MEAN_MOTION: holds elements: expected a "
        "value");
}

TEST_CASE("omm: the frame of an XML document and the message's version are checked",
          "[omm][reliability][regression]") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {iss_xml + "trailing text\n",
       ":39:1: not well-formed XML: text outside the root element: 'trailing text'"},
      {iss_xml + "<omm/>\n", ":39:1: not well-formed XML: a second root element <omm>"},
      {replaced(iss_xml, "<omm ", "junk\n<omm "),
       ":2:1: not well-formed XML: text outside the root element: 'junk'"},
      {iss_xml + "<?xml version=\"1.0\"?>\n",
       ":39:1: not well-formed XML: an XML declaration elsewhere than at the start of the "
       "document"},
      {replaced(iss_xml, "</meanElements>", "</meanelements>"),
       ":24:9: not well-formed XML: the end tag </meanelements> does not match <meanElements> "
       "(line 16)"},
      {replaced(iss_xml, "</omm>\n", ""), ":2:1: not well-formed XML: <omm> is not closed"},
      {replaced(iss_xml, "<COMMENT>", "<!-- <COMMENT>"),
       ":15:9: not well-formed XML: a comment that does not end (no '-->')"},
      {replaced(iss_xml, " version=\"3.0\"", ""),
       ":2:1: omm: missing the version attribute (CCSDS_OMM_VERS)"},
      {replaced(iss_xml, "version=\"3.0\"", "version=\"\""),
       ":2:1: omm/@version: unsupported version '' (conescan reads versions 1 to 3)"},
      {replaced(iss_xml, "version=\"3.0\"", "version=\"three\""),
       ":2:1: omm/@version: unsupported version 'three' (conescan reads versions 1 to 3)"},
  };
  for (const auto& [content, expected] : cases) {
    INFO(content);
    CHECK(error_of("a.xml", content) == expected);
  }
  // Comments, processing instructions and a document type around the root are fine.
  CHECK(error_of("a.xml", replaced(iss_xml, "<omm ", "<!DOCTYPE omm [<!-- > -->]>\n<?pi x?><omm ") +
                              "<!-- the end -->\n") == "read");
  // The version in every format that carries it, as the OEM reader checks its own.
  CHECK(error_of("a.kvn", replaced(iss_kvn, "= 3.0", "=")) ==
        ":1:17: CCSDS_OMM_VERS: unsupported version '' (conescan reads versions 1 to 3)");
  CHECK(error_of("a.kvn", replaced(iss_kvn, "= 3.0", "= 3.0a")) ==
        ":1:18: CCSDS_OMM_VERS: unsupported version '3.0a' (conescan reads versions 1 to 3)");
  CHECK(error_of("a.kvn", replaced(iss_kvn, "= 3.0", "= 4")) ==
        ":1:18: CCSDS_OMM_VERS: unsupported version '4' (conescan reads versions 1 to 3)");
  CHECK(error_of("a.json", replaced(iss_json, "\"3.0\"", "\"x\"")) ==
        ": [0].CCSDS_OMM_VERS: unsupported version 'x' (conescan reads versions 1 to 3)");
  CHECK(error_of("a.kvn", replaced(iss_kvn, "= 3.0", "= 1.0")) == "read");
}

TEST_CASE("omm: a catalogue is read one set at a time, and --omm without --object stops early",
          "[omm][reliability][regression]") {
  // 20 000 sets in each format: --omm refuses at the second, listing five; every set is read by
  // read_omm_sets; the first is taken with tle_selection::first.
  const std::string body = iss_xml.substr(iss_xml.find("<omm"));
  const std::string json_set = iss_json.substr(1, iss_json.size() - 3);
  std::string kvn, xml = "<ndm>\n", json = "[";
  for (int k = 0; k < 20000; ++k) {
    kvn += iss_kvn;
    xml += body;
    json += (k ? "," : "") + json_set;
  }
  xml += "</ndm>\n";
  json += "]";
  for (const auto& [name, content, second] :
       {std::tuple{"c.kvn", kvn, ":29:1: "}, std::tuple{"c.xml", xml, ":39:1: ndm/omm[2]: "},
        std::tuple{"c.json", json, ": [1]: "}}) {
    INFO(name);
    // The first five sets listed, and the reading stopped there.
    const std::string error = error_of(name, content);
    CHECK(error.rfind(std::string(second) + second_set, 0) == 0);
    CHECK(error.size() - error.rfind("; ...") == 5);
    const text_file file(name, content);
    CHECK(read_omm(file.path(), tle_selection::first).ok());
    const auto all = read_omm_sets(content, name);
    REQUIRE(all.ok());
    CHECK(all.value().size() == 20000);
  }
  // An <omm> of more than 1 MiB (a million elements of a few bytes would be a tree of 64 MB) is
  // refused before it is parsed.
  std::string many(std::size_t{1} << 20, ' ');
  for (std::size_t i = 0; i + 4 <= many.size(); i += 4) many.replace(i, 4, "<a/>");
  CHECK(error_of("big.xml", replaced(iss_xml, "<COMMENT>", many + "<COMMENT>")) ==
        ":2:1: omm: an element set of 1049985 bytes, more than 1048576: not an OMM's");
  // A text that starts as no format is refused at its start (/dev/zero: at once).
  CHECK(read_omm("/dev/zero", tle_selection::only_one)
            .error()
            .text()
            .rfind("/dev/zero:1: not an OMM: expected CCSDS KVN", 0) == 0);
  CHECK(read_omm("/tmp", tle_selection::only_one).error().text() ==
        "/tmp: cannot read: Is a directory");
}

TEST_CASE("omm: a JSON number of a million digits is refused in one short line",
          "[omm][reliability][regression]") {
  const std::string digits(1000000, '9');
  const std::string message = error_of(
      "a.json", replaced(iss_json, "\"INCLINATION\":51.6393", "\"INCLINATION\":" + digits));
  INFO(message.substr(0, 300));
  CHECK(message.size() < 200);
  CHECK(message.find('\n') == std::string::npos);
  CHECK(message.find("'99999999") != std::string::npos);
  CHECK(message.find("...'") != std::string::npos);
}

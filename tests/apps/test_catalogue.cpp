// Catalogues (orbit/catalogue.hpp): --tle and --omm of a file of many element sets with --object.
// A catalogue of 1000 objects is built at test time from Vallado's SGP4-VER.TLE (shipped with
// Debian's python3-sgp4), each object a verification set under a number, a designator and a name
// of its own, and written in every format conescan reads: CelesTrak's three-line TLE file, OMM
// JSON (an array), CSV (CelesTrak's header), XML (an <ndm> of <omm>) and KVN (messages one after
// the other). One object is picked from each by its NORAD number, its designator and its name,
// and conescan-sim's rows must equal, byte for byte, those of a file of that object alone. Then
// the refusals: no match, two matches, a single set that does not match, an empty selector, a
// malformed set before and after the match, a catalogue without --object.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "conescan/enum_names.hpp"
#include "orbit/catalogue.hpp"
#include "orbit/tle.hpp"
#include "support/cli.hpp"
#include "support/text_file.hpp"
#include "text/number_text.hpp"

using conescan::orbit::parse_tle;
using conescan::orbit::tle;
using conescan_test::run_sim;
using conescan_test::shell_word;
using conescan_test::text_file;

namespace {

const std::string python_sgp4_dir = CONESCAN_PYTHON_SGP4_DIR;
constexpr std::size_t catalogue_size = 1000;

/// One object of the catalogue: a verification set renumbered, renamed and redesignated.
struct catalogue_object {
  std::string name;          ///< "SGP4-VER 06251 #0002"
  std::string number;        ///< five digits, 40000 + k
  std::string designator;    ///< the TLE's columns 10-17: "15001B  "
  std::string cospar;        ///< "2015-001B"
  std::string line1, line2;  ///< with the number, designator and checksums rewritten
  tle set;                   ///< the lines read back
};

/// The verification sets of SGP4-VER.TLE that read as element sets (columns 1-69 of each line:
/// its line 2 carries the verification's times after them).
std::vector<std::pair<std::string, std::string>> verification_sets() {
  std::ifstream in(python_sgp4_dir + "/SGP4-VER.TLE");
  REQUIRE(in.good());
  std::vector<std::pair<std::string, std::string>> sets;
  std::string line, line1;
  while (std::getline(in, line)) {
    if (line.rfind("1 ", 0) == 0) line1 = line.substr(0, 69);
    if (line.rfind("2 ", 0) != 0 || line1.empty()) continue;
    const std::string line2 = line.substr(0, 69);
    if (parse_tle(line1, line2).ok()) sets.emplace_back(line1, line2);
    line1.clear();
  }
  return sets;
}

void set_checksum(std::string& line) {
  line[68] = static_cast<char>('0' + conescan::orbit::tle_checksum(line));
}

std::vector<catalogue_object> make_catalogue() {
  const auto base = verification_sets();
  REQUIRE(base.size() >= 25);
  std::vector<catalogue_object> objects;
  for (std::size_t k = 0; k < catalogue_size; ++k) {
    const auto& [line1, line2] = base[k % base.size()];
    catalogue_object o;
    char text[64];
    std::snprintf(text, sizeof text, "SGP4-VER %s #%04zu", line1.substr(2, 5).c_str(), k);
    o.name = text;
    o.number = std::to_string(40000 + k);
    const char piece = static_cast<char>('A' + k % 3);
    std::snprintf(text, sizeof text, "15%03zu%c  ", 1 + k / 3, piece);
    o.designator = text;
    std::snprintf(text, sizeof text, "2015-%03zu%c", 1 + k / 3, piece);
    o.cospar = text;
    o.line1 = line1;
    o.line2 = line2;
    o.line1.replace(2, 5, o.number);
    o.line1.replace(9, 8, o.designator);
    o.line2.replace(2, 5, o.number);
    set_checksum(o.line1);
    set_checksum(o.line2);
    const auto read = parse_tle(o.line1, o.line2);
    REQUIRE(read.ok());
    o.set = read.value();
    o.set.name = o.name;
    objects.push_back(std::move(o));
  }
  return objects;
}

const std::vector<catalogue_object>& catalogue() {
  static const std::vector<catalogue_object> objects = make_catalogue();
  return objects;
}

// --- The formats ---------------------------------------------------------------------------

std::string number(double v) {
  return conescan::text::shortest_text(v);
}

/// The epoch as CelesTrak writes it, 2006-06-25T19:46:43.980000 (to the microsecond).
std::string epoch_text(const tle& t) {
  const conescan::orbit::utc_calendar c = conescan::orbit::calendar(t.epoch);
  const auto us = std::llround(t.epoch.fraction_of_day * 86400e6);
  REQUIRE(us < 86400000000LL);
  char text[64];
  std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02lld:%02lld:%02lld.%06lld", c.year, c.month,
                c.day, us / 3600000000LL, us / 60000000LL % 60, us / 1000000LL % 60, us % 1000000);
  return text;
}

/// The OMM's fields of an object, in CelesTrak's CSV order.
std::vector<std::pair<std::string, std::string>> omm_fields(const catalogue_object& o) {
  const tle& t = o.set;
  return {{"OBJECT_NAME", o.name},
          {"OBJECT_ID", o.cospar},
          {"EPOCH", epoch_text(t)},
          {"MEAN_MOTION", number(t.mean_motion_rev_day)},
          {"ECCENTRICITY", number(t.eccentricity)},
          {"INCLINATION", number(t.inclination_deg)},
          {"RA_OF_ASC_NODE", number(t.raan_deg)},
          {"ARG_OF_PERICENTER", number(t.argument_of_perigee_deg)},
          {"MEAN_ANOMALY", number(t.mean_anomaly_deg)},
          {"EPHEMERIS_TYPE", "0"},
          {"CLASSIFICATION_TYPE", std::string(1, t.classification)},
          {"NORAD_CAT_ID", o.number},
          {"ELEMENT_SET_NO", std::to_string(t.element_set_number)},
          {"REV_AT_EPOCH", std::to_string(t.revolution_number)},
          {"BSTAR", number(t.bstar_per_earth_radius)},
          {"MEAN_MOTION_DOT", number(t.mean_motion_dot_rev_day2)},
          {"MEAN_MOTION_DDOT", number(t.mean_motion_ddot_rev_day3)}};
}

bool is_text_field(const std::string& key) {
  return key == "OBJECT_NAME" || key == "OBJECT_ID" || key == "EPOCH" ||
         key == "CLASSIFICATION_TYPE";
}

bool is_metadata(const std::string& key) {
  return key == "OBJECT_NAME" || key == "OBJECT_ID";
}

bool is_mean_element(const std::string& key) {
  return key == "EPOCH" || key == "MEAN_MOTION" || key == "ECCENTRICITY" || key == "INCLINATION" ||
         key == "RA_OF_ASC_NODE" || key == "ARG_OF_PERICENTER" || key == "MEAN_ANOMALY";
}

enum class format { tle, json, csv, xml, kvn };
const char* suffix(format f) {
  static constexpr conescan::enum_names<format, 5> suffixes{{{format::tle, "tle"},
                                                             {format::json, "json"},
                                                             {format::csv, "csv"},
                                                             {format::xml, "xml"},
                                                             {format::kvn, "kvn"}}};
  return conescan::name_of(suffixes, f, "");
}

std::string tle_text(const catalogue_object& o) {
  return o.name + "\n" + o.line1 + "\n" + o.line2 + "\n";
}

std::string json_text(const catalogue_object& o) {
  std::string out = "{";
  for (const auto& [key, value] : omm_fields(o))
    out += (out.size() > 1 ? "," : "") + ("\"" + key + "\":") +
           (is_text_field(key) ? "\"" + value + "\"" : value);
  return out + "}";
}

std::string csv_row(const catalogue_object& o) {
  std::string out;
  for (const auto& [key, value] : omm_fields(o)) out += (out.empty() ? "" : ",") + value;
  return out + "\n";
}

std::string csv_header(const catalogue_object& o) {
  std::string out;
  for (const auto& field : omm_fields(o)) out += (out.empty() ? "" : ",") + field.first;
  return out + "\n";
}

std::string xml_text(const catalogue_object& o) {
  std::string metadata, elements, parameters;
  for (const auto& [key, value] : omm_fields(o)) {
    std::string& part = is_metadata(key) ? metadata : is_mean_element(key) ? elements : parameters;
    part += "<" + key + ">" + value + "</" + key + ">\n";
  }
  return "<omm id=\"CCSDS_OMM_VERS\" version=\"2.0\">\n"
         "<header><CREATION_DATE>2026-12-01T00:00:00</CREATION_DATE>"
         "<ORIGINATOR>CONESCAN TESTS</ORIGINATOR></header>\n"
         "<body><segment><metadata>\n" +
         metadata +
         "<CENTER_NAME>EARTH</CENTER_NAME><REF_FRAME>TEME</REF_FRAME>"
         "<TIME_SYSTEM>UTC</TIME_SYSTEM><MEAN_ELEMENT_THEORY>SGP4</MEAN_ELEMENT_THEORY>\n"
         "</metadata><data><meanElements>\n" +
         elements + "</meanElements><tleParameters>\n" + parameters +
         "</tleParameters></data></segment></body></omm>\n";
}

std::string kvn_text(const catalogue_object& o) {
  std::string out =
      "CCSDS_OMM_VERS = 2.0\nCREATION_DATE = 2026-12-01T00:00:00\nORIGINATOR = CONESCAN TESTS\n";
  for (const auto& [key, value] : omm_fields(o)) {
    out += key + " = " + value + "\n";
    if (key == "OBJECT_ID")
      out +=
          "CENTER_NAME = EARTH\nREF_FRAME = TEME\nTIME_SYSTEM = UTC\nMEAN_ELEMENT_THEORY = SGP4\n";
  }
  return out;
}

/// The objects in a file of format `f` (a catalogue, or one object).
std::string file_text(format f, const std::vector<const catalogue_object*>& objects) {
  std::string out;
  switch (f) {
    case format::tle:
      for (const auto* o : objects) out += tle_text(*o);
      return out;
    case format::json:
      for (const auto* o : objects) out += (out.empty() ? "[" : ",\n") + json_text(*o);
      return out + "]\n";
    case format::csv:
      out = csv_header(*objects.front());
      for (const auto* o : objects) out += csv_row(*o);
      return out;
    case format::xml:
      out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<ndm>\n";
      for (const auto* o : objects) out += xml_text(*o);
      return out + "</ndm>\n";
    case format::kvn:
      for (const auto* o : objects) out += kvn_text(*o);
      return out;
  }
  return out;
}

std::vector<const catalogue_object*> every_object() {
  std::vector<const catalogue_object*> all;
  for (const catalogue_object& o : catalogue()) all.push_back(&o);
  return all;
}

std::string option_of(format f) {
  return f == format::tle ? "--tle " : "--omm ";
}

/// conescan-sim's rows over 20 minutes from the element set's epoch, two heads of the paper.
conescan_test::run_result rows_of(format f, const std::string& path, const std::string& extra) {
  return run_sim(option_of(f) + shell_word(path) + extra + " --duration-s 1200 --step-s 60");
}

const format every_format[] = {format::tle, format::json, format::csv, format::xml, format::kvn};

}  // namespace

TEST_CASE(
    "catalogue: one object of 1000 by number, designator and name, in every format, gives "
    "the rows of that object alone",
    "[catalogue][tle][omm][cli]") {
  const auto& objects = catalogue();
  REQUIRE(objects.size() == catalogue_size);
  // Three objects at three places (among the first, the middle, the very last set), each a near-
  // Earth or a deep-space verification set; each picked by one key, typed as a user might.
  struct pick {
    std::size_t k;
    std::string key;
  };
  const std::vector<pick> picks{
      {2, objects[2].number},                             // NORAD catalogue number
      {500, objects[500].cospar},                         // COSPAR designator, 2015-167C
      {998, "  sgp4-ver " + objects[998].name.substr(9)}  // name, lower case, blanks before
  };
  for (const format f : every_format) {
    const text_file all(std::string("catalogue.") + suffix(f), file_text(f, every_object()));
    for (const pick& p : picks) {
      const text_file alone(std::string("alone.") + suffix(f), file_text(f, {&objects[p.k]}));
      INFO(suffix(f) << ": object " << p.k << " (" << objects[p.k].name << ") as " << p.key);
      const auto expected = rows_of(f, alone.path(), "");
      REQUIRE(expected.exit_status == 0);
      REQUIRE(expected.out.size() > 1000);
      const auto picked = rows_of(f, all.path(), " --object " + shell_word(p.key));
      INFO(picked.err);
      REQUIRE(picked.exit_status == 0);
      CHECK(picked.out == expected.out);
      // The single file with its own key reads alike.
      CHECK(rows_of(f, alone.path(), " --object " + shell_word(p.key)).out == expected.out);
    }
  }
  // The designator in the TLE's own form, and the number with leading zeros, pick alike.
  const text_file all("catalogue.tle", file_text(format::tle, every_object()));
  const text_file alone("alone.tle", file_text(format::tle, {&objects[500]}));
  const std::string expected = rows_of(format::tle, alone.path(), "").out;
  CHECK(rows_of(format::tle, all.path(), " --object 15167c").out == expected);
  CHECK(rows_of(format::tle, all.path(), " --object 0040500").out == expected);
}

TEST_CASE("catalogue: --object from a scene file, and --print-config writes it",
          "[catalogue][cli][config]") {
  const auto& objects = catalogue();
  const text_file all("catalogue.json", file_text(format::json, every_object()));
  const conescan_test::temp_file scene("omm = \"" + all.path() + "\"\nobject = \"" +
                                       objects[7].cospar + "\"\nduration-s = 600\nstep-s = 60\n");
  const auto direct = run_sim("--config " + scene.path);
  INFO(direct.err);
  REQUIRE(direct.exit_status == 0);
  const auto printed = run_sim("--config " + scene.path + " --print-config");
  REQUIRE(printed.exit_status == 0);
  CHECK(printed.out.find("\nobject = \"" + objects[7].cospar + "\"\n") != std::string::npos);
  const conescan_test::temp_file again(printed.out);
  CHECK(run_sim("--config " + again.path).out == direct.out);
  // The command line's --object wins over the file's.
  const text_file alone("alone.json", file_text(format::json, {&objects[8]}));
  const auto expected = run_sim("--omm " + alone.path() + " --duration-s 600 --step-s 60");
  REQUIRE(expected.exit_status == 0);
  CHECK(run_sim("--config " + scene.path + " --object " + objects[8].number).out == expected.out);
}

TEST_CASE("catalogue: no match names the nearest, two matches name both", "[catalogue][cli]") {
  const auto& objects = catalogue();
  for (const format f : every_format) {
    INFO(suffix(f));
    const text_file all(std::string("catalogue.") + suffix(f), file_text(f, every_object()));
    // A name one character off: the nearest is listed first, with its place and keys.
    const auto none = rows_of(f, all.path(), " --object 'SGP4-VER 06251 #0002X'");
    INFO(none.err);
    CHECK(none.exit_status == 2);
    CHECK(none.out.empty());
    CHECK(none.err.find("conescan-sim: --object: " + all.path() +
                        ": 'SGP4-VER 06251 #0002X' is no element set's NORAD catalogue number, "
                        "international designator or name (1000 sets read); the nearest: ") == 0);
    CHECK(none.err.find("'SGP4-VER 06251 #0002' (NORAD 40002, 2015-001C)") != std::string::npos);
  }
  // A number no set has: the nearest numbers (40000, one digit off, first).
  const text_file tles("catalogue.tle", file_text(format::tle, every_object()));
  const auto number = rows_of(format::tle, tles.path(), " --object 41000");
  CHECK(number.exit_status == 2);
  CHECK(number.err.find("the nearest: line 1 'SGP4-VER 00005 #0000' (NORAD 40000, 2015-001A); ") !=
        std::string::npos);
  // Two sets of one name: both listed, with where they are; the number tells them apart.
  std::vector<catalogue_object> twins(objects.begin(), objects.begin() + 10);
  twins[7].name = twins[3].name;
  std::vector<const catalogue_object*> twin_list;
  for (const catalogue_object& o : twins) twin_list.push_back(&o);
  for (const format f : every_format) {
    INFO(suffix(f));
    const text_file file(std::string("twins.") + suffix(f), file_text(f, twin_list));
    const auto two = rows_of(f, file.path(), " --object " + shell_word(twins[3].name));
    CHECK(two.exit_status == 2);
    CHECK(two.err.find("--object: " + file.path() + ": '" + twins[3].name +
                       "' matches 2 element sets: ") != std::string::npos);
    CHECK(two.err.find("(NORAD 40003, 2015-002A)") != std::string::npos);
    CHECK(two.err.find("(NORAD 40007, 2015-003B)") != std::string::npos);
    CHECK(two.err.find("give a key only one of them has") != std::string::npos);
    CHECK(rows_of(f, file.path(), " --object 40007").exit_status == 0);
  }
  // One object's sets twice (a history of its epochs): the number cannot tell them apart.
  const text_file history("history.tle",
                          file_text(format::tle, {&objects[3], &objects[4], &objects[3]}));
  const auto epochs = rows_of(format::tle, history.path(), " --object 40003");
  CHECK(epochs.exit_status == 2);
  CHECK(epochs.err.find("'40003' matches 2 element sets: line 1 'SGP4-VER 08195 #0003' (NORAD "
                        "40003, 2015-002A); line 7 'SGP4-VER 08195 #0003' (NORAD 40003, "
                        "2015-002A); they are one object's sets (a history of epochs?): keep the "
                        "one meant in a file of its own\n") != std::string::npos);
  const text_file twin_tle("twins.tle", file_text(format::tle, twin_list));
  CHECK(rows_of(format::tle, twin_tle.path(), " --object " + shell_word(twins[3].name))
            .err.find("line 10 '" + twins[3].name + "' (NORAD 40003, 2015-002A); line 22 '") !=
        std::string::npos);
}

TEST_CASE(
    "catalogue: a single set that does not match, an empty or blank selector, no file to "
    "choose from",
    "[catalogue][cli][hostile]") {
  const auto& objects = catalogue();
  const text_file alone("alone.tle", file_text(format::tle, {&objects[2]}));
  const auto other = rows_of(format::tle, alone.path(), " --object 40003");
  CHECK(other.exit_status == 2);
  CHECK(other.out.empty());
  CHECK(other.err.find("'40003' is no element set's NORAD catalogue number, international "
                       "designator or name (1 set read); the nearest: line 1 'SGP4-VER 06251 "
                       "#0002' (NORAD 40002, 2015-001C)") != std::string::npos);
  for (const char* blank : {"''", "' '", "'   '"}) {
    const auto run = rows_of(format::tle, alone.path(), std::string(" --object ") + blank);
    INFO(blank << ": " << run.err);
    CHECK(run.exit_status == 2);
    CHECK(run.err.rfind("conescan-sim: --object: ", 0) == 0);
  }
  const conescan_test::temp_file empty("tle = \"" + alone.path() + "\"\nobject = \"\"\n");
  const auto from_file = run_sim("--config " + empty.path);
  CHECK(from_file.exit_status == 2);
  CHECK(from_file.err.find(empty.path + ":2:") != std::string::npos);
  // Without a catalogue to choose from.
  for (const char* scene : {"--a-km 7000", "--oem " CONESCAN_TEST_DATA "/ccsds/paper-orbit.oem"}) {
    const auto run = run_sim(std::string(scene) + " --object 25544 --duration-s 60");
    INFO(scene << ": " << run.err);
    CHECK(run.exit_status == 2);
    CHECK(run.err.find("--object: chooses the element set of a catalogue --tle or --omm") !=
          std::string::npos);
  }
}

TEST_CASE("catalogue: a malformed set before or after the match is refused, naming its place",
          "[catalogue][cli][hostile]") {
  // Every set is read and checked (docs/SOURCES.md, "Catalogues"): a set that cannot be read may
  // be the one meant, and a second match may follow.
  const auto& objects = catalogue();
  std::vector<catalogue_object> broken(objects.begin(), objects.begin() + 200);
  broken[50].line2[69 - 1] = broken[50].line2[68] == '9' ? '0' : '9';  // a checksum
  broken[50].set.eccentricity = 1.5;                                   // the OMMs' fault
  std::vector<const catalogue_object*> list;
  for (const catalogue_object& o : broken) list.push_back(&o);
  struct expected_place {
    format f;
    std::string where;  // the error's place after the file name
  };
  const std::vector<expected_place> places{
      // Set 50: lines 151-153.
      {format::tle, ":153: --tle: line 2: checksum is "},
      // JSON: the member's path (the file leaves the place for the message).
      {format::json, ": [50].ECCENTRICITY: '1.5' is outside [0, 1)"},
      // CSV: the header, then a row a set; line and column.
      {format::csv, ":52:70: --omm: ECCENTRICITY: '1.5' is outside [0, 1)"},
      // XML and KVN: 24 lines a set (XML after 2 of the document's own).
      {format::xml,
       ":1212:1: --omm: ndm/omm[51]/body/segment/data/meanElements/ECCENTRICITY: '1.5' is "
       "outside [0, 1)"},
      {format::kvn, ":1212:16: --omm: ECCENTRICITY: '1.5' is outside [0, 1)"}};
  for (const expected_place& p : places) {
    const text_file file(std::string("broken.") + suffix(p.f), file_text(p.f, list));
    // The match after the malformed set, then before it.
    for (const std::size_t k : {std::size_t{150}, std::size_t{20}}) {
      const auto run = rows_of(p.f, file.path(), " --object " + objects[k].number);
      INFO(suffix(p.f) << ", match " << k << ": " << run.err);
      CHECK(run.exit_status == 2);
      CHECK(run.out.empty());
      CHECK(run.err.find(file.path() + p.where) != std::string::npos);
    }
  }
}

TEST_CASE("catalogue: a file of several without --object is refused where the second begins",
          "[catalogue][tle][omm][cli]") {
  const auto& objects = catalogue();
  const std::vector<const catalogue_object*> three{&objects[0], &objects[1], &objects[2]};
  const text_file tles("three.tle", file_text(format::tle, three));
  const auto run = rows_of(format::tle, tles.path(), "");
  CHECK(run.exit_status == 2);
  CHECK(run.err ==
        "conescan-sim: " + tles.path() +
            ":4: --tle: a second element set begins here: the file is a catalogue of several; "
            "choose one with --object and its NORAD catalogue number, international designator "
            "(1998-067A) or name: line 1 'SGP4-VER 00005 #0000' (NORAD 40000, 2015-001A); line "
            "4 'SGP4-VER 04632 #0001' (NORAD 40001, 2015-001B); line 7 'SGP4-VER 06251 #0002' "
            "(NORAD 40002, 2015-001C)\n");
  // A catalogue: the first few, and the reading stops there.
  const text_file all("catalogue.json", file_text(format::json, every_object()));
  const auto many = rows_of(format::json, all.path(), "");
  CHECK(many.exit_status == 2);
  CHECK(many.err.find("--omm: " + all.path() + ": [1]: a second element set begins here: ") !=
        std::string::npos);
  CHECK(many.err.find("[4] 'SGP4-VER 09880 #0004' (NORAD 40004, 2015-002B); ...\n") !=
        std::string::npos);
}

TEST_CASE("catalogue: designators in both forms, numbers and names as keys", "[catalogue][tle]") {
  using conescan::orbit::cospar_designator;
  using conescan::orbit::tle_form_designator;
  CHECK(tle_form_designator("1998-067A") == "98067A");
  CHECK(tle_form_designator(" 1998-067abc ") == "98067ABC");
  CHECK(tle_form_designator("98067A") == "98067A");
  CHECK_FALSE(tle_form_designator("1998-067"));      // no piece
  CHECK_FALSE(tle_form_designator("1998-067ABCD"));  // four letters
  CHECK_FALSE(tle_form_designator("ISS (ZARYA)"));
  CHECK_FALSE(tle_form_designator(""));
  CHECK(cospar_designator("98067A") == "1998-067A");
  CHECK(cospar_designator("57001B") == "1957-001B");
  CHECK(cospar_designator("56001B") == "2056-001B");
  CHECK(cospar_designator("UNKNOWN") == "UNKNOWN");
  // Keys of one set: alpha-5 number, designator, name.
  const auto& o = catalogue()[0];
  std::string line1 = o.line1, line2 = o.line2;
  line1.replace(2, 5, "A1234");
  line2.replace(2, 5, "A1234");
  set_checksum(line1);
  set_checksum(line2);
  const std::string text = "ISS (ZARYA)\n" + line1 + "\n" + line2 + "\n";
  for (const char* key : {"A1234", "a1234", "101234", "0101234", "2015-001A", "15001a",
                          "iss (zarya)", " ISS (ZARYA) "}) {
    std::istringstream in(text);
    INFO(key);
    CHECK(conescan::orbit::read_tle_object(in, "one.tle", key).ok());
  }
  for (const char* key : {"A1235", "1234", "2015-001B", "ISS", "ISS  (ZARYA)", "0"}) {
    std::istringstream in(text);
    INFO(key);
    const auto read = conescan::orbit::read_tle_object(in, "one.tle", key);
    REQUIRE_FALSE(read.ok());
    CHECK(read.error().option == "object");
  }
}

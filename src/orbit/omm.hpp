// Orbit Mean-Elements Messages (MODEL §10): the element sets SGP4 takes, in the formats CelesTrak
// and Space-Track serve them now that the TLE's five-digit catalogue numbers run out: CCSDS OMM in
// KVN and in XML, CelesTrak's CSV, CelesTrak's and Space-Track's JSON, told apart by the file's
// content (detect_omm_format). Accepted: SGP4/SDP4 elements of the Earth in TEME and UTC with
// every field SGP4 needs, in the OMM's own units. Refused, naming the file, the place (KVN and
// CSV the line and column, XML the line, column and element path, JSON the member's path) and the
// field, the value and what is allowed: SGP4-XP elements and other theories, a field missing or
// out of its range, an unknown KVN or XML keyword, catalogue numbers that disagree. Every rule:
// docs/SOURCES.md, "Orbit Mean-Elements Messages". Verified against python-sgp4's own OMM reader
// on its samples and on SGP4-VER.TLE converted to every format (tests/orbit/test_omm.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "orbit/sgp4.hpp"
#include "orbit/tle.hpp"
#include "text/diagnostic.hpp"

namespace conescan::orbit {

enum class omm_format { kvn, xml, csv, json };

/// "KVN", "XML", "CSV", "JSON".
std::string_view to_string(omm_format format) noexcept;

/// The format of a file's text, from its first characters (after a UTF-8 byte-order mark and
/// blanks): '<' XML, '[' or '{' JSON, CCSDS_OMM_VERS KVN, a first line with commas naming EPOCH
/// CSV; nullopt for anything else.
std::optional<omm_format> detect_omm_format(std::string_view text) noexcept;

/// Largest OMM file read (CelesTrak's catalogue of every active satellite is 8 MB as JSON).
inline constexpr std::size_t omm_max_bytes = std::size_t{64} << 20;

/// One element set of an OMM.
struct omm_element_set {
  /// The fields as a TLE holds them (tle.hpp), for SGP4 and for messages: name = OBJECT_NAME,
  /// catalog_number = NORAD_CAT_ID as written, satellite_number its value (up to 999999999),
  /// international_designator OBJECT_ID in the TLE's form (1998-067A -> 98067A; as written when
  /// it has another form), line_number the line where the set begins (0 for JSON).
  tle elements;
  /// The epoch as SGP4 takes it, days from 1949-12-31T00:00 UTC, computed exactly from the
  /// calendar (one rounding; a TLE's is rounded through a Julian date, see sgp4.cpp).
  double epoch_days_since_1950 = 0;
  omm_format format = omm_format::kvn;
  std::string place;  ///< where the set is, for messages: "line 3", "ndm/omm[2]", "[1]"
};

/// The set's elements in SGP4's units (mean_elements of its TLE fields, with its exact epoch).
sgp4_elements mean_elements(const omm_element_set& set) noexcept;

/// Every element set of an OMM's text (any format), in order; `source` names it in errors.
/// At least one set is required.
checked<std::vector<omm_element_set>> read_omm_sets(std::string_view text,
                                                    const std::string& source);

/// One element set of the file at `path` (at most omm_max_bytes), as `selection` says: with
/// only_one a file of several is refused, naming where the second begins.
checked<omm_element_set> read_omm(const std::string& path, tle_selection selection);

/// The element set of the file at `path` (a catalogue, at most omm_max_bytes) that `object`
/// names (catalogue.hpp: its NORAD catalogue number, international designator or name; exactly
/// one set must match, every set is read and checked), one set at a time; with `object` "" the
/// only set (only_one).
checked<omm_element_set> read_omm_object(const std::string& path, std::string_view object);

}  // namespace conescan::orbit

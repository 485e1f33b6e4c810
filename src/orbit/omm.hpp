// Orbit Mean-Elements Messages: the element sets SGP4 takes, in the formats CelesTrak and
// Space-Track serve them now that the TLE's five-digit catalogue numbers run out (MODEL §10).
//
// Formats, told apart by the file's content (detect_omm_format):
//  - CCSDS OMM in KVN (CCSDS 502.0-B-2/-B-3): `KEYWORD = value [units]` lines, beginning with
//    CCSDS_OMM_VERS; COMMENT lines anywhere. A file of several messages (each from its own
//    CCSDS_OMM_VERS line) holds several sets.
//  - CCSDS OMM in XML (the NDM/XML schema; pugixml): an <omm> root, or an <ndm> root holding
//    <omm> elements (CelesTrak's FORMAT=XML), each with header, body/segment/metadata and
//    data/meanElements, tleParameters.
//  - CelesTrak's CSV (FORMAT=CSV): a header of field names (OBJECT_NAME,OBJECT_ID,EPOCH,...), one
//    set a row; RFC 4180 quotes.
//  - CelesTrak's and Space-Track's JSON (FORMAT=JSON, class gp): an array of objects, or one
//    object, whose members are the field names; numbers as JSON numbers or as strings
//    (Space-Track quotes them); null is an absent field (nlohmann-json).
// In KVN and XML every keyword must be an OMM keyword; CSV columns and JSON members that SGP4
// does not read (Space-Track's SEMIMAJOR_AXIS, PERIOD, DECAY_DATE, ...) are ignored.
//
// What is accepted (SGP4 as Vallado et al. 2006 defines it reads a TLE's fields):
//  - MEAN_ELEMENT_THEORY SGP4, SGP/SGP4 (Space-Track), SDP4 or SGP4/SDP4, any case; mandatory
//    in KVN and XML, implied by CelesTrak's CSV and JSON. SGP4-XP elements (theory SGP4-XP,
//    EPHEMERIS_TYPE 4, or the BTERM and AGOM of its drag and radiation model) are refused: they
//    are fitted to the SGP4-XP propagator, which is not public, and differ from SGP4 elements
//    by kilometres. Other theories (DSST, USM, ...) are refused by name.
//  - CENTER_NAME EARTH, REF_FRAME TEME, TIME_SYSTEM UTC: mandatory in KVN and XML, checked when
//    present in CSV and JSON. SEMI_MAJOR_AXIS is refused (SGP4 takes MEAN_MOTION). GM, the
//    spacecraft parameters, the covariance and user-defined parameters are read and not used
//    (SGP4 has its own WGS-72 constants).
//  - Required, since SGP4 needs them: EPOCH (YYYY-MM-DDThh:mm:ss[.f] or YYYY-DDDThh:mm:ss[.f],
//    an optional Z; 1900-2099; no leap second, as SGP4's days have 86400 s), MEAN_MOTION (rev/day,
//    > 0), ECCENTRICITY ([0, 1)), INCLINATION ([0, 180] deg), RA_OF_ASC_NODE, ARG_OF_PERICENTER,
//    MEAN_ANOMALY ([0, 360] deg) and BSTAR (1/earth radii). Optional, with the TLE's defaults:
//    NORAD_CAT_ID (1 to 9 digits; none: 0), CLASSIFICATION_TYPE (U), EPHEMERIS_TYPE (0; 2 and
//    3, Spacetrack Report #3's SGP4 and SDP4, accepted), ELEMENT_SET_NO, REV_AT_EPOCH,
//    MEAN_MOTION_DOT and MEAN_MOTION_DDOT (0: they do not enter SGP4).
//  - Units in brackets (KVN) or a units attribute (XML), when given, must be the OMM's own
//    (rev/day, deg, 1/ER, rev/day**2, rev/day**3; any case).
//  - Catalogue numbers that disagree between fields are refused: NORAD_CAT_ID against the
//    TLE_LINE1 and TLE_LINE2 that Space-Track's JSON and CSV carry (columns 3-7, alpha-5 read).
// Every refusal names the file and the place: KVN and CSV the line and column, XML the line and
// column and the element's path (ndm/omm[2]/body/segment/data/meanElements/MEAN_MOTION), JSON
// the member's path ([0].MEAN_MOTION) or, for a syntax error, the line and column; and the
// field, the value read and what is allowed.
//
// Verified against python-sgp4's own OMM reader (sgp4.omm, the oracle) on its sample_omm.xml and
// sample_omm.csv and on OMMs converted from SGP4-VER.TLE in every format (tests/test_omm.cpp).
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

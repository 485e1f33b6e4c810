// The fields of one OMM element set as its format wrote them, before they are checked: what the
// readers of the four formats (omm_formats.cpp) hand to the conversion into SGP4's elements
// (omm.cpp). Internal to the orbit library; omm.hpp is the interface.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "text/diagnostic.hpp"

namespace conescan::orbit::omm_detail {

/// One field's value and where it was written.
struct field_value {
  std::string text;          ///< as written, blanks around it and its units removed
  std::uint64_t line = 0;    ///< 1-based; 0 when the format keeps no lines (JSON members)
  std::uint64_t column = 0;  ///< 1-based byte column of the value; 0 when not known
  std::string label;         ///< how a message names the field: "MEAN_MOTION", an XML element's
                             ///< path, a JSON member's path
};

/// One element set: its fields by keyword, and where it begins.
struct record {
  std::map<std::string, field_value, std::less<>> fields;
  std::uint64_t line = 0;  ///< where the set begins (0: not known)
  std::uint64_t column = 0;
  std::string place;   ///< "line 3", "ndm/omm[2]", "[1]": where the set is, for messages
  std::string label;   ///< how a message about the whole set names it ("" when the line does)
  bool ccsds = false;  ///< KVN or XML: CENTER_NAME, REF_FRAME, TIME_SYSTEM and the theory are
                       ///< mandatory (CelesTrak's CSV and JSON imply them)
};

/// The sets of each format, with the format's own checks (syntax, keywords, units, repeats).
checked<std::vector<record>> kvn_records(std::string_view text, const std::string& source);
checked<std::vector<record>> xml_records(std::string_view text, const std::string& source);
checked<std::vector<record>> csv_records(std::string_view text, const std::string& source);
checked<std::vector<record>> json_records(std::string_view text, const std::string& source);

/// The error about a field: FILE:LINE:COLUMN: LABEL: message.
diagnostic field_error(const std::string& source, const field_value& field, std::string message);

/// The error about a whole set: FILE:LINE: [LABEL: ]message.
diagnostic record_error(const std::string& source, const record& set, std::string message);

}  // namespace conescan::orbit::omm_detail

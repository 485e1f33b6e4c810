// The fields of one OMM element set as its format wrote them, before they are checked: what the
// readers of the four formats (omm_formats.cpp) hand to the conversion into SGP4's elements
// (omm.cpp). Internal to the orbit library; omm.hpp is the interface.
#pragma once

#include <cstddef>
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

/// What a format's reader does with each set as soon as the set is complete: true to read on,
/// false to stop (the caller has what it wants), or the error that stops the reading. The
/// readers hold one set at a time, so a catalogue costs the memory of its text and one set.
using record_handler = std::function<checked<bool>(record&&)>;

/// The sets of each format, in order, with the format's own checks (syntax, keywords, units,
/// repeats), each handed to `on_set` as soon as it is complete.
checked<void> kvn_records(std::string_view text, const std::string& source,
                          const record_handler& on_set);
checked<void> xml_records(std::string_view text, const std::string& source,
                          const record_handler& on_set);
checked<void> csv_records(std::string_view text, const std::string& source,
                          const record_handler& on_set);
checked<void> json_records(std::string_view text, const std::string& source,
                           const record_handler& on_set);

/// Largest text of one element set in XML (an <omm> element, from its '<' to its end tag's
/// '>'): a set is a few KiB; the bound keeps the tree pugixml builds of one set within about
/// 64 times this (a node of 64 bytes for every 4 bytes of `<a/>`), whatever the file holds.
inline constexpr std::size_t omm_xml_max_set_bytes = std::size_t{1} << 20;

/// Nesting an OMM's XML may have (<ndm>/<omm>/<body>/<segment>/<data>/<meanElements>/<X> is 7).
inline constexpr std::size_t omm_xml_max_depth = 32;

/// The error about a field: FILE:LINE:COLUMN: LABEL: message.
diagnostic field_error(const std::string& source, const field_value& field, std::string message);

/// The error about a whole set: FILE:LINE: [LABEL: ]message.
diagnostic record_error(const std::string& source, const record& set, std::string message);

}  // namespace conescan::orbit::omm_detail

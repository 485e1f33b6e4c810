// JSON files as the readers of user files need them: nlohmann-json (Debian nlohmann-json3-dev)
// reads RFC 8259, and this adds what a reader of a user's file must refuse that nlohmann keeps
// silently or bounds only by memory: a member given twice in one object (nlohmann keeps the last
// one), nesting deeper than a bound, and a text larger than a bound. Used by the fit's JSON
// (calibration/fit_json.hpp) and CelesTrak's OMM as JSON (orbit/omm.hpp).
//
// Positions. A syntax error is placed at its line and column (from nlohmann's byte offset of the
// last character it read); a member given twice and a nesting too deep are placed by their JSON
// path (`.parameters.h1.sigma`, `[3].NORAD_CAT_ID`), since nlohmann's DOM keeps no positions.
// The readers that then check the document's shape name the path too (json_path below).
// Numbers are read as nlohmann reads them: integers to int64/uint64, others by strtod, correctly
// rounded, so a double written with its shortest round-trip text reads back to itself; a number
// beyond the doubles' range is refused (nlohmann's "number overflow").
#pragma once

#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "text/diagnostic.hpp"

namespace conescan::text {

/// Deepest nesting a document may have (arrays and objects counted alike).
inline constexpr std::size_t json_max_depth = 64;

/// The one JSON value of `text` (whitespace around it allowed). Errors name `file_name` and the
/// line and column of a syntax error, or the path of a repeated member or a nesting too deep.
checked<nlohmann::ordered_json> parse_json_document(std::string_view text,
                                                    const std::string& file_name,
                                                    std::size_t max_depth = json_max_depth);

/// What a streaming reader does with each element of a top-level array as soon as it is read
/// (index, value): true to read on, false to stop, or the error that stops the reading.
using json_element_handler =
    std::function<checked<bool>(std::size_t, const nlohmann::ordered_json&)>;

/// parse_json_document for a document that may be a long array (a catalogue): each element of a
/// top-level array is handed to on_element as soon as it is read and then dropped, so the memory
/// held is one element's, and the reading stops where on_element says. Returns the root: an
/// empty array when the root is an array, the whole value otherwise (on_element not called).
/// Errors as parse_json_document's; on_element's are returned as they are.
checked<nlohmann::ordered_json> parse_json_streaming(std::string_view text,
                                                     const std::string& file_name,
                                                     const json_element_handler& on_element,
                                                     std::size_t max_depth = json_max_depth);

/// A member's path: parent + "." + key ("" + "kind" is ".kind"); an element's: parent + "[i]".
std::string json_path(const std::string& parent, std::string_view key);
std::string json_path(const std::string& parent, std::size_t index);

/// "an object", "an array", "a string", "a number", "true or false", "null": what a value is, for
/// messages that say what was found.
std::string_view json_kind(const nlohmann::ordered_json& value) noexcept;

}  // namespace conescan::text

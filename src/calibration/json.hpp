// JSON text for the calibration's files (the fit's result, the design): strings and numbers as
// the writers of fit_json.cpp put them. Reading is text/json_document.hpp's (nlohmann-json).
#pragma once

#include <string>
#include <string_view>

namespace conescan::calibration {

/// JSON text of a string: quoted and escaped by nlohmann-json (bytes that are not UTF-8 replaced
/// by U+FFFD, so that the file is always JSON a reader takes).
std::string json_string(std::string_view text);

/// JSON text of a number: the shortest text that reads back to the same double (std::to_chars:
/// 0, 0.05, 1e-05, never 0.0), or null for NaN and infinities, which JSON cannot hold.
std::string json_number(double value);

}  // namespace conescan::calibration

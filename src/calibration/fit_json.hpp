// A fit's result as one JSON object (fit_json, design_json), and the reader of a converged fit's
// object (read_fit_json), which `conescan-sim --apply FILE` uses to subtract the modelled errors.
// Every parameter is listed; a value the fit does not determine is null, with "withheld" saying
// why; numbers are the shortest text that reads back to the same double, so a fit read back is
// the fit_result that wrote it. A fit that did not converge has no "parameters" (it cannot be
// taken for an estimate); one with a drifting parameter is not read back (a correction needs one
// value). Every member, with an example of each kind: docs/CALIBRATION.md, "Files".
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "calibration/estimator.hpp"

namespace conescan::calibration {

/// The JSON object of a fit (converged or not) or of a design, ending with a newline.
std::string fit_json(const fit_outcome& outcome);
std::string design_json(const design_result& design);

/// A converged fit's JSON read back (nlohmann-json, text/json_document.hpp): the fit_result
/// that wrote it, exactly (every number round-trips). Errors name the file and, for JSON syntax,
/// the line and column, else the member's JSON path (.parameters.h1.sigma.estimate): not a JSON
/// object, kind not "fit", a fit that did not converge, a member missing or of the wrong type,
/// unknown or incomplete parameters, units that disagree with the table, matrices of the wrong
/// size, coordinates that do not match the free parameters.
checked<fit_result> read_fit_json(std::string_view text, const std::string& file_name);

/// Largest fit JSON read (a fit of 16 heads is ~40 KB).
inline constexpr std::size_t fit_json_max_bytes = std::size_t{64} << 20;

/// The same from a file (at most fit_json_max_bytes), for conescan-sim --apply: every error
/// names the option "apply".
checked<fit_result> read_fit_json_file(const std::string& path);

}  // namespace conescan::calibration

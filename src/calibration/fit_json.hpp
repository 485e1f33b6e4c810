// A fit's result as one JSON object, and the reader of that object, which
// `conescan-sim --apply FILE` uses to subtract the modelled errors.
//
// A converged fit:
//   {"kind": "fit", "converged": true,
//    "parameters": {"h1.sigma": {"estimate": 0.05, "sigma": 0.0004, "unit": "deg", "free": true},
//                   "h1.phase": {"estimate": null, "sigma": null, "unit": "deg", "free": true,
//                                "withheld": "undetermined: ..."},
//                   "h1.dgamma": {"estimate": 0, "sigma": 0, "unit": "deg", "free": false}, ...},
//    "parameter_order": [the free parameters, the order of "correlation"],
//    "correlation": [[...]], "chi2_dof": ..., "dof": ..., "residual_count": ...,
//    "residual_rms_deg": {"h1": ...}, "observations": {"h1": ...}, "condition": ...,
//    "unobservable": [{"combination": {"h1.dgamma": 0.71, "horizon-km": -0.70},
//                      "eigenvalue_ratio": ...}],
//    "rank": ..., "outliers": {"count": ..., "threshold": 6, "worst": [{"t_s": ..., "row": ...,
//    "head": 1, "chord_residual_deg": ..., "phase_residual_deg": ..., "normalised": ...}]},
//    "robust_loss": {"kind": "huber", "scale": 3}, "unit_weights": false,
//    "dropped_at_start": 0, "noise_scaling": "estimated",
//    "noise": {"h1": {"declared_deg": 0.01, "ratio": 1.02, "estimated_deg": 0.0102,
//                     "weight_ratio": 1.01}, ...},
//    "readmitted": 0, "dropped": {"h1": {"count": 0, "fraction": 0}, ...},
//    "systematic": [{"head": 1, "residual": "phase", "outliers": 50, "same_sign": 50,
//                    "sign": 1, "mean_residual_deg": 0.05, "probability": 1.8e-15}],
//    "warnings": ["h2: its residuals show 9.9 times the declared noise ...", ...],
//    "iterations": 7, "solver_message": "...",
//    "drift": {"horizon-km": {"unit": "km", "segment_s": 86400, "segments": [{"start_s": 0,
//              "end_s": 86400, "observations": 172800, "estimate": 41.9, "sigma": 0.002}, ...]}},
//    "coordinates": {"names": [...], "estimate": [...], "covariance": [[...]]}}
// Every parameter is listed, held ones with their held value and sigma 0. A value the fit does
// not determine is null (estimate, sigma, its correlations and coordinates), with "withheld"
// saying why; so is a condition number that is infinite. "coordinates" are the estimated
// values themselves (the misalignment as misalign-x, misalign-y when sigma and phase are both
// free) with their full covariance: what a correction propagates, and defined even where
// phi_A is not. Numbers are the shortest text that reads back to the same double.
//
// "noise" is each head's declared crossing noise, the robust scale of its residuals in units of
// it (ratio, null when not estimated), the crossing noise that implies (null likewise) and the
// scale its weights used; "readmitted" the measurements left out at the start and predictable at
// a later solution, "dropped" those left out at the end, per head; "systematic" the heads'
// outliers whose residuals share a sign (estimator.hpp); "warnings" what the table prints as
// warning lines. A file without "noise_scaling" (written before the noise was estimated) reads
// with no noise and no warnings. "drift", only when a parameter drifts (--free NAME@SECONDS),
// holds each drifting parameter's value and 1 sigma per segment (its entry in "parameters" is
// withheld as "drifts", and "parameter_order", "correlation" and "coordinates" name its segments
// "horizon-km[3]"); such a fit is not read back (a correction needs one value).
//
// A fit that did not converge: {"kind": "fit", "converged": false, "iterations": ..., "cost":
// ..., "solver_message": ..., "last_state": {"h1.sigma": {"value": ..., "unit": "deg", "free":
// true}, ...}}, with no "parameters" so that it cannot be mistaken for an estimate.
// Experiment design: {"kind": "design", "parameters": {... "estimate" the nominal value,
// "sigma" the predicted 1 sigma}, "parameter_order", "correlation", "condition", "unobservable",
// "rank", "residual_count", "dropped", "drift", "coordinates"}.
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

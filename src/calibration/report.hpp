// The human tables of a fit and of an experiment design (standard output of conescan-fit).
// Numbers with 6 significant digits, locale-independent (std::to_chars); the JSON
// (fit_json.hpp) carries them round-trip exact.
#pragma once

#include <string>

#include "calibration/estimator.hpp"

namespace conescan::calibration {

/// Estimate, 1 sigma and unit of every parameter (held ones marked), the correlation matrix of
/// the free ones, chi2/dof, residual RMS per head, the condition number, the unobservable
/// combinations, the outliers and whether the fit converged. A fit that did not converge prints
/// "NOT CONVERGED" and its last state, labelled as such, and no uncertainty.
std::string fit_table(const fit_outcome& outcome);

/// The predicted 1 sigma of every free parameter, correlation, condition and unobservable
/// combinations of an experiment design.
std::string design_table(const design_result& design);

/// A number with `digits` significant digits (std::to_chars, general format); "inf", "nan" as
/// such.
std::string short_number(double value, int digits = 6);

}  // namespace conescan::calibration

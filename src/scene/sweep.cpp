#include "scene/sweep.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "text/number_text.hpp"

namespace conescan::scene {

namespace {

// Decimals of a number as typed: digits after the point less the exponent ("2.5e-2": 3).
int typed_decimals(std::string_view text) {
  const std::size_t e = text.find_first_of("eE");
  const std::string_view mantissa = text.substr(0, e);
  const std::size_t dot = mantissa.find('.');
  long decimals = dot == std::string_view::npos ? 0 : static_cast<long>(mantissa.size() - dot - 1);
  if (e != std::string_view::npos) {
    std::string_view exponent = text.substr(e + 1);
    if (!exponent.empty() && exponent.front() == '+') exponent.remove_prefix(1);
    long power = 0;
    std::from_chars(exponent.data(), exponent.data() + exponent.size(), power);
    decimals -= std::clamp(power, -1000L, 1000L);
  }
  return static_cast<int>(std::clamp(decimals, 0L, 1000L));
}

}  // namespace

checked<sweep_spec> parse_sweep(std::string_view text) {
  const std::string usage = quote(text) + ": expected NAME=FROM:TO:STEP, e.g. e=0:0.1:0.025";
  const std::size_t equals = text.find('=');
  if (equals == std::string_view::npos || equals == 0) return diagnostic::saying(usage);
  sweep_spec spec;
  spec.text = std::string(text);
  spec.name = std::string(text.substr(0, equals));
  const std::string_view range = text.substr(equals + 1);
  const std::size_t c1 = range.find(':');
  const std::size_t c2 = c1 == std::string_view::npos ? c1 : range.find(':', c1 + 1);
  if (c2 == std::string_view::npos || range.find(':', c2 + 1) != std::string_view::npos)
    return diagnostic::saying(usage);
  const std::string_view texts[] = {range.substr(0, c1), range.substr(c1 + 1, c2 - c1 - 1),
                                    range.substr(c2 + 1)};
  const char* roles[] = {"FROM", "TO", "STEP"};
  double values[3] = {};
  for (int k = 0; k < 3; ++k) {
    const checked<double> v = text::parse_real(texts[k]);
    if (!v.ok()) return diagnostic::saying(quote(text) + ": " + roles[k] + " " + v.error().message);
    values[k] = v.value();
  }
  spec.from = values[0];
  spec.to = values[1];
  spec.step = values[2];
  if (!(spec.step > 0)) return diagnostic::saying(quote(text) + ": STEP must be > 0");
  if (!(spec.to >= spec.from)) return diagnostic::saying(quote(text) + ": TO must be >= FROM");
  const double intervals = std::floor((spec.to - spec.from) / spec.step + 1e-9);
  if (!(intervals < static_cast<double>(max_sweep_values)))
    return diagnostic::saying(quote(text) + ": more than 2^53 values");
  spec.count = static_cast<std::uint64_t>(intervals) + 1;
  const int decimals = std::max(typed_decimals(texts[0]), typed_decimals(texts[2]));
  spec.decimals = decimals > 30 ? -1 : decimals;
  return spec;
}

double sweep_value(const sweep_spec& spec, std::uint64_t j) {
  const double exact = spec.from + static_cast<double>(j) * spec.step;
  if (spec.decimals < 0) return exact;
  // Fixed notation of up to 309 integer digits and 30 decimals, then the one parser.
  char text[400];
  const auto written =
      std::to_chars(text, text + sizeof text, exact, std::chars_format::fixed, spec.decimals);
  if (written.ec != std::errc()) return exact;
  const checked<double> rounded = text::parse_real(std::string_view(text, written.ptr - text));
  return rounded.ok() ? rounded.value() : exact;
}

}  // namespace conescan::scene

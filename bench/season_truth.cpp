// conescan-season-truth: the apparent horizon's seasonal shift that conescan-sim's rows hold,
// averaged per segment, for scripts/calibration-season.sh (docs/CALIBRATION.md, "Parameters that
// drift"). conescan-sim moves the horizon's centre north by shift sin(declination) with ERFA's
// apparent declination at each row's own time (sources::sun_declination_track); --date's
// declination is the Almanac's low-precision one (0.002 deg from ERFA's at 2025-03-06: 0.4 m of
// an 11.5 km shift, half the 1 sigma of a day at 1 Hz), so the truth is computed here the way the
// rows were.
//
// Usage: conescan-season-truth EPOCH_UTC DAYS SEGMENT_S STEP_S SHIFT_KM
// Prints CSV: segment, start_s, declination_deg (at the segment's middle), shift_km (the mean of
// SHIFT_KM sin(declination) over the rows t = k STEP_S of the segment).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "sources/sun_declination.hpp"

namespace src = conescan::sources;

int main(int argc, char** argv) {
  if (argc != 6) {
    std::fprintf(stderr, "usage: conescan-season-truth EPOCH_UTC DAYS SEGMENT_S STEP_S SHIFT_KM\n");
    return 2;
  }
  const auto epoch = src::parse_epoch(argv[1], src::time_scale::utc);
  if (!epoch.ok()) {
    std::fprintf(stderr, "conescan-season-truth: %s\n", epoch.error().text().c_str());
    return 2;
  }
  const double days = std::strtod(argv[2], nullptr), segment_s = std::strtod(argv[3], nullptr);
  const double step_s = std::strtod(argv[4], nullptr), shift_km = std::strtod(argv[5], nullptr);
  const double span_s = days * 86400;
  const auto track =
      src::sun_declination_track::over(epoch.value(), src::add_seconds(epoch.value(), span_s));
  if (!track.ok()) return 2;
  constexpr double deg = std::numbers::pi / 180;
  std::printf("segment,start_s,declination_deg,shift_km\n");
  for (long segment = 0; static_cast<double>(segment) * segment_s < span_s; ++segment) {
    const double start_s = static_cast<double>(segment) * segment_s;
    double sum = 0;
    long rows = 0;
    for (long k = std::lround(std::ceil(start_s / step_s));
         static_cast<double>(k) * step_s < std::min(start_s + segment_s, span_s); ++k, ++rows)
      sum += std::sin(
          track.value().at(src::add_seconds(epoch.value(), static_cast<double>(k) * step_s)));
    const double middle =
        track.value().at(src::add_seconds(epoch.value(), start_s + segment_s / 2)) / deg;
    std::printf("%ld,%.17g,%.17g,%.17g\n", segment, start_s, middle,
                shift_km * sum / static_cast<double>(rows));
  }
  return 0;
}

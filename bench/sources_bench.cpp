// conescan-sources-bench: the figures docs/SOURCES.md quotes for the time, orbit and attitude
// sources (src/sources/): how far a noon-of-date Sun is from the row's own time, the time per call
// of each source, and the reading of a large OEM.
//
// Usage:
//   conescan-sources-bench                       all figures but the large file
//   conescan-sources-bench --make-oem PATH N     write a synthetic OEM of N data lines to PATH
//   conescan-sources-bench --read-oem PATH       read PATH whole and with a one-hour span (run it
//                                                under /usr/bin/time -v for the peak memory)
#include <erfa.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <numbers>
#include <string>

#include "orbit/kepler.hpp"
#include "sources/aem.hpp"
#include "sources/attitude_csv.hpp"
#include "sources/oem.hpp"
#include "sources/sun_declination.hpp"
#include "timing.hpp"

using conescan::checked;
using conescan::diagnostic;

namespace {

using namespace conescan::sources;
constexpr double deg = std::numbers::pi / 180;
constexpr double gm = 3.986004418e14;

instant utc(const char* text) {
  return (parse_epoch(text, time_scale::utc)).value();
}

/// The declination at 00:00 and 12:00 of the same day, and its largest change in 12 h of a year:
/// what a noon-of-date Sun misses at other hours.
void noon_against_row_time() {
  double worst = 0;
  for (int day = 0; day < 366; ++day) {
    const instant midnight = add_seconds(utc("2025-01-01T00:00:00"), day * 86400.0);
    worst = std::max(worst, std::abs(sun_declination_rad(add_seconds(midnight, 43200.0)) -
                                     sun_declination_rad(midnight)));
  }
  std::printf("declination change over 12 h (2025): max %.4f deg\n", worst / deg);
}

/// A Kepler orbit (400 km, 51.6 deg) as an OEM of `lines` states `step_s` apart.
void write_oem(const std::string& path, long lines, double step_s, const char* interpolation) {
  const conescan::orbit::elements el{6778137.0, 0.001, 51.6 * deg, 0.3, 0.5, 0.0};
  const conescan::orbit::kepler_orbit orbit(el, conescan::orbit::two_body_rates(el, gm), gm);
  std::ofstream out(path);
  out << "CCSDS_OEM_VERS = 2.0\nCREATION_DATE = 2020-01-01T00:00:00\nORIGINATOR = bench\n"
         "META_START\nOBJECT_NAME = BENCH\nOBJECT_ID = 2020-001A\nCENTER_NAME = EARTH\n"
         "REF_FRAME = GCRF\nTIME_SYSTEM = TAI\nSTART_TIME = 2000-01-01T00:00:00\n"
         "STOP_TIME = 2026-01-01T00:00:00\n"
      << interpolation << "META_STOP\n";
  const instant t0 = utc("2000-01-01T00:00:00");
  char line[256];
  for (long k = 0; k < lines; ++k) {
    const double t = static_cast<double>(k) * step_s;
    const conescan::orbit::orbit_state s = orbit.state_at(t);
    const instant at = add_seconds(t0, t);
    // The TAI calendar date of the instant (no leap seconds on TAI: seconds of day as held).
    int y = 0, m = 0, d = 0;
    double fraction = 0;
    eraJd2cal(2400000.5, static_cast<double>(at.tai_mjd), &y, &m, &d, &fraction);
    const double sec = at.tai_seconds;
    const int hh = static_cast<int>(sec / 3600), mm = static_cast<int>((sec - hh * 3600) / 60);
    const int n = std::snprintf(
        line, sizeof line, "%04d-%02d-%02dT%02d:%02d:%09.6f %.9f %.9f %.9f %.12f %.12f %.12f\n", y,
        m, d, hh, mm, sec - hh * 3600 - mm * 60, s.r_eci_m.x / 1000, s.r_eci_m.y / 1000,
        s.r_eci_m.z / 1000, s.v_eci_m_s.x / 1000, s.v_eci_m_s.y / 1000, s.v_eci_m_s.z / 1000);
    out.write(line, n);
  }
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void read_big(const std::string& path) {
  const auto bytes = static_cast<double>(std::ifstream(path, std::ios::ate).tellg());
  for (int with_span = 0; with_span < 2; ++with_span) {
    oem_read_options options;
    if (with_span) options.span = time_span{utc("2000-01-02T00:00:00"), utc("2000-01-02T01:00:00")};
    const auto start = std::chrono::steady_clock::now();
    const checked<oem_ephemeris> r = read_oem(path, options);
    const double s = seconds_since(start);
    if (!r.ok()) {
      std::printf("%s: %.1f s (%.0f MB/s): %s\n", with_span ? "one-hour span" : "whole file", s,
                  bytes / s / 1e6, r.error().text().c_str());
    } else {
      std::printf("%s: %.1f s (%.0f MB/s): %zu states kept\n",
                  with_span ? "one-hour span" : "whole file", s, bytes / s / 1e6,
                  r.value().segments()[0].samples.size());
    }
  }
}

/// attitude_at of an AEM (a slow tumble sampled every second for an hour) and angles_at of an
/// attitude CSV of the same length.
void time_attitudes() {
  using conescan::bench::keep;
  using conescan::bench::time_per_sample;
  const std::string aem_path = "/tmp/conescan_sources_bench.aem";
  const std::string csv_path = "/tmp/conescan_sources_bench.csv";
  for (const char* interpolation :
       {"INTERPOLATION_METHOD = LINEAR\n",
        "INTERPOLATION_METHOD = LAGRANGE\nINTERPOLATION_DEGREE = 7\n"}) {
    {
      std::ofstream aem(aem_path);
      aem << "CCSDS_AEM_VERS = 1.0\nCREATION_DATE = 2020-01-01T00:00:00\nORIGINATOR = bench\n"
             "META_START\nOBJECT_NAME = BENCH\nOBJECT_ID = 2020-001A\nREF_FRAME_A = EME2000\n"
             "REF_FRAME_B = SC_BODY_1\nATTITUDE_DIR = A2B\nTIME_SYSTEM = TAI\n"
             "START_TIME = 2020-01-01T00:00:00\nSTOP_TIME = 2020-01-01T01:00:00\n"
             "ATTITUDE_TYPE = QUATERNION\nQUATERNION_TYPE = LAST\n"
          << interpolation << "META_STOP\nDATA_START\n";
      char line[160];
      for (int k = 0; k <= 3600; ++k) {
        const double a = 0.01 * k, b = 0.003 * k;  // about a slowly moving axis
        const double n = std::sqrt(1 + b * b);
        const int len =
            std::snprintf(line, sizeof line, "2020-01-01T%02d:%02d:%02d %.15f %.15f %.15f %.15f\n",
                          k / 3600, k / 60 % 60, k % 60, std::sin(a / 2) / n,
                          b * std::sin(a / 2) / n, 0.0, std::cos(a / 2));
        aem.write(line, len);
      }
      aem << "DATA_STOP\n";
    }
    const aem_attitude a = (read_aem(aem_path)).value();
    const instant t0 = (parse_epoch("2020-01-01T00:00:00", time_scale::tai)).value();
    const auto per_call = time_per_sample(1000, [&] {
      for (int k = 0; k < 1000; ++k) {
        keep((a.attitude_at(add_seconds(t0, 3.57 * k))).value().body_from_inertial.w);
      }
    });
    std::printf("AEM %s degree %d: attitude_at %.0f ns\n",
                std::string(to_string(a.segments()[0].method)).c_str(), a.segments()[0].degree,
                per_call.median_ns);
  }
  {
    std::ofstream csv(csv_path);
    csv << "t_s,roll_deg,pitch_deg,yaw_deg\n";
    for (int k = 0; k <= 3600; ++k) csv << k << "," << 0.1 * std::sin(0.01 * k) << ",0.05,0\n";
  }
  const attitude_table table = (read_attitude_csv(csv_path)).value();
  const auto per_row = time_per_sample(1000, [&] {
    for (int k = 0; k < 1000; ++k) keep((table.angles_at(3.57 * k)).value().roll_rad);
  });
  std::printf("attitude CSV: angles_at %.0f ns\n", per_row.median_ns);
  std::remove(aem_path.c_str());
  std::remove(csv_path.c_str());
}

void time_calls() {
  using conescan::bench::keep;
  using conescan::bench::time_per_sample;
  const instant t0 = utc("2025-01-01T00:00:00");
  const std::size_t n = 1000;
  const auto erfa = time_per_sample(
      n,
      [&] {
        for (int k = 0; k < 1000; ++k) keep(sun_declination_rad(add_seconds(t0, 97.0 * k)));
      },
      5);
  const sun_declination_track track =
      (sun_declination_track::over(t0, add_seconds(t0, 86400.0))).value();
  const auto tracked = time_per_sample(n, [&] {
    for (int k = 0; k < 1000; ++k) keep(track.at(add_seconds(t0, 83.0 * k)));
  });
  std::printf("Sun's declination per call: ERFA %.0f ns, track %.1f ns\n", erfa.median_ns,
              tracked.median_ns);

  const std::string path = "/tmp/conescan_sources_bench.oem";
  for (const char* interpolation :
       {"INTERPOLATION = HERMITE\nINTERPOLATION_DEGREE = 7\n",
        "INTERPOLATION = LAGRANGE\nINTERPOLATION_DEGREE = 7\n", "INTERPOLATION = LINEAR\n"}) {
    write_oem(path, 8641, 10.0, interpolation);  // one day at 10 s
    const auto start = std::chrono::steady_clock::now();
    const checked<oem_ephemeris> r = read_oem(path);
    const double read_s = seconds_since(start);
    const oem_ephemeris& o = r.value();
    const instant a = utc("2000-01-01T00:00:00");
    const auto per_state = time_per_sample(n, [&] {
      for (int k = 0; k < 1000; ++k) {
        keep((o.state_at(add_seconds(a, 86.3 * k))).value().state.r_m.x);
      }
    });
    std::printf("OEM %s: read 8641 lines in %.1f ms; state_at %.0f ns\n",
                std::string(to_string(o.segments()[0].method)).c_str(), read_s * 1e3,
                per_state.median_ns);
  }
  std::remove(path.c_str());
  time_attitudes();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 4 && std::strcmp(argv[1], "--make-oem") == 0) {
    write_oem(argv[2], std::atol(argv[3]), 1.0,
              "INTERPOLATION = HERMITE\nINTERPOLATION_DEGREE = 7\n");
    return 0;
  }
  if (argc == 3 && std::strcmp(argv[1], "--read-oem") == 0) {
    read_big(argv[2]);
    return 0;
  }
  noon_against_row_time();
  time_calls();
  return 0;
}

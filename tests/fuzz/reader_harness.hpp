// The readers of files on any bytes: TLE, OMM (KVN, XML, CSV, JSON), OEM, AEM, attitude CSV,
// telemetry, a fit's JSON, a summary state. Header-only, so that the Catch2 suite replays the
// corpora through the same checks (tests/apps/test_robustness.cpp) and each libFuzzer target
// (fuzz_<reader>.cpp) is one call.
//
// Invariants, for every input: no crash, leak or undefined behaviour (the fuzz build's ASan and
// UBSan); a refusal has a message, printable (quote() escapes control bytes, the text is valid
// UTF-8) and naming the file; what is read is consistent (times increasing, numbers finite) and
// usable without a crash (a state, an attitude, SGP4 at the epoch); a fit's JSON and a summary
// state that read write back to text that reads back to the same text.
#pragma once

#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

#include "calibration/fit_json.hpp"
#include "calibration/telemetry.hpp"
#include "orbit/omm.hpp"
#include "orbit/sgp4.hpp"
#include "orbit/tle.hpp"
#include "simulation/summary_state.hpp"
#include "sources/aem.hpp"
#include "sources/attitude_csv.hpp"
#include "sources/oem.hpp"
#include "sources/time_scales.hpp"

namespace conescan_fuzz {

namespace reader_detail {

// Printable ASCII, tabs and newlines aside, and whole UTF-8 sequences only.
inline bool printable(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) continue;
    const std::size_t n = c >= 0xF0 && c <= 0xF4   ? 4
                          : c >= 0xE0              ? 3
                          : c >= 0xC2 && c <= 0xDF ? 2
                                                   : 0;
    if (n == 0 || i + n > text.size()) return false;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) return false;
    i += n - 1;
  }
  return true;
}

// A refusal as the programs print it: a message, printable.
inline std::string check_refusal(const conescan::diagnostic& e, const char* reader) {
  if (e.message.empty()) return std::string(reader) + ": a refusal without a message";
  if (!printable(e.text()))
    return std::string(reader) + ": a refusal that is not printable: " + conescan::quote(e.text());
  return {};
}

// The bytes as a file the path readers open: an anonymous memory file (memfd) named through
// /proc/self/fd, rewritten for each input (no disk, no file left behind).
class memory_file {
 public:
  memory_file() : fd_(static_cast<int>(::memfd_create("conescan-fuzz", 0))) {}
  ~memory_file() {
    if (fd_ >= 0) ::close(fd_);
  }
  memory_file(const memory_file&) = delete;
  memory_file& operator=(const memory_file&) = delete;
  // The path of a file holding exactly `data`; "" if it cannot be made.
  std::string hold(const std::uint8_t* data, std::size_t size) {
    if (fd_ < 0 || ::ftruncate(fd_, 0) != 0) return {};
    std::size_t done = 0;
    while (done < size) {
      const ssize_t n = ::pwrite(fd_, data + done, size - done, static_cast<off_t>(done));
      if (n <= 0) return {};
      done += static_cast<std::size_t>(n);
    }
    return "/proc/self/fd/" + std::to_string(fd_);
  }

 private:
  int fd_;
};

inline memory_file& shared_file() {
  static memory_file file;  // one per process: libFuzzer runs one input at a time
  return file;
}

}  // namespace reader_detail

/// A TLE: read, then SGP4 at its epoch and a day later (any status, no crash).
inline std::string check_tle(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  const auto read =
      conescan::orbit::read_tle(in, "fuzz.tle", conescan::orbit::tle_selection::first);
  if (!read.ok()) return reader_detail::check_refusal(read.error(), "tle");
  const conescan::orbit::sgp4_propagator sgp4(read.value());
  for (const double minutes : {0.0, 1440.0, -720.0}) (void)sgp4.state_at(minutes);
  return {};
}

/// An OMM in any format (the fuzz dictionary leans to XML: comments, CDATA sections, processing
/// instructions, a document type): every set read_omm_sets reads gives SGP4 elements propagated
/// at its epoch and a day on (any status, no crash); --omm's reader of the file (the first set)
/// reads what the text reader read first, and refuses with a printable message.
inline std::string check_omm(const std::uint8_t* data, std::size_t size) {
  namespace orb = conescan::orbit;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto sets = orb::read_omm_sets(text, "fuzz.omm");
  if (!sets.ok()) {
    if (std::string f = reader_detail::check_refusal(sets.error(), "omm"); !f.empty()) return f;
  } else {
    if (sets.value().empty()) return "omm: read with no element set";
    for (const orb::omm_element_set& set : sets.value()) {
      const orb::sgp4_propagator sgp4(orb::mean_elements(set));
      for (const double minutes : {0.0, 1440.0}) (void)sgp4.state_at(minutes);
    }
  }
  const std::string path = reader_detail::shared_file().hold(data, size);
  if (path.empty()) return {};
  const auto first = orb::read_omm(path, orb::tle_selection::first);
  if (!first.ok()) {
    // The file reader decides the format on the file's first 4 KiB; within them it must read
    // what the text reader read.
    if (sets.ok() && size <= 4096) return "omm: the text reads, the file does not";
    return reader_detail::check_refusal(first.error(), "omm file");
  }
  if (sets.ok() &&
      (first.value().epoch_days_since_1950 != sets.value().front().epoch_days_since_1950 ||
       first.value().elements.mean_motion_rev_day !=
           sets.value().front().elements.mean_motion_rev_day))
    return "omm: the file's first set is not the text's";
  return {};
}

/// An OEM: read; its segments' times increase and its states are finite; the coverage of its
/// whole span checked; a state at its first usable time.
inline std::string check_oem(const std::uint8_t* data, std::size_t size) {
  const std::string path = reader_detail::shared_file().hold(data, size);
  if (path.empty()) return {};
  namespace src = conescan::sources;
  const auto read = src::read_oem(path, {std::nullopt, 4096, 0});
  if (!read.ok()) return reader_detail::check_refusal(read.error(), "oem");
  const src::oem_ephemeris& o = read.value();
  if (o.segments().empty()) return "oem: read with no segment";
  for (const src::oem_segment& s : o.segments()) {
    if (s.t_s.size() != s.samples.size() || s.lines.size() != s.samples.size())
      return "oem: a segment's times, states and lines differ in number";
    for (std::size_t k = 1; k < s.t_s.size(); ++k)
      if (!(s.t_s[k] > s.t_s[k - 1])) return "oem: times do not increase within a segment";
  }
  const auto coverage = o.check_coverage(o.usable_start(), o.usable_stop());
  if (!coverage.ok())
    if (std::string f = reader_detail::check_refusal(coverage.error(), "oem coverage"); !f.empty())
      return f;
  (void)o.state_at(o.usable_start());
  (void)o.state_at(o.usable_stop());
  return {};
}

/// An AEM: read; attitudes at the ends of its usable span; its coverage checked.
inline std::string check_aem(const std::uint8_t* data, std::size_t size) {
  const std::string path = reader_detail::shared_file().hold(data, size);
  if (path.empty()) return {};
  namespace src = conescan::sources;
  const auto read = src::read_aem(path, {std::nullopt, 4096});
  if (!read.ok()) return reader_detail::check_refusal(read.error(), "aem");
  const src::aem_attitude& a = read.value();
  if (a.segments().empty()) return "aem: read with no segment";
  const auto coverage = a.check_coverage(a.usable_start(), a.usable_stop(), 1e-8);
  if (!coverage.ok())
    if (std::string f = reader_detail::check_refusal(coverage.error(), "aem coverage"); !f.empty())
      return f;
  (void)a.attitude_at(a.usable_start());
  (void)a.attitude_at(a.usable_stop());
  return {};
}

/// An attitude table: read; its angles at its first time finite.
inline std::string check_attitude_csv(const std::uint8_t* data, std::size_t size) {
  const std::string path = reader_detail::shared_file().hold(data, size);
  if (path.empty()) return {};
  namespace src = conescan::sources;
  const auto epoch = src::parse_epoch("2020-01-01T00:00:00", src::time_scale::utc);
  const auto read = src::read_attitude_csv(path, {epoch.value(), 4096});
  if (!read.ok()) return reader_detail::check_refusal(read.error(), "attitude-csv");
  const conescan::sources::attitude_table& t = read.value();
  if (t.rows() == 0) return "attitude-csv: read with no row";
  (void)t.check_coverage(0, 1e6);
  return {};
}

/// Telemetry of 1 to 4 heads (the first byte chooses): read; rows counted, times increasing.
inline std::string check_telemetry(const std::uint8_t* data, std::size_t size) {
  const std::size_t heads = size == 0 ? 1 : 1 + data[0] % 4;
  std::istringstream in(size == 0 ? std::string()
                                  : std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
  // Absolute time stamps as the scene gives them (scene_time_stamps), from a fixed epoch.
  namespace src = conescan::sources;
  const src::instant epoch = src::parse_epoch("2020-01-01T00:00:00", src::time_scale::utc).value();
  conescan::calibration::telemetry_time_stamps stamps;
  stamps.from_utc = [epoch](std::string_view utc) -> conescan::checked<double> {
    const auto t = src::parse_epoch(utc, src::time_scale::utc);
    if (!t.ok()) return t.error();
    return src::seconds_between(epoch, t.value());
  };
  stamps.from_gps = [](double week, double seconds) -> conescan::checked<double> {
    return week * 604800 + seconds - 2e9;
  };
  const auto read = conescan::calibration::read_telemetry(in, "fuzz.csv", heads, stamps);
  if (!read.ok()) return reader_detail::check_refusal(read.error(), "telemetry");
  const auto& t = read.value();
  if (t.row_count == 0) return "telemetry: read with no row";
  for (std::size_t i = 1; i < t.observations.size(); ++i)
    if (t.observations[i].sample.t_s < t.observations[i - 1].sample.t_s)
      return "telemetry: times decrease";
  return {};
}

/// A fit's JSON: read; written again, it reads back to the same text from the second writing on
/// (the first may differ in what the reader normalises: "-0" reads back as the integer 0).
inline std::string check_fit_json(const std::uint8_t* data, std::size_t size) {
  namespace cal = conescan::calibration;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto read = cal::read_fit_json(text, "fuzz.json");
  if (!read.ok()) return reader_detail::check_refusal(read.error(), "fit json");
  std::string written = cal::fit_json(cal::fit_outcome(read.value()));
  for (int round = 0; round < 2; ++round) {
    const auto again = cal::read_fit_json(written, "fuzz.json");
    if (!again.ok()) return "fit json: its own text does not read back: " + again.error().text();
    const std::string rewritten = cal::fit_json(cal::fit_outcome(again.value()));
    if (round == 1 && rewritten != written)
      return "fit json: written, read and written again differs";
    written = rewritten;
  }
  return {};
}

/// A summary state: read (the start checked as --merge does); written again, it reads back to
/// the same text.
inline std::string check_summary_state(const std::uint8_t* data, std::size_t size) {
  namespace sc = conescan::scene;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto start = sc::check_summary_state_start(text);
  const auto read = sc::read_summary_state(text);
  if (!start.ok() && read.ok()) return "summary state: read although its start is foreign";
  if (!read.ok()) return reader_detail::check_refusal(read.error(), "summary state");
  const std::string written = sc::summary_state_text(read.value());
  const auto again = sc::read_summary_state(written);
  if (!again.ok()) return "summary state: its own text does not read back: " + again.error().text();
  if (sc::summary_state_text(again.value()) != written)
    return "summary state: written, read and written again differs";
  return {};
}

}  // namespace conescan_fuzz

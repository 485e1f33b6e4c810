#include "sources/oem.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "sources/earth_rotation.hpp"
#include "sources/ephemeris_interpolation.hpp"
#include "sources/kvn.hpp"
#include "sources/kvn_reader.hpp"
#include "text/number_text.hpp"
#include "text/text_lines.hpp"

namespace conescan::sources {

namespace {

constexpr std::string_view header_vocabulary[] = {"CLASSIFICATION", "CREATION_DATE", "ORIGINATOR",
                                                  "MESSAGE_ID"};
constexpr std::string_view header_mandatory[] = {"CREATION_DATE", "ORIGINATOR"};
constexpr std::string_view metadata_vocabulary[] = {
    "OBJECT_NAME",       "OBJECT_ID",   "CENTER_NAME",   "REF_FRAME",
    "REF_FRAME_EPOCH",   "TIME_SYSTEM", "START_TIME",    "USEABLE_START_TIME",
    "USEABLE_STOP_TIME", "STOP_TIME",   "INTERPOLATION", "INTERPOLATION_DEGREE"};
constexpr std::string_view metadata_mandatory[] = {"OBJECT_NAME", "OBJECT_ID",   "CENTER_NAME",
                                                   "REF_FRAME",   "TIME_SYSTEM", "START_TIME",
                                                   "STOP_TIME"};
constexpr std::string_view data_field_names[] = {"X",     "Y",      "Z",      "X_DOT", "Y_DOT",
                                                 "Z_DOT", "X_DDOT", "Y_DDOT", "Z_DDOT"};
constexpr double max_oem_version = 3.0;
constexpr double metres_per_km = 1000.0;

/// A META block, checked: what its segment's data lines and interpolation need.
struct segment_metadata {
  frame_kind frame = frame_kind::inertial;
  std::string ref_frame;
  time_scale scale = time_scale::utc;
  time_span declared{};  ///< USEABLE_START/STOP_TIME, else START/STOP_TIME
  interpolation_method method = oem_default_method;
  int degree = oem_default_degree;
};

checked<segment_metadata> check_metadata(const kvn_block& meta, std::size_t meta_stop_line) {
  if (checked<void> e = meta.require(metadata_mandatory, meta_stop_line); !e.ok()) return e.error();
  segment_metadata m;
  const kvn_entry& center = *meta.find("CENTER_NAME");
  if (text::to_upper(center.value) != "EARTH") return unsupported_value(center, "EARTH only");
  const kvn_entry& frame = *meta.find("REF_FRAME");
  m.frame = classify_frame(frame.value);
  m.ref_frame = frame.value;
  if (m.frame != frame_kind::inertial && m.frame != frame_kind::earth_fixed) {
    const std::string accepted = "EME2000, GCRF, ICRF, TEME, TOD or ITRF*";
    if (text::to_upper(frame.value) == "J2000") {
      return unsupported_value(frame, accepted + "; the J2000 mean equator is EME2000");
    }
    return unsupported_value(frame, accepted);
  }
  const kvn_entry& system = *meta.find("TIME_SYSTEM");
  const std::optional<time_scale> scale = parse_time_system(system.value);
  if (!scale) return unsupported_value(system, "UTC, TAI, TT or GPS");
  m.scale = *scale;
  checked<time_span> span = declared_span(meta, m.scale);
  if (!span.ok()) return span.error();
  m.declared = span.value();
  checked<interpolation_choice> interpolation =
      interpolation_from(meta, "INTERPOLATION", {oem_default_method, oem_default_degree});
  if (!interpolation.ok()) return interpolation.error();
  m.method = interpolation.value().method;
  m.degree = interpolation.value().degree;
  return m;
}

constexpr kvn_layout oem_layout{
    "CCSDS_OEM_VERS", "CCSDS_AEM_VERS",    max_oem_version, header_vocabulary,
    header_mandatory, metadata_vocabulary, false,           true};

/// An OEM's segments: each META block checked, each data line read, turned inertial and kept.
class oem_reader final : public kvn_segments_reader {
 public:
  explicit oem_reader(const oem_read_options& options)
      : kvn_segments_reader(oem_layout),
        options_(options),
        policy_{options.span, options.max_states} {}

  std::vector<oem_segment> take_segments() { return std::move(segments_); }

 private:
  checked<void> open_segment(const kvn_block& meta) override {
    checked<segment_metadata> m = check_metadata(meta, line());
    if (!m.ok()) return m.error();
    metadata_ = std::move(m).value();
    oem_segment s;
    s.meta_line = meta.first_line();
    s.method = metadata_.method;
    s.degree = metadata_.degree;
    s.ref_frame = metadata_.ref_frame;
    s.time_system = metadata_.scale;
    segments_.push_back(std::move(s));
    progress_ = segment_progress{metadata_.declared, {}, {}, 0};
    return success();
  }

  checked<void> on_data_line(std::string_view text) override {
    std::array<std::string_view, 11> fields;
    const std::size_t n = text::split_fields(text, fields.data(), fields.size());
    if (n != 7 && n != 10) {
      return diagnostic::in_file(
          {}, 0,
          "data line with " + std::to_string(n) +
              " fields (expected an epoch and 6 numbers, or 9 with accelerations)");
    }
    const checked<instant> epoch = parse_epoch(fields[0], metadata_.scale);
    if (!epoch.ok()) return epoch.error();
    const instant t = epoch.value();
    std::array<double, 9> x{};
    for (std::size_t i = 1; i < n; ++i) {
      const std::optional<double> v = text::parse_number(fields[i]);
      if (!v) {
        return diagnostic::in_file({}, 0,
                                   "malformed number " + quote(fields[i]) + " (" +
                                       std::string(data_field_names[i - 1]) + ")");
      }
      x[i - 1] = *v;
    }
    oem_segment& s = segments_.back();
    if (checked<void> e = progress_.next_epoch(t, fields[0], s.reference); !e.ok())
      return e.error();
    cartesian_state state{vec3<double>(x[0], x[1], x[2]) * metres_per_km,
                          vec3<double>(x[3], x[4], x[5]) * metres_per_km};
    if (metadata_.frame == frame_kind::earth_fixed) {
      state = inertial_from_itrf(state, t, options_.ut1_minus_utc_s);
    }
    // Either side of a span: the window and the estimate's extra sample, and one to spare.
    return keep_sample(s, t, state, policy_, s.wanted_points() + 2, kept_total_);
  }

  checked<void> close_segment() override {
    return finish_segment(segments_.back(), progress_, interpolate_oem);
  }

  oem_read_options options_;
  keep_policy policy_;
  segment_metadata metadata_;
  segment_progress progress_;
  std::vector<oem_segment> segments_;
  std::size_t kept_total_ = 0;
};

/// The reason an interval's estimate is large, for the refusal's message.
std::string why_inaccurate(const oem_segment& s, double interval_s) {
  const std::string interpolation =
      std::string(to_string(s.method)) + " of degree " + std::to_string(s.degree);
  if (s.samples.size() <= s.wanted_points()) {
    // No sample beyond the window: the estimate compared with one sample fewer (oem.hpp).
    return "the segment's " + std::to_string(s.samples.size()) + " states are too few to check " +
           interpolation + " (the estimate then compares it with one state fewer)";
  }
  return "states " + text::rounded_text(interval_s) + " s apart are too sparse for " +
         interpolation;
}

/// A non-negative figure as a float: beyond float's range +inf (the cast would be undefined).
float as_float(double x) noexcept {
  return x > std::numeric_limits<float>::max() ? std::numeric_limits<float>::infinity()
                                               : static_cast<float>(x);
}

/// error / size as a direction error: 0 for no error, +inf for an error on a zero vector.
double relative(double error, double size) noexcept {
  return error == 0 ? 0 : error / size;
}

interval_error estimate_from(const vec3<double>& dr, const vec3<double>& dv,
                             const cartesian_state& s) noexcept {
  const double position_m = norm(dr), velocity_m_s = norm(dv);
  const double angle =
      std::max(relative(position_m, norm(s.r_m)), relative(velocity_m_s, norm(s.v_m_s)));
  return interval_error{as_float(angle), as_float(position_m), as_float(velocity_m_s)};
}

}  // namespace

interpolated_state interpolate_oem(const oem_segment& s, std::size_t k, double tau) noexcept {
  const std::size_t n = s.samples.size();
  if (n == 1) return {s.samples[0], interval_error{}};
  const std::size_t points = s.points();
  const bool extra = points < n;
  node_array<std::size_t> index;
  const std::size_t count = window_indices(n, k, points + (extra ? 1 : 0), index.data());
  node_array<double> z;
  node_array<vec3<double>> r, v;
  interpolated_state out;
  if (s.uses_derivatives()) {
    for (std::size_t i = 0; i < count; ++i) {
      const cartesian_state& c = s.samples[index[i]];
      z[2 * i] = z[2 * i + 1] = s.t_s[index[i]];
      r[2 * i] = r[2 * i + 1] = c.r_m;
      v[2 * i] = v[2 * i + 1] = c.v_m_s;
    }
    const std::size_t head = 2 * (extra ? points : points - 1);
    const newton_sums p = newton_interpolate(z.data(), r.data(), v.data(), 2 * count, head, tau);
    out.state = extra ? cartesian_state{p.head, p.head_derivative}
                      : cartesian_state{p.full, p.full_derivative};
    out.estimate = estimate_from(p.full - p.head, p.full_derivative - p.head_derivative, out.state);
    return out;
  }
  for (std::size_t i = 0; i < count; ++i) {
    z[i] = s.t_s[index[i]];
    r[i] = s.samples[index[i]].r_m;
    v[i] = s.samples[index[i]].v_m_s;
  }
  const std::size_t head = extra ? points : points - 1;
  const newton_sums pr = newton_interpolate(z.data(), r.data(), nullptr, count, head, tau);
  const newton_sums pv = newton_interpolate(z.data(), v.data(), nullptr, count, head, tau);
  out.state = extra ? cartesian_state{pr.head, pv.head} : cartesian_state{pr.full, pv.full};
  out.estimate = estimate_from(pr.full - pr.head, pv.full - pv.head, out.state);
  return out;
}

checked<oem_ephemeris> read_oem(const std::string& path, const oem_read_options& options) {
  oem_reader reader(options);
  if (checked<void> e = read_kvn(path, reader); !e.ok()) return e.error();
  return oem_ephemeris(path, reader.take_segments());
}

checked<void> oem_ephemeris::check_coverage(const instant& t0, const instant& t1,
                                            std::optional<double> max_angle_rad) const {
  return coverage(t0, t1, max_angle_rad, [&](const worst_interval_error& w, const oem_segment& s) {
    return "interpolation error estimate " + text::rounded_text(w.error.position_m) + " m, " +
           text::rounded_text(w.error.velocity_m_s) + " m/s (" +
           text::rounded_text(w.error.angle_rad * 180 / std::numbers::pi) + " deg) at " +
           format_utc(w.at, 3) + " UTC exceeds the " +
           text::rounded_text(*max_angle_rad * 180 / std::numbers::pi) +
           " deg the angles need: " + why_inaccurate(s, w.interval_s);
  });
}

}  // namespace conescan::sources

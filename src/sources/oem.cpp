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
      if (!options_.eop) {
        state = inertial_from_itrf(state, t, options_.ut1_minus_utc_s);
      } else if (const auto eop = options_.eop->at(t)) {
        state = inertial_from_itrf(state, t, *eop);
      } else {
        return diagnostic::in_file({}, 0,
                                   "no Earth orientation for " + std::string(fields[0]) +
                                       " (ITRF): --eop " + options_.eop->coverage());
      }
    }
    // Either side of a span: the window and the estimate's extra sample, and one to spare.
    return keep_sample(s, t, state, line(), policy_, s.wanted_points() + 2, kept_total_);
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

// Positions and velocities each through `points` samples around interval k (LAGRANGE, or LINEAR
// with 2), with the estimate from one sample more (or fewer, at the segment's end).
interpolated_state interpolate_values(const oem_segment& s, std::size_t k, double tau,
                                      std::size_t points) noexcept {
  const std::size_t n = s.samples.size();
  const bool extra = points < n;
  node_array<std::size_t> index;
  const std::size_t count = window_indices(n, k, points + (extra ? 1 : 0), index.data());
  node_array<double> z;
  node_array<vec3<double>> r, v;
  for (std::size_t i = 0; i < count; ++i) {
    z[i] = s.t_s[index[i]];
    r[i] = s.samples[index[i]].r_m;
    v[i] = s.samples[index[i]].v_m_s;
  }
  const std::size_t head = extra ? points : points - 1;
  const newton_sums pr = newton_interpolate(z.data(), r.data(), nullptr, count, head, tau);
  const newton_sums pv = newton_interpolate(z.data(), v.data(), nullptr, count, head, tau);
  interpolated_state out;
  out.state = extra ? cartesian_state{pr.head, pv.head} : cartesian_state{pr.full, pv.full};
  out.estimate = estimate_from(pr.full - pr.head, pv.full - pv.head, out.state);
  return out;
}

// Why a HERMITE interval's estimate is large when LAGRANGE of the same degree, which does not
// take the sampled velocities as the positions' derivative, is good there: the velocities are
// not the derivative of the positions (SGP4's states, a resampled ephemeris). "" otherwise.
std::string velocities_inconsistent(const oem_segment& s, const worst_interval_error& w,
                                    double max_angle_rad) {
  if (!s.uses_derivatives() || w.interval + 1 >= s.t_s.size()) return {};
  const std::size_t points = std::min(static_cast<std::size_t>(s.degree) + 1, s.samples.size());
  const double middle = 0.5 * (s.t_s[w.interval] + s.t_s[w.interval + 1]);
  const interval_error lagrange = interpolate_values(s, w.interval, middle, points).estimate;
  if (!(lagrange.angle_rad <= max_angle_rad || lagrange.angle_rad * 10 < w.error.angle_rad))
    return {};
  return "the velocities are inconsistent with the positions (HERMITE takes them as the "
         "positions' derivative; LAGRANGE of degree " +
         std::to_string(s.degree) + " on the same states estimates " +
         text::rounded_text(lagrange.angle_rad * 180 / std::numbers::pi) +
         " deg here): give the segment INTERPOLATION = LAGRANGE";
}

}  // namespace

interpolated_state interpolate_oem(const oem_segment& s, std::size_t k, double tau) noexcept {
  const std::size_t n = s.samples.size();
  if (n == 1) return {s.samples[0], interval_error{}};
  const std::size_t points = s.points();
  if (!s.uses_derivatives()) return interpolate_values(s, k, tau, points);
  const bool extra = points < n;
  node_array<std::size_t> index;
  const std::size_t count = window_indices(n, k, points + (extra ? 1 : 0), index.data());
  node_array<double> z;
  node_array<vec3<double>> r, v;
  interpolated_state out;
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

checked<oem_ephemeris> read_oem(const std::string& path, const oem_read_options& options) {
  oem_reader reader(options);
  if (checked<void> e = read_kvn(path, reader); !e.ok()) return e.error();
  return oem_ephemeris(path, reader.take_segments());
}

namespace {

// Where two segments' usable spans overlap within [t0, t1], the later one serves (segment_at):
// the two must agree there to within max_angle_rad (the direction error of interval_error), or a
// file that holds two different orbits for one time would have one of them silently win.
// Compared at every data epoch of either segment in the overlap and at its ends.
checked<void> check_overlaps(const std::vector<oem_segment>& segments, const instant& t0,
                             const instant& t1, double max_angle_rad) {
  for (std::size_t later = 1; later < segments.size(); ++later)
    for (std::size_t earlier = 0; earlier < later; ++earlier) {
      const oem_segment &a = segments[earlier], &b = segments[later];
      const instant from = std::max({t0, a.usable.start, b.usable.start});
      const instant to = std::min({t1, a.usable.stop, b.usable.stop});
      if (to < from) continue;
      std::vector<instant> times{from, to};
      for (const oem_segment* s : {&a, &b})
        for (const double t : s->t_s)
          if (const instant at = add_seconds(s->reference, t); !(at < from) && !(to < at))
            times.push_back(at);
      for (const instant& at : times) {
        const auto state_of = [&](const oem_segment& s) {
          const double tau = seconds_between(s.reference, at);
          return interpolate_oem(s, s.interval_of(tau).value_or(0), tau).state;
        };
        const cartesian_state x = state_of(a), y = state_of(b);
        const interval_error d = estimate_from(x.r_m - y.r_m, x.v_m_s - y.v_m_s, y);
        if (d.angle_rad <= max_angle_rad) continue;
        const auto data = b.interval_of(seconds_between(b.reference, at));
        return diagnostic::in_file(
            {}, data && *data < b.lines.size() ? b.lines[*data] : b.meta_line,
            "the segments of lines " + std::to_string(a.meta_line) + " and " +
                std::to_string(b.meta_line) + " overlap and disagree by " +
                text::rounded_text(d.position_m) + " m, " + text::rounded_text(d.velocity_m_s) +
                " m/s (" + text::rounded_text(d.angle_rad * 180 / std::numbers::pi) + " deg) at " +
                format_utc(at, 3) + " UTC, beyond the " +
                text::rounded_text(max_angle_rad * 180 / std::numbers::pi) +
                " deg the angles need: the later would win there; correct or remove one");
      }
    }
  return success();
}

}  // namespace

checked<void> oem_ephemeris::check_coverage(const instant& t0, const instant& t1,
                                            std::optional<double> max_angle_rad) const {
  if (max_angle_rad && !(t1 < t0))
    if (checked<void> e = check_overlaps(segments(), t0, t1, *max_angle_rad); !e.ok()) {
      e.error().where.file = path();
      return e;
    }
  return coverage(t0, t1, max_angle_rad, [&](const worst_interval_error& w, const oem_segment& s) {
    const std::string velocities = velocities_inconsistent(s, w, *max_angle_rad);
    return "interpolation error estimate " + text::rounded_text(w.error.position_m) + " m, " +
           text::rounded_text(w.error.velocity_m_s) + " m/s (" +
           text::rounded_text(w.error.angle_rad * 180 / std::numbers::pi) + " deg) at " +
           format_utc(w.at, 3) + " UTC, after this line, exceeds the " +
           text::rounded_text(*max_angle_rad * 180 / std::numbers::pi) + " deg the angles need: " +
           (velocities.empty() ? why_inaccurate(s, w.interval_s) : velocities) +
           " (or accept a coarser orbit with --interpolation-tolerance-deg)";
  });
}

}  // namespace conescan::sources

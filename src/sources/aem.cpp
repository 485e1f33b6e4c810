#include "sources/aem.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

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
    "OBJECT_NAME",         "OBJECT_ID",         "CENTER_NAME", "REF_FRAME_A",
    "REF_FRAME_B",         "ATTITUDE_DIR",      "TIME_SYSTEM", "START_TIME",
    "USEABLE_START_TIME",  "USEABLE_STOP_TIME", "STOP_TIME",   "ATTITUDE_TYPE",
    "QUATERNION_TYPE",     "EULER_ROT_SEQ",     "RATE_FRAME",  "INTERPOLATION_METHOD",
    "INTERPOLATION_DEGREE"};
constexpr std::string_view metadata_mandatory[] = {"OBJECT_NAME", "OBJECT_ID",    "REF_FRAME_A",
                                                   "REF_FRAME_B", "TIME_SYSTEM",  "START_TIME",
                                                   "STOP_TIME",   "ATTITUDE_TYPE"};
constexpr double max_aem_version = 2.0;
/// |1 - |Q|| a quaternion may have before it is refused as not a rotation.
constexpr double unit_norm_tolerance = 1e-3;

constexpr kvn_layout aem_layout{"CCSDS_AEM_VERS",
                                "CCSDS_OEM_VERS",
                                max_aem_version,
                                header_vocabulary,
                                header_mandatory,
                                metadata_vocabulary,
                                true,
                                false};

/// A META block, checked: how its data lines become rotations body <- inertial.
struct segment_metadata {
  std::string inertial_frame, body_frame;
  time_scale scale = time_scale::utc;
  time_span declared{};
  interpolation_choice interpolation{aem_default_method, aem_default_degree};
  bool scalar_first = false;
  /// True when the file's quaternion transforms inertial coordinates to body ones (then
  /// q_BI = conj Q, aem.hpp).
  bool inertial_to_body = true;
};

/// Which of REF_FRAME_A/B is inertial and which the body; ATTITUDE_DIR.
checked<void> check_frames(const kvn_block& meta, double version, std::size_t meta_stop_line,
                           segment_metadata& m) {
  const kvn_entry& a = *meta.find("REF_FRAME_A");
  const kvn_entry& b = *meta.find("REF_FRAME_B");
  const frame_kind ka = classify_frame(a.value), kb = classify_frame(b.value);
  const bool a_inertial = ka == frame_kind::inertial && kb == frame_kind::spacecraft_body;
  const bool b_inertial = kb == frame_kind::inertial && ka == frame_kind::spacecraft_body;
  if (!a_inertial && !b_inertial) {
    const kvn_entry& bad =
        (ka == frame_kind::inertial || ka == frame_kind::spacecraft_body) ? b : a;
    return unsupported_value(
        bad,
        "one inertial frame, EME2000, GCRF, ICRF, TEME or TOD, and one spacecraft "
        "body frame, SC_BODY_n");
  }
  m.inertial_frame = text::to_upper(a_inertial ? a.value : b.value);
  m.body_frame = text::to_upper(a_inertial ? b.value : a.value);
  bool a_to_b = true;
  if (const kvn_entry* dir = meta.find("ATTITUDE_DIR")) {
    const std::string d = text::to_upper(dir->value);
    if (d != "A2B" && d != "B2A") return unsupported_value(*dir, "A2B or B2A");
    a_to_b = d == "A2B";
  } else if (version < 2.0) {
    return diagnostic::in_file(
        {}, meta_stop_line,
        "missing mandatory keyword ATTITUDE_DIR in the META block starting at "
        "line " +
            std::to_string(meta.first_line()) + " (AEM version 1)");
  }
  m.inertial_to_body = a_to_b == a_inertial;
  return success();
}

/// ATTITUDE_TYPE QUATERNION and its QUATERNION_TYPE.
checked<void> check_attitude_type(const kvn_block& meta, std::size_t meta_stop_line,
                                  segment_metadata& m) {
  const kvn_entry& type = *meta.find("ATTITUDE_TYPE");
  if (text::to_upper(type.value) != "QUATERNION") return unsupported_value(type, "QUATERNION only");
  const kvn_entry* order = meta.find("QUATERNION_TYPE");
  if (!order) {
    return diagnostic::in_file(
        {}, meta_stop_line,
        "missing mandatory keyword QUATERNION_TYPE in the META block starting at "
        "line " +
            std::to_string(meta.first_line()) + " (ATTITUDE_TYPE QUATERNION)");
  }
  const std::string o = text::to_upper(order->value);
  if (o != "FIRST" && o != "LAST") return unsupported_value(*order, "FIRST or LAST");
  m.scalar_first = o == "FIRST";
  return success();
}

checked<segment_metadata> check_metadata(const kvn_block& meta, double version,
                                         std::size_t meta_stop_line) {
  if (checked<void> e = meta.require(metadata_mandatory, meta_stop_line); !e.ok()) return e.error();
  segment_metadata m;
  if (checked<void> e = check_frames(meta, version, meta_stop_line, m); !e.ok()) return e.error();
  const kvn_entry& system = *meta.find("TIME_SYSTEM");
  const std::optional<time_scale> scale = parse_time_system(system.value);
  if (!scale) return unsupported_value(system, "UTC, TAI, TT or GPS");
  m.scale = *scale;
  const checked<time_span> span = declared_span(meta, m.scale);
  if (!span.ok()) return span.error();
  m.declared = span.value();
  if (checked<void> e = check_attitude_type(meta, meta_stop_line, m); !e.ok()) return e.error();
  const checked<interpolation_choice> interpolation =
      interpolation_from(meta, "INTERPOLATION_METHOD", {aem_default_method, aem_default_degree});
  if (!interpolation.ok()) return interpolation.error();
  m.interpolation = interpolation.value();
  return m;
}

/// An AEM's segments: each META block checked, each quaternion turned into q_BI and kept.
class aem_reader final : public kvn_segments_reader {
 public:
  explicit aem_reader(const aem_read_options& options)
      : kvn_segments_reader(aem_layout), policy_{options.span, options.max_samples} {}

  std::vector<aem_segment> take_segments() { return std::move(segments_); }

 private:
  checked<void> open_segment(const kvn_block& meta) override {
    checked<segment_metadata> m = check_metadata(meta, version(), line());
    if (!m.ok()) return m.error();
    metadata_ = std::move(m).value();
    aem_segment s;
    s.meta_line = meta.first_line();
    s.method = metadata_.interpolation.method;
    s.degree = metadata_.interpolation.degree;
    s.sampled_derivatives = false;
    s.inertial_frame = metadata_.inertial_frame;
    s.body_frame = metadata_.body_frame;
    s.time_system = metadata_.scale;
    segments_.push_back(std::move(s));
    progress_ = segment_progress{metadata_.declared, {}, {}, 0};
    return success();
  }

  checked<void> on_data_line(std::string_view text) override {
    std::array<std::string_view, 6> fields;
    const std::size_t n = text::split_fields(text, fields.data(), fields.size());
    if (n != 5) {
      return diagnostic::in_file({}, 0,
                                 "data line with " + std::to_string(n) +
                                     " fields (expected an epoch and the 4 quaternion components)");
    }
    const checked<instant> epoch = parse_epoch(fields[0], metadata_.scale);
    if (!epoch.ok()) return epoch.error();
    std::array<double, 4> c{};
    for (std::size_t i = 0; i < 4; ++i) {
      const std::optional<double> v = text::parse_number(fields[i + 1]);
      if (!v) {
        const bool scalar = metadata_.scalar_first ? i == 0 : i == 3;
        const std::size_t vector_index = metadata_.scalar_first ? i : i + 1;
        return diagnostic::in_file(
            {}, 0,
            "malformed number " + quote(fields[i + 1]) + " (" +
                (scalar ? std::string("QC") : "Q" + std::to_string(vector_index)) + ")");
      }
      c[i] = *v;
    }
    const quaternion q = metadata_.scalar_first ? quaternion{c[0], c[1], c[2], c[3]}
                                                : quaternion{c[3], c[0], c[1], c[2]};
    const double length = norm(q);
    if (!(std::abs(length - 1) <= unit_norm_tolerance)) {
      return diagnostic::in_file({}, 0,
                                 "quaternion of norm " + text::rounded_text(length) +
                                     " (expected 1 within " +
                                     text::rounded_text(unit_norm_tolerance) + ")");
    }
    quaternion q_bi = scaled(metadata_.inertial_to_body ? conjugate(q) : q, 1 / length);
    aem_segment& s = segments_.back();
    if (!s.samples.empty() && dot(q_bi, s.samples.back()) < 0) q_bi = scaled(q_bi, -1);
    if (checked<void> e = progress_.next_epoch(epoch.value(), fields[0], s.reference); !e.ok())
      return e;
    return keep_sample(s, epoch.value(), q_bi, policy_, s.wanted_points() + 2, kept_total_);
  }

  checked<void> close_segment() override {
    return finish_segment(segments_.back(), progress_, interpolate_aem);
  }

  keep_policy policy_;
  segment_metadata metadata_;
  segment_progress progress_;
  std::vector<aem_segment> segments_;
  std::size_t kept_total_ = 0;
};

/// The rotation vector of `q` relative to `reference`, taken among its 2 pi equivalents as the
/// one nearest `neighbour` (the previous sample's, outward from the reference): a rotation
/// about a fixed axis past pi then stays continuous.
vec3<double> unwrapped_rotation_vector(const quaternion& q, const quaternion& reference,
                                       const vec3<double>& neighbour) noexcept {
  const vec3<double> phi = rotation_vector(q * conjugate(reference));
  const double angle = norm(phi);
  if (angle == 0) return phi;
  const vec3<double> turn = phi * (2 * std::numbers::pi / angle);
  vec3<double> best = phi;
  for (const vec3<double>& candidate : {phi + turn, phi - turn}) {
    if (norm(candidate - neighbour) < norm(best - neighbour)) best = candidate;
  }
  return best;
}

}  // namespace

interpolated_attitude interpolate_aem(const aem_segment& s, std::size_t k, double tau) noexcept {
  const std::size_t n = s.samples.size();
  if (n == 1) return {s.samples[0], interval_error{}};
  const std::size_t points = s.points();
  const bool extra = points < n;
  node_array<std::size_t> index;
  const std::size_t count = window_indices(n, k, points + (extra ? 1 : 0), index.data());
  // Rotation vectors relative to sample k, in time order outward from it (unwrapping), then in
  // the window's nearest-first order for the Newton sums.
  const quaternion& reference = s.samples[k];
  const std::size_t lo = *std::min_element(index.begin(), index.begin() + count);
  const std::size_t hi = *std::max_element(index.begin(), index.begin() + count);
  node_array<vec3<double>> by_time;  // by_time[j - lo]
  by_time[k - lo] = vec3<double>(0.0);
  for (std::size_t j = k + 1; j <= hi; ++j) {
    by_time[j - lo] = unwrapped_rotation_vector(s.samples[j], reference, by_time[j - 1 - lo]);
  }
  for (std::size_t j = k; j-- > lo;) {
    by_time[j - lo] = unwrapped_rotation_vector(s.samples[j], reference, by_time[j + 1 - lo]);
  }
  node_array<double> z;
  node_array<vec3<double>> phi;
  for (std::size_t i = 0; i < count; ++i) {
    z[i] = s.t_s[index[i]];
    phi[i] = by_time[index[i] - lo];
  }
  const std::size_t head = extra ? points : points - 1;
  const newton_sums p = newton_interpolate(z.data(), phi.data(), nullptr, count, head, tau);
  const quaternion full = quaternion_from_rotation_vector(p.full) * reference;
  const quaternion with_head = quaternion_from_rotation_vector(p.head) * reference;
  interpolated_attitude out;
  out.body_from_inertial = extra ? with_head : full;
  out.estimate.angle_rad = static_cast<float>(angle_between(full, with_head));
  return out;
}

checked<aem_attitude> read_aem(const std::string& path, const aem_read_options& options) {
  aem_reader reader(options);
  if (checked<void> e = read_kvn(path, reader); !e.ok()) return e.error();
  return aem_attitude(path, reader.take_segments());
}

checked<void> aem_attitude::check_coverage(const instant& t0, const instant& t1,
                                           std::optional<double> max_angle_rad) const {
  return coverage(t0, t1, max_angle_rad, [&](const worst_interval_error& w, const aem_segment&) {
    return "attitude interpolation error estimate " +
           text::rounded_text(w.error.angle_rad * 180 / std::numbers::pi) + " deg at " +
           format_utc(w.at, 3) + " UTC exceeds the " +
           text::rounded_text(*max_angle_rad * 180 / std::numbers::pi) +
           " deg the angles need (samples " + text::rounded_text(w.interval_s) + " s apart there)";
  });
}

}  // namespace conescan::sources

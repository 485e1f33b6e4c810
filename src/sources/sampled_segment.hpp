// What an OEM and an AEM have in common once read: segments of time-tagged samples, each with its
// usable span and interpolation, the choice of segment for a time, the coverage of a span, the
// bound on the samples kept, and the interpolation error estimated on every interval.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sources/kvn.hpp"
#include "sources/time_scales.hpp"
#include "text/diagnostic.hpp"
#include "text/number_text.hpp"
#include "text/text_lines.hpp"

namespace conescan::sources {

/// The interpolation error estimated on one interval between samples, at its midpoint, as the
/// difference between the interpolant used there and the one with the next sample added
/// (ephemeris_interpolation.hpp). `angle_rad` is the direction error it implies: OEM
/// max(position / radius, velocity / speed), AEM the rotation angle.
struct interval_error {
  float angle_rad = 0;
  float position_m = 0;    ///< OEM only
  float velocity_m_s = 0;  ///< OEM only
};

/// The worst estimate over a span, where it is, and in which segment.
struct worst_interval_error {
  interval_error error{};
  instant at{};
  std::size_t segment_line = 0;  ///< META_START line of its segment (0: no interval in the span)
  std::size_t data_line = 0;     ///< the data line that starts the interval
  std::size_t interval = 0;      ///< the interval's index k in its segment: [t_s[k], t_s[k + 1]]
  double interval_s = 0;         ///< the interval's length
};

/// One segment: samples at t_s[k] seconds from `reference`, strictly increasing.
template <class Sample>
struct sampled_segment {
  std::size_t meta_line = 0;  ///< line of its META_START
  interpolation_method method = interpolation_method::lagrange;
  int degree = 1;
  /// false when the samples carry no derivative (AEM quaternions): HERMITE is then LAGRANGE.
  bool sampled_derivatives = true;
  instant reference{};  ///< the segment's first data epoch
  time_span usable{};   ///< USEABLE_START/STOP (else START/STOP) within the data's span
  std::vector<double> t_s;
  std::vector<Sample> samples;
  std::vector<std::size_t> lines;      ///< the file's line of each sample (for messages)
  std::vector<interval_error> errors;  ///< errors[k]: interval [t_s[k], t_s[k + 1]]

  /// How many samples the interpolant takes by the file's method and degree: LAGRANGE
  /// degree + 1; HERMITE ceil((degree + 1) / 2), each with its derivative, for a polynomial of
  /// degree >= the file's (without sampled derivatives, as LAGRANGE); LINEAR 2.
  std::size_t wanted_points() const noexcept {
    const auto d = static_cast<std::size_t>(degree);
    if (method == interpolation_method::linear) return 2;
    return uses_derivatives() ? (d + 2) / 2 : d + 1;
  }

  bool uses_derivatives() const noexcept {
    return method == interpolation_method::hermite && sampled_derivatives;
  }

  /// wanted_points, capped by the samples the segment has.
  std::size_t points() const noexcept { return std::min(wanted_points(), samples.size()); }

  /// k with t_s[k] <= tau <= t_s[k + 1] (k = 0 for a one-sample segment); nullopt outside the
  /// stored samples.
  std::optional<std::size_t> interval_of(double tau) const noexcept {
    if (t_s.empty() || tau < t_s.front() || tau > t_s.back()) return std::nullopt;
    const auto above = std::upper_bound(t_s.begin(), t_s.end(), tau);
    const auto k = static_cast<std::size_t>(above - t_s.begin());
    return k == 0 ? 0 : std::min(k - 1, t_s.size() >= 2 ? t_s.size() - 2 : 0);
  }
};

/// The segment for time t: the last (in file order) whose usable span holds it, since a later
/// segment supersedes an earlier one (after a manoeuvre); nullptr if none.
template <class Segment>
const Segment* segment_at(const std::vector<Segment>& segments, const instant& t) noexcept {
  for (auto s = segments.rbegin(); s != segments.rend(); ++s) {
    if (!(t < s->usable.start) && !(s->usable.stop < t)) return &*s;
  }
  return nullptr;
}

/// "START to STOP (line N), ..." of the segments, for messages.
template <class Segment>
std::string describe_spans(const std::vector<Segment>& segments) {
  std::string text;
  for (const Segment& s : segments) {
    if (!text.empty()) text += ", ";
    text += format_utc(s.usable.start, 3) + " to " + format_utc(s.usable.stop, 3) +
            " (segment at line " + std::to_string(s.meta_line) + ")";
  }
  return text + " UTC";
}

/// nullopt when the union of the segments' usable spans holds all of `span`, else an error
/// naming the first time it misses.
template <class Segment>
checked<void> check_span_covered(const std::vector<Segment>& segments, const time_span& span) {
  instant covered_to = span.start;  // [span.start, covered_to] is covered once found
  for (;;) {
    const Segment* reach = nullptr;  // holds covered_to, reaches furthest
    for (const Segment& s : segments) {
      const bool holds = !(covered_to < s.usable.start) && !(s.usable.stop < covered_to);
      if (holds && (!reach || reach->usable.stop < s.usable.stop)) reach = &s;
    }
    if (reach && !(reach->usable.stop < span.stop)) return success();
    if (!reach || !(covered_to < reach->usable.stop)) {  // no segment, or none goes further
      return diagnostic::in_file(
          {}, 0,
          std::string(reach ? "no usable data just after " : "no usable data at ") +
              format_utc(covered_to, 3) + " UTC; usable: " + describe_spans(segments));
    }
    covered_to = reach->usable.stop;
  }
}

/// The worst interval error estimate over the intervals that meet `span` in each segment's
/// usable span (a segment superseded there by a later one still counts: conservative).
template <class Segment>
worst_interval_error worst_error_over(const std::vector<Segment>& segments, const time_span& span) {
  worst_interval_error worst;
  for (const Segment& s : segments) {
    const instant from = std::max(span.start, s.usable.start);
    const instant to = std::min(span.stop, s.usable.stop);
    if (to < from || s.errors.empty()) continue;
    const double a = seconds_between(s.reference, from), b = seconds_between(s.reference, to);
    const std::size_t first = s.interval_of(a).value_or(0);
    const std::size_t last =
        std::min(s.interval_of(b).value_or(s.errors.size() - 1), s.errors.size() - 1);
    for (std::size_t k = first; k <= last; ++k) {
      if (worst.segment_line == 0 || worst.error.angle_rad < s.errors[k].angle_rad) {
        worst.error = s.errors[k];
        worst.at = add_seconds(s.reference, 0.5 * (s.t_s[k] + s.t_s[k + 1]));
        worst.segment_line = s.meta_line;
        worst.data_line = k < s.lines.size() ? s.lines[k] : 0;
        worst.interval = k;
        worst.interval_s = s.t_s[k + 1] - s.t_s[k];
      }
    }
  }
  return worst;
}

/// nullopt when the samples kept (read_options::span) hold the part of `span` each segment
/// serves; else an error naming the span the file was read for.
template <class Segment>
checked<void> check_samples_kept(const std::vector<Segment>& segments, const time_span& span) {
  for (const Segment& s : segments) {
    const instant from = std::max(span.start, s.usable.start);
    const instant to = std::min(span.stop, s.usable.stop);
    if (to < from) continue;
    if (!s.interval_of(seconds_between(s.reference, from)) ||
        !s.interval_of(seconds_between(s.reference, to))) {
      return diagnostic::in_file({}, s.meta_line,
                                 "the file was read for a shorter span: " + format_utc(from, 3) +
                                     " to " + format_utc(to, 3) + " UTC is not in the states kept");
    }
  }
  return success();
}

/// Before any row: [t0, t1] ordered, covered by usable spans, and within the samples kept.
template <class Segment>
checked<void> check_sampled_coverage(const std::vector<Segment>& segments, const time_span& span) {
  if (span.stop < span.start) {
    return diagnostic::in_file({}, 0,
                               "the span ends (" + format_utc(span.stop, 3) +
                                   ") before it starts (" + format_utc(span.start, 3) + ")");
  }
  if (checked<void> e = check_span_covered(segments, span); !e.ok()) return e.error();
  return check_samples_kept(segments, span);
}

/// The sample interpolated at t by `interpolate(segment, k, tau)`, in the segment that serves t
/// (segment_at); an error outside every usable span or the samples kept.
template <class Segment, class Interpolate>
auto sample_at(const std::vector<Segment>& segments, const instant& t,
               const Interpolate& interpolate)
    -> checked<decltype(interpolate(segments.front(), std::size_t{0}, 0.0))> {
  const Segment* s = segment_at(segments, t);
  if (!s) {
    return diagnostic::in_file(
        {}, 0,
        "no usable data at " + format_utc(t, 3) + " UTC; usable: " + describe_spans(segments));
  }
  const double tau = seconds_between(s->reference, t);
  const std::optional<std::size_t> k = s->interval_of(tau);
  if (!k) {
    return diagnostic::in_file({}, s->meta_line,
                               format_utc(t, 3) +
                                   " UTC is not in the states kept (the file was read "
                                   "for a shorter span)");
  }
  return interpolate(*s, *k, tau);
}

/// How a reader keeps samples: all of them, or only those that interpolation over `span` needs
/// (those inside it and `margin` either side of it, per segment) — and at most `max_samples` in
/// all, so that a file of any size is read in bounded memory.
struct keep_policy {
  std::optional<time_span> span;
  std::size_t max_samples = 0;
};

/// Adds one sample, read at line `line`, to a segment under a keep_policy; `kept_total` counts
/// the samples kept in all segments. An error names the limit when it is exceeded.
template <class Sample>
checked<void> keep_sample(sampled_segment<Sample>& s, const instant& epoch, const Sample& sample,
                          std::size_t line, const keep_policy& policy, std::size_t margin,
                          std::size_t& kept_total) {
  const double t = seconds_between(s.reference, epoch);
  if (policy.span) {
    if (epoch < policy.span->start) {
      // Before the span: keep the last `margin` only (trimmed in batches: amortised O(1)).
      if (s.t_s.size() >= 2 * margin) {
        const auto drop = static_cast<std::ptrdiff_t>(s.t_s.size() - margin + 1);
        s.t_s.erase(s.t_s.begin(), s.t_s.begin() + drop);
        s.samples.erase(s.samples.begin(), s.samples.begin() + drop);
        s.lines.erase(s.lines.begin(), s.lines.begin() + drop);
        kept_total -= static_cast<std::size_t>(drop);
      }
    } else if (policy.span->stop < epoch) {
      // After the span: keep the first `margin` (the samples are in time order, so those after
      // the span are the last ones kept: count at most `margin` of them from the back).
      const double stop_s = seconds_between(s.reference, policy.span->stop);
      std::size_t after = 0;
      for (auto x = s.t_s.rbegin(); x != s.t_s.rend() && *x > stop_s && after < margin; ++x) {
        ++after;
      }
      if (after >= margin) return success();
    }
  }
  if (kept_total >= policy.max_samples) {
    return diagnostic::in_file(
        {}, 0,
        "more than " + std::to_string(policy.max_samples) +
            " data lines to keep (the limit that bounds memory): give a shorter "
            "span, or resample the file");
  }
  s.t_s.push_back(t);
  s.samples.push_back(sample);
  s.lines.push_back(line);
  ++kept_total;
  return success();
}

/// One segment's data lines as they are read (OEM and AEM alike): the span its META block
/// declared, the span of its epochs, and how many lines it had.
struct segment_progress {
  time_span declared{};
  instant first{}, last{};
  std::size_t lines = 0;

  /// Takes the epoch of the next data line (its text for the message): refused unless after the
  /// previous line's. The first epoch becomes the segment's `reference`.
  checked<void> next_epoch(const instant& t, std::string_view text, instant& reference) {
    if (lines > 0 && !(last < t)) {
      return diagnostic::in_file(
          {}, 0,
          "epoch " + std::string(text) +
              (t == last ? " repeats the previous line's" : " is before the previous line's") +
              " (epochs must increase within a segment)");
    }
    if (lines == 0) first = reference = t;
    last = t;
    ++lines;
    return success();
  }
};

/// The end of a segment: its usable span (the declared one within the data's), and the error
/// estimate of every interval, `interpolate(s, k, tau).estimate` at its midpoint.
template <class Segment, class Interpolate>
checked<void> finish_segment(Segment& s, const segment_progress& p,
                             const Interpolate& interpolate) {
  if (p.lines == 0) return diagnostic::in_file({}, s.meta_line, "the segment has no data lines");
  s.usable.start = std::max(p.declared.start, p.first);
  s.usable.stop = std::min(p.declared.stop, p.last);
  if (s.usable.stop < s.usable.start) {
    return diagnostic::in_file({}, s.meta_line,
                               "the segment's usable span (" + format_utc(p.declared.start, 3) +
                                   " to " + format_utc(p.declared.stop, 3) +
                                   " UTC) misses its data (" + format_utc(p.first, 3) + " to " +
                                   format_utc(p.last, 3) + ")");
  }
  s.errors.resize(s.t_s.size() > 1 ? s.t_s.size() - 1 : 0);
  for (std::size_t k = 0; k < s.errors.size(); ++k) {
    s.errors[k] = interpolate(s, k, 0.5 * (s.t_s[k] + s.t_s[k + 1])).estimate;
  }
  return success();
}

/// A file of sampled segments once read: what an OEM and an AEM show alike. `Interpolate` is
/// the file type's interpolate(segment, k, tau) (oem.hpp, aem.hpp).
template <class Segment, auto Interpolate>
class sampled_file {
 public:
  using value_type = decltype(Interpolate(std::declval<const Segment&>(), std::size_t{0}, 0.0));

  const std::string& path() const noexcept { return path_; }
  const std::vector<Segment>& segments() const noexcept { return segments_; }

  /// The earliest and latest usable times of all segments (there may be gaps between them:
  /// check_coverage finds them).
  instant usable_start() const noexcept {
    instant t = segments_.front().usable.start;
    for (const Segment& s : segments_) t = std::min(t, s.usable.start);
    return t;
  }
  instant usable_stop() const noexcept {
    instant t = segments_.front().usable.stop;
    for (const Segment& s : segments_) t = std::max(t, s.usable.stop);
    return t;
  }

  /// The worst interval error estimate over [t0, t1] (segment_line 0: no interval there).
  worst_interval_error worst_error(const instant& t0, const instant& t1) const {
    return worst_error_over(segments_, time_span{t0, t1});
  }

 protected:
  sampled_file() = default;
  sampled_file(std::string path, std::vector<Segment> segments)
      : path_(std::move(path)), segments_(std::move(segments)) {}

  /// The interpolated value at t from the segment that serves it (segment_at).
  checked<value_type> value_at(const instant& t) const {
    checked<value_type> out = sample_at(segments_, t, Interpolate);
    if (!out.ok()) out.error().where.file = path_;
    return out;
  }

  /// check_sampled_coverage, then, given max_angle_rad, the worst estimate against it:
  /// `describe(worst, segment)` words the refusal.
  template <class Describe>
  checked<void> coverage(const instant& t0, const instant& t1, std::optional<double> max_angle_rad,
                         const Describe& describe) const {
    checked<void> e = check_sampled_coverage(segments_, time_span{t0, t1});
    if (e.ok() && max_angle_rad) {
      const worst_interval_error w = worst_error(t0, t1);
      if (w.segment_line != 0 && !(w.error.angle_rad <= *max_angle_rad)) {
        const Segment& s = *std::find_if(segments_.begin(), segments_.end(), [&](const Segment& x) {
          return x.meta_line == w.segment_line;
        });
        e = diagnostic::in_file({}, w.data_line != 0 ? w.data_line : w.segment_line,
                                describe(w, s));
      }
    }
    if (!e.ok()) e.error().where.file = path_;
    return e;
  }

 private:
  std::string path_;
  std::vector<Segment> segments_;
};

}  // namespace conescan::sources

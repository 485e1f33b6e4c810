#include "calibration/passes.hpp"

#include <array>
#include <limits>

namespace conescan::calibration::passes {

namespace {

constexpr std::size_t head_size = head_parameter_count;
constexpr std::size_t earth_size = earth_parameter_count;
constexpr std::size_t bias_in_offset = static_cast<std::size_t>(head_parameter::bias_in);
constexpr std::size_t bias_out_offset = static_cast<std::size_t>(head_parameter::bias_out);

/// The two whitened residuals of one measurement at the given blocks, for double or Jets.
template <class T>
bool whitened(const setup& s, const observation& o, const T* head, const T* earth, T* r) {
  using std::isfinite;
  const std::size_t k = o.sample.head;
  const predicted_measurement<T> p = s.model->predict(
      o.sample, head_geometry_of(head, s.layout->forms[k]), earth_geometry_of(earth));
  if (p.state != status::ok) return false;
  const predicted_measurement<T> biased =
      with_crossing_biases(p, head[bias_in_offset], head[bias_out_offset]);
  r[0] = (o.chord_deg - biased.chord_deg) / s.sigma[k].chord_deg;
  r[1] = wrapped_difference_deg(T(o.phase_deg - biased.phase_deg)) / s.sigma[k].phase_deg;
  return isfinite(r[0]) && isfinite(r[1]);
}

/// Huber's rho(s) and its weight rho'(s) (no loss: s and 1).
struct robust_value {
  double rho;
  double weight;
};
robust_value huber(double s, double a) {
  if (a <= 0 || s <= a * a) return {s, 1.0};
  const double root = std::sqrt(s);
  return {2 * a * root - a * a, a / root};
}

/// The coordinate of each of a measurement's 12 slots (its head's 7, the Earth's 5), -1 if held.
std::array<std::ptrdiff_t, jet_size> local_coordinates(const setup& s,
                                                       const telemetry_sample& sample) {
  std::array<std::ptrdiff_t, jet_size> c{};
  const std::size_t head_base = estimation_layout::head_block(sample.head);
  for (std::size_t j = 0; j < head_size; ++j)
    c[j] = s.layout->coordinate(head_base + j, sample.t_s);
  for (std::size_t j = 0; j < earth_size; ++j)
    c[head_size + j] = s.layout->coordinate(s.layout->earth_block() + j, sample.t_s);
  return c;
}

/// Which part of the normal equations each part of a pass adds up.
normal_equations empty_sums(const setup& s, Eigen::Index p) {
  normal_equations n;
  n.h = Eigen::MatrixXd::Zero(p, p);
  n.g = Eigen::VectorXd::Zero(p);
  n.count.assign(s.layout->head_count, 0);
  n.sum_squares_deg2.assign(s.layout->head_count, 0.0);
  return n;
}

void add_measurement(const setup& s, const observation& o, const Eigen::VectorXd& x,
                     normal_equations& n) {
  const std::array<std::ptrdiff_t, jet_size> c = local_coordinates(s, o.sample);
  const std::size_t head_base = estimation_layout::head_block(o.sample.head);
  parameter_jet head[head_size], earth[earth_size], r[2];
  for (std::size_t j = 0; j < jet_size; ++j) {
    const std::size_t slot =
        j < head_size ? head_base + j : s.layout->earth_block() + j - head_size;
    // A held parameter carries no derivative: a model may then run on Jets of the free ones'
    // slots alone (the sensor physics' chain does: scene_model.hpp, compact_physics_crossings).
    (j < head_size ? head[j] : earth[j - head_size]) =
        c[j] >= 0 ? parameter_jet(x(c[j]), static_cast<int>(j)) : parameter_jet(s.slots[slot]);
  }
  if (!whitened(s, o, head, earth, r)) {
    ++n.failed;
    return;
  }
  const double sq = r[0].a * r[0].a + r[1].a * r[1].a;
  const robust_value loss = huber(sq, s.huber_scale);
  n.cost += loss.rho / 2;
  n.chi2 += loss.weight * loss.weight * sq;
  const std::size_t k = o.sample.head;
  ++n.count[k];
  const double chord_deg = r[0].a * s.sigma[k].chord_deg, phase_deg = r[1].a * s.sigma[k].phase_deg;
  n.sum_squares_deg2[k] += chord_deg * chord_deg + phase_deg * phase_deg;
  for (std::size_t a = 0; a < jet_size; ++a) {
    if (c[a] < 0) continue;
    const auto ia = static_cast<int>(a);
    n.g(c[a]) += loss.weight * (r[0].v[ia] * r[0].a + r[1].v[ia] * r[1].a);
    for (std::size_t b = 0; b < jet_size; ++b) {
      if (c[b] < 0) continue;
      const auto ib = static_cast<int>(b);
      n.h(c[a], c[b]) += loss.weight * (r[0].v[ia] * r[0].v[ib] + r[1].v[ia] * r[1].v[ib]);
    }
  }
}

}  // namespace

log_histogram::log_histogram() : counts_(bins, 0) {}

void log_histogram::add(double value) {
  ++counts_[bin_of(std::abs(value))];
  ++total_;
}

void log_histogram::merge(const log_histogram& other) {
  for (std::size_t i = 0; i < bins; ++i) counts_[i] += other.counts_[i];
  total_ += other.total_;
}

double log_histogram::median() const {
  if (total_ == 0) return std::numeric_limits<double>::quiet_NaN();
  const double target = static_cast<double>(total_) / 2;
  double below = 0;
  for (std::size_t i = 0; i < bins; ++i) {
    const double here = static_cast<double>(counts_[i]);
    if (below + here >= target) return lower(i) + (upper(i) - lower(i)) * (target - below) / here;
    below += here;
  }
  return upper(bins - 1);
}

std::size_t log_histogram::bin_of(double a) {
  if (!(a > 0)) return 0;  // 0 and NaN
  if (!(a <= std::numeric_limits<double>::max())) return bins - 1;
  int exponent = 0;
  const double mantissa = std::frexp(a, &exponent);  // a = mantissa 2^exponent, [0.5, 1)
  const int octave = exponent - 1 - lowest_exponent;
  if (octave < 0) return 0;
  if (octave >= octaves) return bins - 1;
  const auto step = static_cast<int>((2 * mantissa - 1) * per_octave);
  return static_cast<std::size_t>(octave * per_octave + std::min(step, per_octave - 1));
}

double log_histogram::lower(std::size_t bin) {
  const int octave = static_cast<int>(bin) / per_octave, step = static_cast<int>(bin) % per_octave;
  return std::ldexp(1.0 + static_cast<double>(step) / per_octave, octave + lowest_exponent);
}

double log_histogram::upper(std::size_t bin) {
  const int octave = static_cast<int>(bin) / per_octave, step = static_cast<int>(bin) % per_octave;
  return std::ldexp(1.0 + static_cast<double>(step + 1) / per_octave, octave + lowest_exponent);
}

void slots_at(const setup& s, const Eigen::VectorXd& x, const telemetry_sample& sample,
              double* head_block, double* earth_block) {
  const std::array<std::ptrdiff_t, jet_size> c = local_coordinates(s, sample);
  const std::size_t head_base = estimation_layout::head_block(sample.head);
  for (std::size_t j = 0; j < head_size; ++j)
    head_block[j] = c[j] >= 0 ? x(c[j]) : s.slots[head_base + j];
  for (std::size_t j = 0; j < earth_size; ++j)
    earth_block[j] =
        c[head_size + j] >= 0 ? x(c[head_size + j]) : s.slots[s.layout->earth_block() + j];
}

bool residuals_deg(const setup& s, const observation& o, const double* head_block,
                   const double* earth_block, double& chord_deg, double& phase_deg) {
  double r[2];
  if (!whitened(s, o, head_block, earth_block, r)) return false;
  chord_deg = r[0] * s.sigma[o.sample.head].chord_deg;
  phase_deg = r[1] * s.sigma[o.sample.head].phase_deg;
  return true;
}

normal_equations linearize(const setup& s, const inclusion& fitted, const Eigen::VectorXd& x) {
  const auto p = static_cast<Eigen::Index>(s.layout->coordinates.size());
  // Parts independent of the threads: the same sums, to the bit, on any number of them.
  const std::size_t part_count = text::reduction_part_count(s.observations.size());
  std::vector<normal_equations> parts(part_count, empty_sums(s, p));
  parallel_parts(s.observations.size(), s.threads, part_count,
                 [&](std::size_t begin, std::size_t end, std::size_t part) {
                   for (std::size_t i = begin; i < end; ++i)
                     if (fitted[i] != 0) add_measurement(s, s.observations[i], x, parts[part]);
                 });
  normal_equations total = std::move(parts[0]);
  for (std::size_t part = 1; part < parts.size(); ++part) {
    const normal_equations& n = parts[part];
    total.h += n.h;
    total.g += n.g;
    total.cost += n.cost;
    total.chi2 += n.chi2;
    total.failed += n.failed;
    for (std::size_t k = 0; k < total.count.size(); ++k) {
      total.count[k] += n.count[k];
      total.sum_squares_deg2[k] += n.sum_squares_deg2[k];
    }
  }
  return total;
}

namespace {

// The residuals at x of every observation whose inclusion is `included` (and whose forward model
// holds there), in `parts` parts: visit(part, i, observation, chord_deg, phase_deg). Parts see
// disjoint observations.
template <class Visit>
void for_each_residual(const setup& s, const inclusion& fitted, bool included,
                       const Eigen::VectorXd& x, std::size_t parts, Visit&& visit) {
  parallel_parts(s.observations.size(), s.threads, parts,
                 [&](std::size_t begin, std::size_t end, std::size_t part) {
                   double head[head_size], earth[earth_size], chord = 0, phase = 0;
                   for (std::size_t i = begin; i < end; ++i) {
                     if ((fitted[i] != 0) != included) continue;
                     const observation& o = s.observations[i];
                     slots_at(s, x, o.sample, head, earth);
                     if (!residuals_deg(s, o, head, earth, chord, phase)) continue;
                     visit(part, i, o, chord, phase);
                   }
                 });
}

}  // namespace

std::vector<double> median_abs_residual(const setup& s, const inclusion& fitted,
                                        const Eigen::VectorXd& x,
                                        const std::vector<measurement_sigma>& unit,
                                        std::size_t minimum_count) {
  const std::size_t heads = s.layout->head_count;
  // One histogram a thread (256 KiB each): counts, whose sum does not depend on the parts.
  const std::size_t part_count = text::parallel_part_count(s.observations.size(), s.threads);
  std::vector<std::vector<log_histogram>> parts(part_count, std::vector<log_histogram>(heads));
  for_each_residual(
      s, fitted, true, x, part_count,
      [&](std::size_t part, std::size_t, const observation& o, double chord, double phase) {
        const std::size_t k = o.sample.head;
        parts[part][k].add(chord / unit[k].chord_deg);
        parts[part][k].add(phase / unit[k].phase_deg);
      });
  std::vector<double> medians;
  for (std::size_t k = 0; k < heads; ++k) {
    for (std::size_t part = 1; part < parts.size(); ++part) parts[0][k].merge(parts[part][k]);
    medians.push_back(parts[0][k].total() < 2 * minimum_count
                          ? std::numeric_limits<double>::quiet_NaN()
                          : parts[0][k].median());
  }
  return medians;
}

std::size_t readmit(const setup& s, inclusion& fitted, const Eigen::VectorXd& x) {
  const std::size_t part_count = text::parallel_part_count(s.observations.size(), s.threads);
  std::vector<std::size_t> back(part_count, 0);
  for_each_residual(s, fitted, false, x, part_count,
                    [&](std::size_t part, std::size_t i, const observation&, double, double) {
                      fitted[i] = 1;  // parts write disjoint elements
                      ++back[part];
                    });
  std::size_t total = 0;
  for (std::size_t n : back) total += n;
  return total;
}

namespace {

bool worse(const outlier& a, const outlier& b) {
  if (a.normalised != b.normalised) return a.normalised > b.normalised;
  return a.sample.row != b.sample.row ? a.sample.row < b.sample.row : a.sample.head < b.sample.head;
}

}  // namespace

outlier_scan find_outliers(const setup& s, const inclusion& fitted, const Eigen::VectorXd& x,
                           double chi2_dof, double threshold, std::size_t listed) {
  const std::size_t heads = s.layout->head_count;
  outlier_scan empty;
  empty.chord.resize(heads);
  empty.phase.resize(heads);
  const std::size_t part_count = text::reduction_part_count(s.observations.size());
  std::vector<outlier_scan> parts(part_count, empty);
  for_each_residual(
      s, fitted, true, x, part_count,
      [&](std::size_t part, std::size_t, const observation& o, double chord, double phase) {
        outlier_scan& scan = parts[part];
        const std::size_t k = o.sample.head;
        const double zc = chord / s.sigma[k].chord_deg, zp = phase / s.sigma[k].phase_deg;
        const double z = std::sqrt((zc * zc + zp * zp) / chi2_dof);
        if (!(z > threshold)) return;
        ++scan.count;
        for (auto [tally, r] :
             {std::pair{&scan.chord[k], chord}, std::pair{&scan.phase[k], phase}}) {
          ++tally->n;
          tally->positive += r > 0;
          tally->sum_deg += r;
        }
        // Keep the `listed` worst: a heap with the least bad on top.
        scan.worst.push_back({o.sample, chord, phase, z});
        std::push_heap(scan.worst.begin(), scan.worst.end(), worse);
        if (scan.worst.size() > listed) {
          std::pop_heap(scan.worst.begin(), scan.worst.end(), worse);
          scan.worst.pop_back();
        }
      });
  outlier_scan total = std::move(parts[0]);
  for (std::size_t part = 1; part < parts.size(); ++part) {
    total.count += parts[part].count;
    total.worst.insert(total.worst.end(), parts[part].worst.begin(), parts[part].worst.end());
    for (std::size_t k = 0; k < heads; ++k)
      for (auto [into, from] : {std::pair{&total.chord[k], &parts[part].chord[k]},
                                std::pair{&total.phase[k], &parts[part].phase[k]}}) {
        into->n += from->n;
        into->positive += from->positive;
        into->sum_deg += from->sum_deg;
      }
  }
  std::sort(total.worst.begin(), total.worst.end(), worse);
  if (total.worst.size() > listed) total.worst.resize(listed);
  return total;
}

}  // namespace conescan::calibration::passes

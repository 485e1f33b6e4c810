#include "scene/budget_run.hpp"

namespace conescan::scene {

budget_run::budget_run(const std::vector<budget_source>& sources) {
  for (const budget_source& s : sources) {
    sims_.push_back(simulation::of(s.scene).value());
    single_.push_back(s.name != budget_all_name);
  }
}

budget_row budget_run::make_row() const {
  budget_row r;
  for (const simulation& sim : sims_) r.sources.push_back(sim.make_row());
  return r;
}

void budget_run::compute(std::uint64_t k, budget_row& out) const noexcept {
  for (std::size_t i = 0; i < sims_.size(); ++i) sims_[i].compute(k, out.sources[i]);
  sum_single_sources(out);
}

void budget_run::sum_single_sources(budget_row& out) const noexcept {
  out.roll_sum_rad = out.pitch_sum_rad = 0;
  out.sum_state = status::ok;
  for (std::size_t i = 0; i < sims_.size(); ++i) {
    if (!single_[i]) continue;
    const row& r = out.sources[i];
    out.roll_sum_rad += r.roll_err_rad;
    out.pitch_sum_rad += r.pitch_err_rad;
    if (r.state != status::ok) out.sum_state = status::none;
  }
}

void budget_summary::add(const budget_row& r) noexcept {
  for (std::size_t i = 0; i < sources.size(); ++i)
    sources[i].add(r.sources[i].roll_err_rad, r.sources[i].pitch_err_rad, r.sources[i].state);
  sum.add(r.roll_sum_rad, r.pitch_sum_rad, r.sum_state);
}

void budget_summary::merge(const budget_summary& other) noexcept {
  for (std::size_t i = 0; i < sources.size(); ++i) sources[i].merge(other.sources[i]);
  sum.merge(other.sum);
}

}  // namespace conescan::scene

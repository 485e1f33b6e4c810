#include "simulation/budget_run.hpp"

namespace conescan::scene {

budget_run::budget_run(const std::vector<budget_source>& sources, int threads) {
  for (const budget_source& s : sources) {
    if (s.name == budget_all_name) all_ = sims_.size();
    sims_.push_back(simulation::of(s.scene, threads).value());
    single_.push_back(s.name != budget_all_name);
    baseline_.push_back(s.baseline);
  }
}

budget_row budget_run::make_row() const {
  budget_row r;
  for (const simulation& sim : sims_) r.sources.push_back(sim.make_row());
  return r;
}

void budget_run::compute(std::uint64_t k, budget_row& out) const noexcept {
  for (std::size_t i = 0; i < sims_.size(); ++i) sims_[i].compute(k, out.sources[i]);
  combine_sources(out);
}

// A baseline comes before its source and has none itself (budget.hpp): it is still its own row.
void budget_run::subtract_baselines(budget_row& out) const noexcept {
  for (std::size_t i = 0; i < sims_.size(); ++i) {
    if (!baseline_[i]) continue;
    row& r = out.sources[i];
    const row& base = out.sources[*baseline_[i]];
    r.roll_err_rad -= base.roll_err_rad;
    r.pitch_err_rad -= base.pitch_err_rad;
    if (r.state == status::ok) r.state = base.state;  // a difference needs both
  }
}

void budget_run::combine_sources(budget_row& out) const noexcept {
  subtract_baselines(out);
  out.roll_sum_rad = out.pitch_sum_rad = 0;
  out.sum_state = status::ok;
  for (std::size_t i = 0; i < sims_.size(); ++i) {
    if (!single_[i]) continue;
    const row& r = out.sources[i];
    out.roll_sum_rad += r.roll_err_rad;
    out.pitch_sum_rad += r.pitch_err_rad;
    if (r.state != status::ok) out.sum_state = status::none;
  }
  const row& all = out.sources[all_];
  out.roll_interaction_rad = all.roll_err_rad - out.roll_sum_rad;
  out.pitch_interaction_rad = all.pitch_err_rad - out.pitch_sum_rad;
  out.interaction_state =
      all.state == status::ok && out.sum_state == status::ok ? status::ok : status::none;
}

void budget_summary::add(const budget_row& r) noexcept {
  for (std::size_t i = 0; i < sources.size(); ++i)
    sources[i].add(r.sources[i].roll_err_rad, r.sources[i].pitch_err_rad, r.sources[i].state);
  sum.add(r.roll_sum_rad, r.pitch_sum_rad, r.sum_state);
  interaction.add(r.roll_interaction_rad, r.pitch_interaction_rad, r.interaction_state);
}

void budget_summary::merge(const budget_summary& other) noexcept {
  for (std::size_t i = 0; i < sources.size(); ++i) sources[i].merge(other.sources[i]);
  sum.merge(other.sum);
  interaction.merge(other.interaction);
}

const error_statistics& budget_summary::line(std::size_t k) const noexcept {
  if (k < sources.size()) return sources[k];
  return k == sources.size() ? sum : interaction;
}

void budget_summary::reset(std::size_t lines) {
  sources.assign(lines - 2, error_statistics{});
  sum = interaction = error_statistics{};
}

}  // namespace conescan::scene

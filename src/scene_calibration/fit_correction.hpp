// conescan-sim --apply FILE: the paper's "elimination by simple subtraction of the
// modeled errors". A fit's JSON (conescan-fit --json) gives each head's misalignment, cone-angle
// bias and crossing biases and the Earth's horizon terms; for every row the core's rule
// (calibrated_crossings, conescan/head_calibration.hpp: the one flight code runs on board)
// predicts each head's chord and phase with those estimates and with an ideal head (no
// misalignment, no biases) at the row's true geometry on the fitted Earth (the calibration's
// forward model, src/scene_calibration/scene_model.hpp), and the difference, turned into the two
// crossings' errors, is subtracted from the measured crossings before the processing. What the
// CSV then shows is what remains after calibration. A head whose sensor physics the fit modelled
// (its hK.tau-ms in the file) is predicted through MODEL §12's chain with the fitted physics
// (scene_model::corrected), against an ideal head on the limb's 50 % height.
//
// Decision: only the head's errors are subtracted. The fitted horizon and limb terms are used to
// predict (they set where the crossings lie) but not removed: the processing's assumed Earth is
// the scene's (--processing-horizon-km etc.), which a user sets to the fitted value to use it.
#pragma once

#include <memory>
#include <string>

#include "scene/loaded_scene.hpp"
#include "scene/scene_config.hpp"
#include "simulation/simulation.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

/// The correction of a scene by a fit. Errors (option "apply", naming the file): the file's
/// (read_fit_json_file), a head count that differs from the scene's, a head parameter the fit
/// left undetermined, and the scene's --model bias (the fit's model is the scan model).
class fit_correction final : public crossing_correction {
 public:
  static conescan::checked<std::unique_ptr<fit_correction>> of(const loaded_scene& scene,
                                                               const std::string& fit_path);
  ~fit_correction() override;
  crossings<double> corrected(std::uint64_t k, double t_s, std::size_t head,
                              const crossings<double>& measured) const noexcept override;

 private:
  struct state;
  explicit fit_correction(std::unique_ptr<state> s);
  std::unique_ptr<state> state_;
};

}  // namespace conescan::scene

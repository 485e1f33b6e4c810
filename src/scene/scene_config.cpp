#include "scene/scene_config.hpp"

#include <cmath>

#include "conescan/scalar.hpp"
#include "orbit/kepler.hpp"
#include "orbit/wgs84.hpp"
#include "text/output_file.hpp"

namespace conescan::scene {

double sun_synchronous_cos_inclination(const scene_config& s) {
  const orbit::earth_constants& w = orbit::wgs84();
  return orbit::sun_synchronous_cos_inclination(s.a_km * 1000, s.e, w.gm_m3_s2, w.j2, w.a_m);
}

bool has_noise(const scene_config& scene) {
  for (const head_config& h : scene.heads)
    if (h.noise_deg > 0) return true;
  return false;
}

double effective_inclination_deg(const scene_config& scene) {
  if (!scene.sun_sync) return scene.i_deg;
  return rad_to_deg(std::acos(sun_synchronous_cos_inclination(scene)));
}

std::vector<input_file> scene_input_files(const scene_config& scene) {
  std::vector<input_file> files;
  const std::pair<std::string_view, const std::string*> sources[] = {
      {"tle", &scene.tle_file}, {"omm", &scene.omm_file},
      {"oem", &scene.oem_file}, {"eop", &scene.eop_file},
      {"aem", &scene.aem_file}, {"attitude-csv", &scene.attitude_csv_file}};
  for (const auto& [option, path] : sources)
    if (!path->empty()) files.push_back({option, *path});
  return files;
}

checked<void> output_apart_from_inputs(std::string_view option, const std::string& path,
                                       std::span<const input_file> inputs) {
  if (path.empty()) return success();
  for (const input_file& input : inputs)
    if (text::same_output_file(path, input.path))
      return diagnostic{std::string(option),
                        quote(path) + " is the file of --" + std::string(input.option) +
                            ", which this run reads: give the output a file of its own",
                        {}};
  return success();
}

}  // namespace conescan::scene

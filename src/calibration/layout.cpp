#include "calibration/layout.hpp"

namespace conescan::calibration {

namespace {

constexpr std::size_t sigma_slot = static_cast<std::size_t>(head_parameter::sigma);
constexpr std::size_t phase_slot = static_cast<std::size_t>(head_parameter::phase);

}  // namespace

estimation_layout estimation_layout::of(const parameter_set& parameters, double t_first_s,
                                        double t_last_s) {
  estimation_layout layout;
  layout.head_count = parameters.head_count;
  layout.free = parameters.free;
  layout.segment_s = parameters.segment_s;
  layout.segment_s.resize(layout.free.size(), 0.0);
  layout.t0_s = t_first_s;
  layout.t_last_s = t_last_s;
  for (std::size_t k = 0; k < parameters.head_count; ++k) {
    const bool both = parameters.free[parameter_index(k, head_parameter::sigma)] &&
                      parameters.free[parameter_index(k, head_parameter::phase)];
    layout.forms.push_back(both ? misalignment_form::cartesian : misalignment_form::polar);
  }
  const std::size_t n = layout.free.size();
  layout.segments.assign(n, 1);
  layout.first_coordinate.assign(n, -1);
  layout.stride.assign(n, 1);
  for (std::size_t slot = 0; slot < n; ++slot) {
    if (!layout.free[slot]) layout.segment_s[slot] = 0;
    if (layout.drifts(slot))
      layout.segments[slot] =
          static_cast<std::size_t>(segment_count(t_first_s, t_last_s, layout.segment_s[slot]));
  }
  auto add = [&](std::size_t slot, std::size_t segment) {
    if (segment == 0)
      layout.first_coordinate[slot] = static_cast<std::ptrdiff_t>(layout.coordinates.size());
    layout.coordinates.push_back(slot);
    layout.coordinate_segment.push_back(segment);
  };
  for (std::size_t slot = 0; slot < n; ++slot) {
    if (!layout.free[slot]) continue;
    const bool pair = slot < layout.earth_block() && slot % head_parameter_count == sigma_slot &&
                      layout.forms[slot / head_parameter_count] == misalignment_form::cartesian;
    if (slot < layout.earth_block() && slot % head_parameter_count == phase_slot &&
        layout.forms[slot / head_parameter_count] == misalignment_form::cartesian &&
        layout.drifts(slot))
      continue;  // interleaved with its sigma slot below
    if (pair && layout.drifts(slot)) {
      layout.stride[slot] = layout.stride[slot + 1] = 2;
      for (std::size_t k = 0; k < layout.segments[slot]; ++k) {
        add(slot, k);
        add(slot + 1, k);
      }
      continue;
    }
    for (std::size_t k = 0; k < layout.segments[slot]; ++k) add(slot, k);
  }
  return layout;
}

std::string coordinate_name(const estimation_layout& layout, std::size_t i) {
  const std::size_t slot = layout.coordinates[i];
  std::string name = slot_name(layout, slot);
  if (layout.drifts(slot)) name += "[" + std::to_string(layout.coordinate_segment[i]) + "]";
  return name;
}

coordinate_key coordinate_key_of(const estimation_layout& layout, std::size_t i) {
  const std::size_t slot = layout.coordinates[i];
  coordinate_key key{slot, std::nullopt, false};
  if (layout.drifts(slot)) key.segment = layout.coordinate_segment[i];
  if (slot < layout.earth_block())
    key.cartesian = layout.forms[slot / head_parameter_count] == misalignment_form::cartesian &&
                    slot % head_parameter_count <= phase_slot;
  return key;
}

std::string slot_name(const estimation_layout& layout, std::size_t slot) {
  if (slot < layout.earth_block()) {
    const std::size_t head = slot / head_parameter_count;
    const std::size_t offset = slot % head_parameter_count;
    if (layout.forms[head] == misalignment_form::cartesian && offset <= phase_slot)
      return "h" + std::to_string(head + 1) +
             (offset == sigma_slot ? ".misalign-x" : ".misalign-y");
  }
  return parameter_name(slot, layout.head_count);
}

double wrap_deg(double angle_deg) {
  double wrapped = std::remainder(angle_deg, 360.0);  // [-180, 180], exact
  return wrapped == -180.0 ? 180.0 : wrapped;
}

std::vector<double> slots_from_parameters(const estimation_layout& layout,
                                          const parameter_set& parameters) {
  std::vector<double> slots = parameters.values;
  for (std::size_t k = 0; k < layout.head_count; ++k) {
    if (layout.forms[k] != misalignment_form::cartesian) continue;
    const std::size_t base = estimation_layout::head_block(k);
    const double sigma = parameters.values[base + sigma_slot];
    const double phase_rad = parameters.values[base + phase_slot] * radians_per_degree;
    slots[base + sigma_slot] = sigma * std::cos(phase_rad);
    slots[base + phase_slot] = sigma * std::sin(phase_rad);
  }
  return slots;
}

std::vector<double> coordinates_from_slots(const estimation_layout& layout,
                                           const std::vector<double>& slots) {
  std::vector<double> coordinates;
  for (std::size_t slot : layout.coordinates) coordinates.push_back(slots[slot]);
  return coordinates;
}

std::vector<double> slots_with_coordinates(const estimation_layout& layout,
                                           std::vector<double> slots,
                                           const std::vector<double>& coordinates) {
  for (std::size_t i = 0; i < layout.coordinates.size(); ++i)
    if (layout.coordinate_segment[i] == 0) slots[layout.coordinates[i]] = coordinates[i];
  return slots;
}

std::vector<double> parameters_from_slots(const estimation_layout& layout,
                                          const std::vector<double>& slots) {
  std::vector<double> values = slots;
  for (std::size_t k = 0; k < layout.head_count; ++k) {
    const std::size_t base = estimation_layout::head_block(k);
    if (layout.forms[k] == misalignment_form::cartesian) {
      const double x = slots[base + sigma_slot], y = slots[base + phase_slot];
      values[base + sigma_slot] = std::hypot(x, y);
      values[base + phase_slot] = std::atan2(y, x) / radians_per_degree;
    }
    if (layout.free[base + phase_slot])
      values[base + phase_slot] = wrap_deg(values[base + phase_slot]);
  }
  return values;
}

}  // namespace conescan::calibration

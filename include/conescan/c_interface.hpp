// The definitions of conescan/conescan.h, the C interface: include this file in exactly one C++
// file of a program (C++17; it needs no exceptions, RTTI or heap). Each function converts the
// plain structs to the core's types and calls the core (sensor_head, processing, attitude,
// head_calibration) in float or double; a head lives in the caller's conescan_head_* storage,
// built there in place.
#pragma once

#include <new>

#include "conescan/attitude.hpp"
#include "conescan/conescan.h"
#include "conescan/head_calibration.hpp"
#include "conescan/processing.hpp"
#include "conescan/sensor_head.hpp"

namespace conescan::c_interface {

// The C enum mirrors the core's, value for value.
static_assert(CONESCAN_OK == static_cast<int>(status::ok) &&
                  CONESCAN_INVALID == static_cast<int>(status::invalid) &&
                  CONESCAN_NONE == static_cast<int>(status::none) &&
                  CONESCAN_NONE + 1 == static_cast<int>(status_count),
              "conescan_status must list conescan::status in order");

/// The C types of one scalar.
template <class T>
struct types;
template <>
struct types<float> {
  using head = conescan_head_f;
  using config = conescan_head_config_f;
  using disk = conescan_disk_f;
  using crossings = conescan_crossings_f;
  using estimate = conescan_estimate_f;
  using attitude = conescan_attitude_f;
  using calibration = conescan_calibration_f;
};
template <>
struct types<double> {
  using head = conescan_head_d;
  using config = conescan_head_config_d;
  using disk = conescan_disk_d;
  using crossings = conescan_crossings_d;
  using estimate = conescan_estimate_d;
  using attitude = conescan_attitude_d;
  using calibration = conescan_calibration_d;
};

template <class T>
using c_head = typename types<T>::head;

template <class T>
const sensor_head<T>& head_of(const c_head<T>* head) noexcept {
  static_assert(
      sizeof(sensor_head<T>) <= sizeof(head->storage) && alignof(sensor_head<T>) <= alignof(double),
      "conescan_head_* must hold a sensor_head");
  return *std::launder(reinterpret_cast<const sensor_head<T>*>(head->storage));
}

inline conescan_status to_c(status s) noexcept {
  return static_cast<conescan_status>(s);
}
inline status from_c(conescan_status s) noexcept {
  return static_cast<status>(s);
}

template <class T>
conescan_status head_init(c_head<T>* head, const typename types<T>::config* c) noexcept {
  const sensor_head<T>* built = ::new (static_cast<void*>(head->storage))
      sensor_head<T>(sensor_head<T>::from_mounting(c->alpha_rad, c->beta_rad,
                                                   {c->gamma_rad, c->sigma_rad, c->phi_a_rad},
                                                   {T(0), T(0)}, c->envelope_rad));
  return to_c(built->state());
}

template <class T>
crossings<T> from_c(const typename types<T>::crossings& c) noexcept {
  return {c.phi_in_rad, c.phi_out_rad, from_c(c.status), 0};
}
template <class T>
typename types<T>::crossings to_c(const crossings<T>& c) noexcept {
  return {c.phi_in, c.phi_out, to_c(c.state)};
}
template <class T>
disk_trig<T> from_c(const typename types<T>::disk& d) noexcept {
  return {d.sin_rho, d.cos_rho, from_c(d.status)};
}
template <class T>
typename types<T>::estimate to_c(const head_estimate<T>& e) noexcept {
  return {{e.nadir.x, e.nadir.y, e.nadir.z}, e.eta_s, to_c(e.state)};
}
template <class T>
head_estimate<T> from_c(const typename types<T>::estimate& e) noexcept {
  return {e.eta_rad, vec3<T>(e.nadir[0], e.nadir[1], e.nadir[2]), from_c(e.status)};
}

template <class T>
typename types<T>::disk disk_of(T radius, T r) noexcept {
  const disk_trig<T> d = disk_trig_of(radius, r);
  return {d.sin_rho, d.cos_rho, to_c(d.state)};
}

template <class T>
typename types<T>::estimate process(const c_head<T>* head,
                                    const typename types<T>::crossings* measured,
                                    const typename types<T>::disk* assumed) noexcept {
  return to_c(head_of<T>(head).process(from_c<T>(*measured), from_c<T>(*assumed)));
}

template <class T>
typename types<T>::estimate combine(const typename types<T>::estimate* estimates,
                                    std::size_t count) noexcept {
  // combine_heads reads the status and the nadir of each: an iterator converting on the fly.
  struct iterator {
    const typename types<T>::estimate* at;
    head_estimate<T> value;
    const head_estimate<T>* operator->() {
      value = from_c<T>(*at);
      return &value;
    }
    iterator& operator++() {
      ++at;
      return *this;
    }
    bool operator!=(const iterator& other) const { return at != other.at; }
  };
  return to_c(combine_heads<T>(iterator{estimates, {}}, iterator{estimates + count, {}}));
}

template <class T>
typename types<T>::attitude attitude_of(const typename types<T>::estimate* e) noexcept {
  if (e->status != CONESCAN_OK) return {not_a_number<T>(), not_a_number<T>(), e->status};
  const conescan::roll_pitch<T> rp =
      roll_pitch_from_nadir(vec3<T>(e->nadir[0], e->nadir[1], e->nadir[2]));
  return {rp.roll, rp.pitch, CONESCAN_OK};
}

template <class T>
typename types<T>::crossings correct(const c_head<T>* head, const typename types<T>::calibration* c,
                                     const typename types<T>::crossings* measured,
                                     const T nadir_body[3],
                                     const typename types<T>::disk* disk) noexcept {
  const sensor_head<T>& h = head_of<T>(head);
  const crossings<T> m = from_c<T>(*measured);
  if (m.state == status::ok && h.state() != status::ok)
    return to_c(crossings<T>::failed(status::invalid));
  const head_calibration<T> calibration{
      {c->misalignment_x_deg, c->misalignment_y_deg, c->dgamma_deg},
      c->bias_in_deg,
      c->bias_out_deg};
  return to_c(calibrated_crossings(
      m, h.optics().gamma, calibration,
      h.in_scan_frame(vec3<T>(nadir_body[0], nadir_body[1], nadir_body[2])), from_c<T>(*disk)));
}

}  // namespace conescan::c_interface

extern "C" {

const char* conescan_status_name(conescan_status s) {
  return conescan::to_string(conescan::c_interface::from_c(s));
}

#define CONESCAN_C_INTERFACE_DEFINE(T, s)                                                    \
  conescan_status conescan_head_init_##s(conescan_head_##s* head,                            \
                                         const conescan_head_config_##s* config) {           \
    return conescan::c_interface::head_init<T>(head, config);                                \
  }                                                                                          \
  conescan_disk_##s conescan_disk_of_##s(T radius, T r) {                                    \
    return conescan::c_interface::disk_of<T>(radius, r);                                     \
  }                                                                                          \
  conescan_crossings_##s conescan_crossings_of_##s(T chord_rad, T phase_rad) {               \
    return conescan::c_interface::to_c(                                                      \
        conescan::crossings<T>::from_chord_phase(chord_rad, phase_rad));                     \
  }                                                                                          \
  conescan_estimate_##s conescan_process_##s(const conescan_head_##s* head,                  \
                                             const conescan_crossings_##s* measured,         \
                                             const conescan_disk_##s* assumed) {             \
    return conescan::c_interface::process<T>(head, measured, assumed);                       \
  }                                                                                          \
  conescan_estimate_##s conescan_combine_##s(const conescan_estimate_##s* estimates,         \
                                             size_t count) {                                 \
    return conescan::c_interface::combine<T>(estimates, count);                              \
  }                                                                                          \
  conescan_attitude_##s conescan_roll_pitch_##s(const conescan_estimate_##s* estimate) {     \
    return conescan::c_interface::attitude_of<T>(estimate);                                  \
  }                                                                                          \
  conescan_crossings_##s conescan_correct_##s(                                               \
      const conescan_head_##s* head, const conescan_calibration_##s* calibration,            \
      const conescan_crossings_##s* measured, const T nadir_body[3],                         \
      const conescan_disk_##s* disk) {                                                       \
    return conescan::c_interface::correct<T>(head, calibration, measured, nadir_body, disk); \
  }

CONESCAN_C_INTERFACE_DEFINE(float, f)
CONESCAN_C_INTERFACE_DEFINE(double, d)

#undef CONESCAN_C_INTERFACE_DEFINE
}

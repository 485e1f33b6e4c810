#include "simulation/blinding_calendar.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "conescan/vector.hpp"
#include "simulation/simulation.hpp"

namespace conescan::scene {

namespace {

using sky_check = simulation::sky_check;

// The rate bounds are doubled to hold over a step (blinding_calendar.hpp).
constexpr double rate_safety = 2;
// Upper bounds of the bodies' geocentric angular rates (rad/s): the Sun's 1.02 deg/day at
// perihelion, the Moon's 16.5 deg/day at perigee, each with room.
constexpr std::array<double, calendar_bodies> body_rate_bound{2.5e-7, 4.0e-6};
// A rate bound is never below this (rad/s): a margin of 1e-3 rad then allows 1e6 s, capped.
constexpr double rate_floor = 1e-9;

const sources::body_view& body_of(const sky_check& s, std::size_t body) noexcept {
  return body == 0 ? s.bodies.sun : s.bodies.moon;
}

double offset_of(const simulation::sky_head& head, std::size_t body) noexcept {
  return body == 0 ? head.sun_offset_rad : head.moon_offset_rad;
}

// eps = fov/2 + r_X (MODEL §13).
double reach_of(const sky_check& s, std::size_t head, std::size_t body) noexcept {
  return s.heads[head].fov_rad / 2 + body_of(s, body).angular_radius_rad;
}

// What the calendar tracks of one head and body.
enum class tracked { lost, on_cone };

bool holds(const sky_check& s, std::size_t head, std::size_t body, tracked what) noexcept {
  if (!s.ok) return false;
  if (what == tracked::lost) return s.heads[head].state == (body == 0 ? status::sun : status::moon);
  return std::abs(offset_of(s.heads[head], body)) <= reach_of(s, head, body);
}

// The margins of one head and body (blinding_calendar.hpp), rad, and their rate bounds, rad/s.
struct margins {
  double cone, cone_rate;  // g1
  double limb, limb_rate;  // g2
};

// The body's angle from the Earth's centre and the outline's angular radii, seen from the
// satellite.
struct limb_view {
  double theta, rho_in, rho_out, centre_rate;  // rad, rad/s
};

limb_view limb_of(const sky_check& s, std::size_t body) noexcept {
  const vec3<double> to_centre = s.centre_tod_m - s.r_tod_m;
  const double distance = norm(to_centre);
  const double rho_in = std::asin(std::min(1.0, s.inner_radius_m / distance));
  const double rho_out = std::asin(std::min(1.0, s.outer_radius_m / distance));
  const double speed = norm(s.v_tod_m_s);
  return {angle_between(body_of(s, body).direction_tod, to_centre), rho_in, rho_out,
          speed / distance * (1 + std::tan(rho_out))};
}

// The body's direction's rate bound in the scene frame: its own motion and the parallax.
double body_rate(const sky_check& s, std::size_t body) noexcept {
  return body_rate_bound[body] + norm(s.v_tod_m_s) / body_of(s, body).distance_m;
}

margins margins_of(const sky_check& s, std::size_t head, std::size_t body,
                   double axis_rate) noexcept {
  const double eps = reach_of(s, head, body);
  const limb_view limb = limb_of(s, body);
  const double x_rate = body_rate(s, body);
  return {std::abs(offset_of(s.heads[head], body)) - eps,
          rate_safety * (axis_rate + x_rate) + rate_floor,
          std::max(limb.rho_in - limb.theta,
                   limb.theta - limb.rho_out - 2 * eps - s.heads[head].fov_rad / 2),
          rate_safety * (x_rate + limb.centre_rate) + rate_floor};
}

bool candidate(const margins& m) noexcept {
  return m.cone <= 0 && m.limb <= 0;
}

// How long neither the on-cone state nor the pair of conditions can change (s): g1 keeps its
// sign for |g1| / rate; both conditions need g1 <= 0 and g2 <= 0.
double quiet_time(const margins& m) noexcept {
  const double cone_flip = std::abs(m.cone) / m.cone_rate;
  const double both =
      std::max(std::max(m.cone, 0.0) / m.cone_rate, std::max(m.limb, 0.0) / m.limb_rate);
  return std::min(cone_flip, both);
}

class event_finder {
 public:
  event_finder(const simulation& sim, double span_s, double resolution_s, blinding_calendar& out)
      : sim_(sim),
        span_s_(span_s),
        resolution_s_(resolution_s),
        out_(out),
        heads_(sim.head_count()),
        open_(heads_ * calendar_bodies * 2, std::numeric_limits<double>::quiet_NaN()) {}

  void run() {
    double t = 0;
    check(t, now_);
    for (std::size_t h = 0; h < heads_; ++h)
      for (std::size_t b = 0; b < calendar_bodies; ++b)
        for (tracked what : {tracked::lost, tracked::on_cone})
          if (holds(now_, h, b, what)) open(h, b, what, 0);
    while (t < span_s_) {
      const double next_t = std::min(span_s_, t + step_from(t));
      check(next_t, next_);
      for (std::size_t h = 0; h < heads_; ++h)
        for (std::size_t b = 0; b < calendar_bodies; ++b)
          for (tracked what : {tracked::lost, tracked::on_cone}) {
            const bool before = holds(now_, h, b, what);
            if (before == holds(next_, h, b, what)) continue;
            const double edge = bisect(t, next_t, h, b, what, before);
            if (before)
              close(h, b, what, edge);
            else
              open(h, b, what, edge);
          }
      std::swap(now_, next_);
      t = next_t;
    }
    for (std::size_t h = 0; h < heads_; ++h)
      for (std::size_t b = 0; b < calendar_bodies; ++b)
        for (tracked what : {tracked::lost, tracked::on_cone})
          if (!std::isnan(open_at(h, b, what))) close(h, b, what, span_s_);
  }

 private:
  void check(double t, sky_check& into) {
    sim_.sky_check_at(t, into);
    ++out_.samples;
  }

  // The next step from the sample now_ at t (s).
  double step_from(double t) {
    if (!now_.ok) return resolution_s_;
    for (std::size_t h = 0; h < heads_; ++h)
      for (std::size_t b = 0; b < calendar_bodies; ++b)
        if (candidate(margins_of(now_, h, b, 0))) return resolution_s_;
    // The optical axes' turn, over rate_probe_s (backwards at the span's end).
    const double probe_t = t + calendar_rate_probe_s <= span_s_ ? t + calendar_rate_probe_s
                                                                : t - calendar_rate_probe_s;
    check(probe_t, probe_);
    if (!probe_.ok) return resolution_s_;
    double step = calendar_max_step_s;
    for (std::size_t h = 0; h < heads_; ++h) {
      const double axis_rate =
          angle_between(now_.heads[h].axis_tod, probe_.heads[h].axis_tod) / calendar_rate_probe_s;
      for (std::size_t b = 0; b < calendar_bodies; ++b) {
        const double quiet = quiet_time(margins_of(now_, h, b, axis_rate));
        step = std::min(step, std::isnan(quiet) ? resolution_s_ : quiet);
      }
    }
    return std::max(step, resolution_s_);
  }

  // The time in (a, b] where `what` of head h and body `body` changes from `before` (one change
  // between a and b), to the edge tolerance: the middle of the last bracket.
  double bisect(double a, double b, std::size_t h, std::size_t body, tracked what, bool before) {
    while (b - a > calendar_edge_tolerance_s) {
      const double middle = a + (b - a) / 2;
      check(middle, scratch_);
      if (holds(scratch_, h, body, what) == before)
        a = middle;
      else
        b = middle;
    }
    return a + (b - a) / 2;
  }

  double& open_at(std::size_t h, std::size_t body, tracked what) {
    return open_[(h * calendar_bodies + body) * 2 + (what == tracked::lost ? 0 : 1)];
  }
  void open(std::size_t h, std::size_t body, tracked what, double t) { open_at(h, body, what) = t; }
  void close(std::size_t h, std::size_t body, tracked what, double t) {
    double& start = open_at(h, body, what);
    check(start, scratch_);
    const double orbit_deg = scratch_.ok
                                 ? argument_of_latitude_deg(scratch_.r_tod_m, scratch_.v_tod_m_s)
                                 : std::numeric_limits<double>::quiet_NaN();
    (what == tracked::lost ? out_.lost : out_.on_cone).push_back({h, body, start, t, orbit_deg});
    start = std::numeric_limits<double>::quiet_NaN();
  }

  const simulation& sim_;
  double span_s_, resolution_s_;
  blinding_calendar& out_;
  std::size_t heads_;
  std::vector<double> open_;  // per head, body and what: the open interval's start, or NaN
  sky_check now_, next_, probe_, scratch_;
};

bool by_start(const calendar_interval& a, const calendar_interval& b) {
  if (a.start_s != b.start_s) return a.start_s < b.start_s;
  if (a.head != b.head) return a.head < b.head;
  return a.body < b.body;
}

}  // namespace

const char* calendar_body_name(std::size_t body) noexcept {
  return body == 0 ? "sun" : "moon";
}

double argument_of_latitude_deg(const vec3<double>& r_m, const vec3<double>& v_m_s) noexcept {
  const vec3<double> h = cross(r_m, v_m_s);
  const vec3<double> node = cross(vec3<double>(0, 0, 1), h);  // towards the ascending node
  double u;
  if (norm(node) <= 1e-12 * norm(h))  // equatorial: the true longitude, along the motion
    u = h.z >= 0 ? std::atan2(r_m.y, r_m.x) : -std::atan2(r_m.y, r_m.x);
  else
    u = std::atan2(dot(cross(node, r_m), h) / norm(h), dot(node, r_m));
  const double deg = u * 180 / pi<double>();
  return deg < 0 ? deg + 360 : deg;
}

checked<blinding_calendar> blinding_calendar_of(const loaded_scene& scene) {
  blinding_calendar out;
  out.span_s = last_row_t_s(scene);
  out.resolution_s = scene.config.step_s;
  // The simulation over the same span in two rows: no pass over the rows (the physics tables'),
  // whose chain the calendar never asks (the rule runs on the geometric pulse, MODEL §13).
  loaded_scene two_rows = scene;
  two_rows.config.step_s = out.span_s > 0 ? out.span_s : scene.config.step_s;
  two_rows.config.duration_s = out.span_s;
  checked<simulation> sim = simulation::of(two_rows);
  if (!sim.ok()) return std::move(sim).error();
  out.epoch = sim.value().truth().epoch();
  out.heads = sim.value().head_count();
  event_finder(sim.value(), out.span_s, out.resolution_s, out).run();
  std::sort(out.lost.begin(), out.lost.end(), by_start);
  std::sort(out.on_cone.begin(), out.on_cone.end(), by_start);
  return out;
}

}  // namespace conescan::scene

// SGP4/SDP4 (src/orbit/sgp4.hpp): properties of the model and of the propagator's interface.
// The reproduction of Vallado's verification output is in test_sgp4_verification.cpp, the
// random cross-check against python-sgp4 in test_sgp4_oracle.cpp.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "orbit/sgp4.hpp"
#include "orbit/tle.hpp"

using namespace conescan::orbit;
using conescan::vec3;

namespace {

tle parsed(const std::string& line1, const std::string& line2) {
  const conescan::checked<tle> r = parse_tle(line1, line2);
  if (!r.ok()) FAIL(r.error().text());
  return r.value();
}

const tle iss = parsed("1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927",
                       "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537");
// From SGP4-VER.TLE: a 24-hour resonant GEO (XM-3), a 12-hour resonant Molniya (MOLNIYA 2-14),
// a non-resonant deep-space orbit (SL-12 R/B) and a decaying rocket body (MINOTAUR R/B).
const tle geo = parsed("1 28626U 05008A   06176.46683397 -.00000205  00000-0  10000-3 0  2190",
                       "2 28626   0.0019 286.9433 0000335  13.7918  55.6504  1.00270176  4891");
const tle molniya = parsed("1 08195U 75081A   06176.33215444  .00000099  00000-0  11873-3 0   813",
                           "2 08195  64.1586 279.0717 6877146 264.7651  20.2257  2.00491383225656");
const tle far = parsed("1 20413U 83020D   05363.79166667  .00000000  00000-0  00000+0 0  7041",
                       "2 20413  12.3514 187.4253 7864447 196.3027 356.5478  0.24690082  7978");
const tle minotaur =
    parsed("1 28872U 05037B   05333.02012661  .25992681  00000-0  24476-3 0  1534",
           "2 28872  96.4736 157.9986 0303955 244.0492 110.6523 16.46015938 10708");

double distance(const vec3<double>& a, const vec3<double>& b) {
  return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z);
}

bool same_state(const teme_state& a, const teme_state& b) {
  return a.status == b.status && a.r_teme_km == b.r_teme_km && a.v_teme_km_s == b.v_teme_km_s;
}

}  // namespace

TEST_CASE("sgp4: the ISS example at epoch, as python-sgp4 2.15 gives it", "[sgp4]") {
  const teme_state s = sgp4_propagator(iss).state_at(0.0);
  REQUIRE(s.status == sgp4_status::ok);
  // python-sgp4 2.15: Satrec.twoline2rv(...).sgp4_tsince(0.0)
  CHECK(distance(s.r_teme_km, {4083.902463520656, -993.6319996058095, 5243.603665370765}) < 1e-9);
  CHECK(distance(s.v_teme_km_s, {2.512837295156162, 7.259888524980963, -0.5837785365057586}) <
        1e-12);
}

TEST_CASE("sgp4: SGP4 below a period of 225 min, SDP4 and its resonances above", "[sgp4]") {
  CHECK_FALSE(sgp4_propagator(iss).deep_space());
  CHECK(sgp4_propagator(iss).resonance() == sgp4_resonance::none);
  CHECK(sgp4_propagator(geo).resonance() == sgp4_resonance::synchronous);
  CHECK(sgp4_propagator(molniya).resonance() == sgp4_resonance::half_day);
  CHECK(sgp4_propagator(far).deep_space());
  CHECK(sgp4_propagator(far).resonance() == sgp4_resonance::none);
  // Both sides of 225 min (6.4 rev/day; the recovered Brouwer motion decides, a little below
  // the TLE's Kozai one).
  sgp4_elements el = mean_elements(iss);
  el.mean_motion_rad_min = 2 * std::acos(-1.0) / 224.0;
  CHECK_FALSE(sgp4_propagator(el).deep_space());
  el.mean_motion_rad_min = 2 * std::acos(-1.0) / 226.0;
  CHECK(sgp4_propagator(el).deep_space());
}

TEST_CASE("sgp4: the velocity is the position's rate, to the model's own approximation", "[sgp4]") {
  // A central difference of the position over +-0.5 s: truncation h^2 |r'''| / 6 (1e-9 km/s in
  // low orbit) plus rounding eps |r| / h (1e-13 km/s). SGP4's velocity is not the exact rate of
  // its position: [STR3] differentiates the short-period terms only, not the secular and
  // long-period drift of the elements, nor the Sun's and Moon's periodics. Measured, relative
  // to |v|, at the times below: ISS 2.8e-6, GEO 2.2e-5, Molniya 1.8e-4, the far orbit (a = 17
  // earth radii, where the Moon pulls hardest) 1.3e-3. Each is allowed 4 times its figure.
  const std::pair<const tle*, double> cases[] = {
      {&iss, 1e-5}, {&geo, 1e-4}, {&molniya, 7e-4}, {&far, 5e-3}};
  for (const auto& [set, tolerance] : cases) {
    const sgp4_propagator model(*set);
    double worst = 0;
    for (double t : {-300.0, 0.0, 37.5, 1000.0, 5000.0}) {
      const double h_min = 0.5 / 60;
      const teme_state before = model.state_at(t - h_min), after = model.state_at(t + h_min);
      const teme_state at = model.state_at(t);
      const vec3<double> rate = (after.r_teme_km - before.r_teme_km) / (2 * h_min * 60);
      const double speed = std::hypot(at.v_teme_km_s.x, at.v_teme_km_s.y, at.v_teme_km_s.z);
      const double relative = distance(rate, at.v_teme_km_s) / speed;
      INFO("satellite " << set->satellite_number << ", t = " << t << " min");
      CHECK(relative < tolerance);
      worst = std::max(worst, relative);
    }
    CHECK(worst > tolerance / 20);  // the figure above is still the model's
  }
}

TEST_CASE("sgp4: state_at keeps nothing between calls", "[sgp4]") {
  // The reference resumes its resonance integration from the last call; here each call starts
  // from epoch. The same steps are taken either way: any order of calls gives the same states.
  for (const tle* set : {&geo, &molniya}) {
    const sgp4_propagator model(*set);
    const teme_state first = model.state_at(10000.0);
    model.state_at(5000.0);
    model.state_at(-7000.0);
    CHECK(same_state(model.state_at(10000.0), first));
    CHECK(same_state(sgp4_propagator(*set).state_at(10000.0), first));
  }
}

TEST_CASE("sgp4: states_at and a carried cursor give state_at's states bit for bit, in any order",
          "[sgp4]") {
  std::vector<double> times;
  for (int k = 0; k <= 200; ++k) times.push_back(37.0 * k);          // away from epoch, in order
  for (int k = 0; k <= 100; ++k) times.push_back(-53.0 * k);         // the other side of epoch
  for (int k = 0; k <= 50; ++k) times.push_back(9000.0 - 71.0 * k);  // back toward epoch
  times.push_back(0.0);
  times.push_back(1440.0 * 30);
  for (const tle* set : {&iss, &geo, &molniya, &far}) {
    const sgp4_propagator model(*set);
    std::vector<teme_state> batch(times.size());
    model.states_at(times.data(), batch.data(), times.size());
    sgp4_propagator::resonance_cursor cursor;  // carried as a scene's rows carry it
    for (std::size_t i = 0; i < times.size(); ++i) {
      INFO("satellite " << set->satellite_number << ", t = " << times[i] << " min");
      CHECK(same_state(batch[i], model.state_at(times[i])));
      CHECK(same_state(model.state_at(times[i], cursor), batch[i]));
    }
  }
}

TEST_CASE("sgp4: a decayed satellite keeps its state, flagged", "[sgp4]") {
  const sgp4_propagator model(minotaur);
  CHECK(model.status_at_epoch() == sgp4_status::ok);
  const teme_state s = model.state_at(55.0);  // tcppver.out stops MINOTAUR R/B at 55 min
  CHECK(s.status == sgp4_status::decayed);
  const double r_km = std::hypot(s.r_teme_km.x, s.r_teme_km.y, s.r_teme_km.z);
  CHECK(std::isfinite(r_km));
  CHECK(r_km < 6378.135);
  CHECK(model.state_at(50.0).status == sgp4_status::ok);
}

TEST_CASE("sgp4: far from epoch a state is finite or refused, never a silent NaN", "[sgp4]") {
  // Drag terms grow as t^4 and overflow; the eccentricity test (code 1) then refuses the time
  // before a non-finite number reaches the state. Resonant orbits integrate one step per 720
  // min, so they are taken to 1e8 min only.
  for (const tle* set : {&iss, &geo, &molniya, &far, &minotaur}) {
    const sgp4_propagator model(*set);
    const double reach = model.resonance() == sgp4_resonance::none ? 1e300 : 1e8;
    for (double t = 1.0; t <= reach; t *= 3.7) {
      for (double signed_t : {t, -t}) {
        const teme_state s = model.state_at(signed_t);
        const bool finite = std::isfinite(s.r_teme_km.x) && std::isfinite(s.r_teme_km.y) &&
                            std::isfinite(s.r_teme_km.z) && std::isfinite(s.v_teme_km_s.x) &&
                            std::isfinite(s.v_teme_km_s.y) && std::isfinite(s.v_teme_km_s.z);
        const bool has_state = s.status == sgp4_status::ok || s.status == sgp4_status::decayed;
        INFO("satellite " << set->satellite_number << ", t = " << signed_t << " min");
        CHECK(finite == has_state);
      }
    }
  }
}

TEST_CASE("sgp4: elements and times the model refuses", "[sgp4][bad input]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto status_of = [](const sgp4_elements& el, double t) {
    const teme_state s = sgp4_propagator(el).state_at(t);
    CHECK(std::isnan(s.r_teme_km.x));
    CHECK(std::isnan(s.v_teme_km_s.z));
    return s.status;
  };
  const sgp4_elements good = mean_elements(iss);
  sgp4_elements el = good;
  el.bstar = nan;
  CHECK(status_of(el, 0.0) == sgp4_status::invalid_input);
  CHECK(sgp4_propagator(el).status_at_epoch() == sgp4_status::invalid_input);
  el = good;
  el.epoch_days_since_1950 = inf;
  CHECK(status_of(el, 10.0) == sgp4_status::invalid_input);
  el = good;
  el.eccentricity = 1.0;
  CHECK(status_of(el, 0.0) == sgp4_status::mean_eccentricity);
  el.eccentricity = -1e-9;
  CHECK(status_of(el, 0.0) == sgp4_status::mean_eccentricity);
  el = good;
  el.mean_motion_rad_min = 0.0;
  CHECK(status_of(el, 0.0) == sgp4_status::mean_motion);
  CHECK(status_of(good, nan) == sgp4_status::invalid_input);
  CHECK(status_of(good, -inf) == sgp4_status::invalid_input);
  // Both sides of the boundaries: e = 0 and a tiny positive mean motion are the model's.
  el = good;
  el.eccentricity = 0.0;
  CHECK(sgp4_propagator(el).state_at(100.0).status == sgp4_status::ok);
}

TEST_CASE("sgp4: every status has its own description", "[sgp4]") {
  std::set<std::string> texts;
  for (sgp4_status s : {sgp4_status::ok, sgp4_status::mean_eccentricity, sgp4_status::mean_motion,
                        sgp4_status::perturbed_eccentricity, sgp4_status::semi_latus_rectum,
                        sgp4_status::decayed, sgp4_status::invalid_input})
    texts.insert(describe(s));
  CHECK(texts.size() == 7);
}

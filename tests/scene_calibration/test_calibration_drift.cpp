// Parameters that drift (--free NAME@SECONDS): one value per segment of the telemetry, the
// others global. The segmented fit with one segment is the global fit; a horizon that steps
// between two halves of the data is recovered in each; the history is in the table and the
// JSON; a fit that drifts is not read back for a correction.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <variant>

#include "calibration/fit_json.hpp"
#include "calibration/report.hpp"
#include "support/synthetic_model.hpp"

namespace cal = conescan::calibration;
using cal::earth_parameter;
using cal::head_parameter;
using cal::parameter_index;

namespace {

const cal::forward_model_of<cal::synthetic_model>& model() {
  static const cal::forward_model_of<cal::synthetic_model> m{cal::synthetic_model({})};
  return m;
}

cal::fit_result fit_converged(const cal::parameter_set& start,
                              const std::vector<cal::observation>& data) {
  const auto outcome = cal::fit({&model(), start, data, {{0.01, 0.0}, {0.01, 0.0}}}, {});
  INFO((outcome.ok() ? std::string() : outcome.error().text()));
  REQUIRE(outcome.ok());
  REQUIRE(std::holds_alternative<cal::fit_result>(outcome.value()));
  return std::get<cal::fit_result>(outcome.value());
}

const std::size_t horizon = parameter_index(2, earth_parameter::horizon);

std::string free_error(const std::string& list) {
  const auto r = cal::parse_free_selection(list, 2);
  REQUIRE_FALSE(r.ok());
  return r.error().text();
}

}  // namespace

TEST_CASE("calibration drift: --free reads NAME@SECONDS", "[calibration][drift]") {
  const auto r = cal::parse_free_selection("h1.sigma,horizon-km@86400,h2.dgamma@3600.5", 2);
  REQUIRE(r.ok());
  REQUIRE(r.value().size() == 3);
  CHECK(r.value()[0].index == 0);
  CHECK(r.value()[0].segment_s == 0);
  CHECK(r.value()[1].index == horizon);
  CHECK(r.value()[1].segment_s == 86400);
  CHECK(r.value()[2].index == parameter_index(1, head_parameter::dgamma));
  CHECK(r.value()[2].segment_s == 3600.5);
  CHECK(cal::parse_free_selection("h1.sigma@60,h1.phase@60", 1).ok());
  const std::string grammar =
      ": a drifting parameter is NAME@SECONDS, the segment length a number of seconds in (0, 1e12]";
  for (const char* bad : {"horizon-km@", "horizon-km@0", "horizon-km@-5", "horizon-km@abc",
                          "horizon-km@1e13", "horizon-km@nan", "horizon-km@ 5"})
    CHECK(free_error(bad) == "--free: '" + std::string(bad) + "'" + grammar);
  CHECK(free_error("horizon-km@5,horizon-km") == "--free: 'horizon-km' is named twice");
  CHECK_THAT(free_error("h1.sigma@100,h1.phase"),
             Catch::Matchers::StartsWith("--free: h1.sigma and h1.phase are estimated together"));
  CHECK_THAT(free_error("h3.sigma@100"), Catch::Matchers::Contains("names head 3"));
  // The plain list (conescan.fit) has no drifting parameters.
  const auto plain = cal::parse_free_list("horizon-km@100", 2);
  REQUIRE_FALSE(plain.ok());
  CHECK_THAT(plain.error().text(),
             Catch::Matchers::StartsWith("--free: drifting parameters (NAME@SECONDS)"));
}

TEST_CASE("calibration drift: one segment is the global fit", "[calibration][drift]") {
  const std::vector<cal::observation> data =
      cal::simulate_observations(model().model(), cal::recovery_truth(), 0, 10, 600, 0.01, 3, 0);
  const cal::fit_result global = fit_converged(cal::recovery_start(), data);
  // The horizon, and head 1's misalignment (a cartesian pair), each in one segment longer than
  // the data.
  for (const std::vector<std::size_t>& drifting :
       {std::vector<std::size_t>{horizon}, std::vector<std::size_t>{0, 1},
        std::vector<std::size_t>{0, 1, horizon}}) {
    cal::parameter_set start = cal::recovery_start();
    for (std::size_t index : drifting) start.segment_s[index] = 1e6;
    const cal::fit_result one = fit_converged(start, data);
    INFO(cal::fit_table(one));
    REQUIRE(one.uncertainty.reported.size() == global.uncertainty.reported.size());
    for (std::size_t i = 0; i < one.uncertainty.reported.size(); ++i) {
      const cal::parameter_estimate& a = one.uncertainty.reported[i];
      const cal::parameter_estimate& b = global.uncertainty.reported[i];
      INFO(a.name << " against " << b.name);
      CHECK(a.index == b.index);
      CHECK(a.estimate == b.estimate);
      CHECK(a.sigma == b.sigma);
      for (std::size_t j = 0; j < one.uncertainty.reported.size(); ++j)
        CHECK(one.uncertainty.correlation[i][j] == global.uncertainty.correlation[i][j]);
    }
    CHECK(one.chi2_dof == global.chi2_dof);
    CHECK(one.iterations == global.iterations);
    REQUIRE(one.uncertainty.drift.size() == (drifting.size() == 1 ? 1 : drifting.size()));
    for (const cal::drift_history& h : one.uncertainty.drift) {
      REQUIRE(h.segments.size() == 1);
      CHECK(h.segments[0].observations == 1200);
      CHECK(h.segments[0].value.estimate == global.uncertainty.parameters[h.parameter].estimate);
      CHECK(h.segments[0].value.sigma == global.uncertainty.parameters[h.parameter].sigma);
      CHECK(h.segments[0].start_s == 0);
      CHECK(h.segments[0].end_s == 5990);  // the last segment ends at the last measurement
      CHECK_FALSE(one.uncertainty.parameters[h.parameter].determined);
      CHECK_THAT(one.uncertainty.parameters[h.parameter].withheld,
                 Catch::Matchers::StartsWith("drifts: one value in each of 1 segment of 1e+06 s"));
    }
  }
}

TEST_CASE("calibration drift: a horizon that steps is recovered in each segment",
          "[calibration][drift]") {
  // Two orbits at 10 s with the horizon at 42 km, then two at 43 km.
  cal::parameter_set truth = cal::recovery_truth();
  std::vector<cal::observation> data =
      cal::simulate_observations(model().model(), truth, 0, 10, 1200, 0.01, 5, 0);
  truth.value(earth_parameter::horizon) = 43;
  const std::vector<cal::observation> later =
      cal::simulate_observations(model().model(), truth, 12000, 10, 1200, 0.01, 6, 0);
  for (cal::observation o : later) {
    o.sample.row += 1200;
    data.push_back(o);
  }
  cal::parameter_set start = cal::recovery_start();
  start.segment_s[horizon] = 12000;
  const cal::fit_result r = fit_converged(start, data);
  const std::string table = cal::fit_table(r);
  INFO(table);
  REQUIRE(r.uncertainty.drift.size() == 1);
  const cal::drift_history& h = r.uncertainty.drift[0];
  CHECK(h.name == "horizon-km");
  CHECK(h.unit == "km");
  REQUIRE(h.segments.size() == 2);
  for (std::size_t k = 0; k < 2; ++k) {
    const cal::drift_segment& d = h.segments[k];
    CHECK(d.value.name == "horizon-km[" + std::to_string(k) + "]");
    CHECK(d.observations == 2400);
    CHECK(d.start_s == 12000.0 * static_cast<double>(k));
    REQUIRE(d.value.determined);
    CHECK(std::abs(d.value.estimate - (42.0 + static_cast<double>(k))) < 3 * d.value.sigma);
  }
  CHECK(r.warnings.empty());
  CHECK(table.find("history of horizon-km (one value per 12000 s") != std::string::npos);
  CHECK(table.find("horizon-km[1]") != std::string::npos);
  // The global fit of the same data lands between the two, far from both.
  const cal::fit_result global = fit_converged(cal::recovery_start(), data);
  const cal::parameter_estimate& g = global.uncertainty.parameters[horizon];
  CHECK(std::abs(g.estimate - 42.5) < 0.2);
  CHECK(std::abs(g.estimate - 42) > 10 * g.sigma);
  // The JSON: the history, the segments in the order; not read back for a correction.
  const std::string json = cal::fit_json(r);
  CHECK(json.find("\"drift\": {\n    \"horizon-km\": {\"unit\": \"km\", \"segment_s\": 12000, "
                  "\"segments\": [\n      {\"start_s\": 0, \"end_s\": 12000, \"observations\": "
                  "2400, \"estimate\": ") != std::string::npos);
  CHECK(json.find("\"horizon-km[0]\", \"horizon-km[1]\"]") != std::string::npos);
  const auto read = cal::read_fit_json(json, "fit.json");
  REQUIRE_FALSE(read.ok());
  CHECK_THAT(read.error().text(), Catch::Matchers::Contains(
                                      ".drift: a fit with drifting parameters holds no one value"));
}

TEST_CASE("calibration drift: a drifting misalignment, segment by segment, and the limits",
          "[calibration][drift]") {
  const std::vector<cal::observation> data =
      cal::simulate_observations(model().model(), cal::recovery_truth(), 0, 10, 1200, 0.01, 7, 0);
  cal::parameter_set start = cal::recovery_start();
  start.segment_s[0] = start.segment_s[1] = 4000;  // h1's sigma and phase: 3 segments
  const cal::fit_result r = fit_converged(start, data);
  INFO(cal::fit_table(r));
  REQUIRE(r.uncertainty.drift.size() == 2);
  const char* names[] = {"h1.sigma[0]", "h1.phase[0]", "h1.sigma[1]", "h1.phase[1]"};
  for (std::size_t i = 0; i < 4; ++i) CHECK(r.uncertainty.reported[i].name == names[i]);
  CHECK(r.uncertainty.coordinate_names[0] == "h1.misalign-x[0]");
  CHECK(r.uncertainty.coordinate_names[3] == "h1.misalign-y[1]");
  const double truth[] = {0.05, 60};
  for (const cal::drift_history& h : r.uncertainty.drift) {
    REQUIRE(h.segments.size() == 3);
    for (const cal::drift_segment& d : h.segments) {
      REQUIRE(d.value.determined);
      CHECK(std::abs(cal::wrap_deg(d.value.estimate - truth[h.parameter])) < 3 * d.value.sigma);
    }
  }
  // Sigma and phase drift together or not at all; and no more than 1000 values in all.
  cal::parameter_set split = cal::recovery_start();
  split.segment_s[0] = 4000;
  const auto refused = cal::fit({&model(), split, data, {{0.01, 0.0}, {0.01, 0.0}}}, {});
  REQUIRE_FALSE(refused.ok());
  CHECK_THAT(refused.error().text(), Catch::Matchers::Contains("drift together or not"));
  cal::parameter_set fine = cal::recovery_start();
  fine.segment_s[horizon] = 10;
  const auto too_many = cal::fit({&model(), fine, data, {{0.01, 0.0}, {0.01, 0.0}}}, {});
  REQUIRE_FALSE(too_many.ok());
  CHECK(too_many.error().text() ==
        "--free: 1204 estimated values are more than a fit takes (1000): horizon-km@10 (1199 "
        "segments): give longer segments");
  // Counted before anything is allocated, in double: 1e-5 s over the data is 1.2e9 segments
  // (it once took all memory), 1e-20 s more than a size_t holds (it once wrapped to 1 segment).
  for (const double seconds : {1e-5, 1e-20, 1e-300}) {
    fine.segment_s[horizon] = seconds;
    const auto refused_tiny = cal::fit({&model(), fine, data, {{0.01, 0.0}, {0.01, 0.0}}}, {});
    INFO(seconds);
    REQUIRE_FALSE(refused_tiny.ok());
    CHECK_THAT(refused_tiny.error().text(),
               Catch::Matchers::Contains("estimated values are more than a fit takes (1000)"));
  }
  std::vector<cal::telemetry_sample> samples;
  for (const cal::observation& o : data) samples.push_back(o.sample);
  fine.segment_s[horizon] = 1e-20;
  const auto planned = cal::predict_uncertainty(model(), fine, samples,
                                                std::vector<cal::head_noise>(2, {0.01, 0.0}));
  REQUIRE_FALSE(planned.ok());
  CHECK_THAT(planned.error().text(),
             Catch::Matchers::Contains("estimated values are more than a fit takes (1000)"));
}

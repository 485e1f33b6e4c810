"""conescan.fit and conescan.predict against conescan-fit --json, and simulate's apply= against
conescan-sim --apply: the same telemetry and options give the same JSON object (every number the
same double: both are the one C++ writer's text), bad input gives conescan-fit's message.

ctest sets CONESCAN_SIM and CONESCAN_FIT to the programs built beside the module."""
import json
import re

import numpy as np
import pytest
from conftest import another_thread_runs_during, program
from test_simulate import assert_same_table

import conescan

if not hasattr(conescan._conescan, "_fit"):
    pytest.skip("the module was built without the scene layer", allow_module_level=True)


@pytest.fixture(scope="module")
def sim():
    return program("CONESCAN_SIM")


@pytest.fixture(scope="module")
def fit_cli():
    return program("CONESCAN_FIT")


# The truth: the paper's orbit (e = 0.1), one orbit at 10 s, two misaligned heads, head 1 with a
# cone-angle bias, the horizon at 42 km, 0.01 deg crossing noise.
TRUTH = {"model": "scan", "step_s": 10, "orbits": 1, "horizon_km": 42, "seed": 15,
         "head": ["sigma=0.05,phase=60,dgamma=0.02,noise=0.01",
                  "beta=-90,sigma=0.03,phase=200,noise=0.01"]}
TRUTH_ARGS = ["--model", "scan", "--step-s", "10", "--orbits", "1", "--horizon-km", "42",
              "--seed", "15", "--head", "sigma=0.05,phase=60,dgamma=0.02,noise=0.01",
              "--head", "beta=-90,sigma=0.03,phase=200,noise=0.01"]
# The fit's scene: the start of the free parameters (sigma 0, no bias, 40 km).
START = {"model": "scan", "step_s": 10, "orbits": 1, "horizon_km": 40,
         "head": ["sigma=0,noise=0.01", "beta=-90,sigma=0,noise=0.01"]}
START_ARGS = ["--model", "scan", "--step-s", "10", "--orbits", "1", "--horizon-km", "40",
              "--head", "sigma=0,noise=0.01", "--head", "beta=-90,sigma=0,noise=0.01"]
FREE = ["h1.sigma", "h1.phase", "h1.dgamma", "h2.sigma", "h2.phase", "horizon-km"]


@pytest.fixture(scope="module")
def telemetry_csv(sim, tmp_path_factory):
    path = tmp_path_factory.mktemp("fit") / "orbit.csv"
    path.write_text(sim(TRUTH_ARGS).stdout)
    return path


@pytest.fixture(scope="module")
def cli_fit(fit_cli, telemetry_csv):
    done = fit_cli(["--telemetry", str(telemetry_csv), *START_ARGS, "--free", ",".join(FREE),
                    "--json"])
    return done.stdout


def test_a_fit_of_simulated_telemetry_is_the_clis(cli_fit):
    result = conescan.fit(conescan.simulate(**TRUTH), free=FREE, **START)
    assert result == json.loads(cli_fit)  # every number the same double, every member there
    assert result["converged"] is True
    assert set(result["parameters"]) >= set(FREE)
    for name in FREE:  # the truth within 4 sigma of the estimate
        truth = {"h1.sigma": 0.05, "h1.phase": 60, "h1.dgamma": 0.02, "h2.sigma": 0.03,
                 "h2.phase": -160, "horizon-km": 42}[name]
        p = result["parameters"][name]
        assert abs(p["estimate"] - truth) < 4 * p["sigma"], name
    for member in ("correlation", "chi2_dof", "residual_rms_deg", "condition", "unobservable"):
        assert member in result


def test_a_telemetry_file_and_a_mapping_give_the_same_fit(cli_fit, telemetry_csv):
    expected = json.loads(cli_fit)
    assert conescan.fit(str(telemetry_csv), free=",".join(FREE), **START) == expected
    assert conescan.fit(telemetry_csv, free=FREE, **START) == expected  # a path
    rows = conescan.simulate(**TRUTH)
    columns = {name: rows[name] for name in ("t_s", "h1_chord_deg", "h1_phase_deg",
                                              "h2_chord_deg", "h2_phase_deg")}
    assert conescan.fit(columns, free=FREE, **START) == expected


def test_loss_and_iterations_reach_the_fit(fit_cli, telemetry_csv):
    args = ["--telemetry", str(telemetry_csv), *START_ARGS, "--free", "h1.sigma,h2.sigma",
            "--loss", "none", "--json"]
    assert conescan.fit(telemetry_csv, free=["h1.sigma", "h2.sigma"], loss="none",
                        **START) == json.loads(fit_cli(args).stdout)


def test_the_sensor_physics_is_fitted_as_the_cli_fits_it(sim, fit_cli, tmp_path):
    # One head with 1 ms of lag at 1 rev/s and the limb 40 km up, one orbit at 30 s; the fit
    # frees the lag from 0.5 ms (MODEL §12 in the forward model, docs/CALIBRATION.md).
    common = ["--model", "scan", "--step-s", "30", "--orbits", "1", "--radiance-offset-km", "40"]
    path = tmp_path / "lag.csv"
    path.write_text(sim([*common, "--head", "sigma=0,spin-hz=1,tau-ms=1,noise=0.001"]).stdout)
    head = "sigma=0,noise=0.001,spin-hz=1,tau-ms=0.5"
    expected = fit_cli(["--telemetry", str(path), *common, "--head", head, "--free",
                        "h1.tau-ms", "--json"]).stdout
    result = conescan.fit(path, free=["h1.tau-ms"], model="scan", step_s=30, orbits=1,
                          radiance_offset_km=40, head=[head])
    assert result == json.loads(expected)
    tau = result["parameters"]["h1.tau-ms"]
    assert abs(tau["estimate"] - 1) < 4 * tau["sigma"]
    assert tau["unit"] == "ms"


def test_a_fit_that_does_not_converge_raises_with_its_last_state(fit_cli, telemetry_csv):
    args = ["--telemetry", str(telemetry_csv), *START_ARGS, "--free", ",".join(FREE),
            "--max-iterations", "1", "--json"]
    done = fit_cli(args, check=False)
    assert done.returncode == 1  # conescan-fit: no estimate, its last state
    with pytest.raises(conescan.FitNotConverged, match="did not converge") as raised:
        conescan.fit(telemetry_csv, free=FREE, max_iterations=1, **START)
    assert isinstance(raised.value, RuntimeError)
    assert raised.value.result == json.loads(done.stdout)
    assert raised.value.result["converged"] is False and "parameters" not in raised.value.result


def cli_message(done):
    assert done.returncode == 2 and done.stdout == ""
    return done.stderr.strip().removeprefix("conescan-fit: ")


def python_named(message):
    """conescan-fit's message as conescan.fit says it: its own arguments named as Python spells
    them (the scene's options as the command line does)."""
    for cli, keyword in [("--free:", "free:"), ("--loss:", "loss:"),
                         ("--max-iterations:", "max_iterations:"), ("--telemetry:", "telemetry:")]:
        message = message.replace(cli, keyword)
    return message


def test_bad_input_gives_the_clis_message(fit_cli, telemetry_csv, tmp_path):
    tel = str(telemetry_csv)
    for options, args in [
        ({"free": ["h1.sigma", "h3.sigma"]}, ["--free", "h1.sigma,h3.sigma"]),  # unknown
        ({"free": ["h1.tilt"]}, ["--free", "h1.tilt"]),
        ({"free": []}, ["--free", ""]),  # no free parameter
        ({"free": ["h1.sigma"], "loss": "cauchy"}, ["--free", "h1.sigma", "--loss", "cauchy"]),
        ({"free": ["h1.sigma"], "max_iterations": 0},
         ["--free", "h1.sigma", "--max-iterations", "0"]),
        ({"free": ["h1.sigma"], "runs": 2}, ["--free", "h1.sigma", "--runs", "2"]),
        ({"free": ["h1.sigma"], "e": 1.5}, ["--free", "h1.sigma", "--e", "1.5"]),
        ({"free": ["h1.sigma"], "sweep": "e=0:0.1:0.05"},
         ["--free", "h1.sigma", "--sweep", "e=0:0.1:0.05"]),
    ]:
        expected = python_named(
            cli_message(fit_cli(["--telemetry", tel, *START_ARGS, *args], check=False)))
        with pytest.raises(ValueError, match="^" + re.escape(expected) + "$"):
            conescan.fit(tel, **options, **START)
    # A missing column: in a file, and in arrays (the same reader, the file named "<array>").
    rows = conescan.simulate(**TRUTH)
    cut = tmp_path / "cut.csv"
    names = ["t_s", "h1_chord_deg", "h1_phase_deg", "h2_chord_deg"]
    cut.write_text(",".join(names) + "\n" + "".join(
        ",".join(repr(float(rows[n][k])) for n in names) + "\n" for k in range(3)))
    expected = python_named(cli_message(
        fit_cli(["--telemetry", str(cut), *START_ARGS, "--free", "h1.sigma"], check=False)))
    assert "h2_phase_deg" in expected
    with pytest.raises(ValueError, match="^" + re.escape(expected) + "$"):
        conescan.fit(cut, free=["h1.sigma"], **START)
    with pytest.raises(ValueError, match="^" + re.escape(expected.replace(str(cut), "<array>"))
                       + "$"):
        conescan.fit({n: rows[n] for n in names}, free=["h1.sigma"], **START)
    missing = tmp_path / "nonexistent.csv"
    expected = python_named(cli_message(
        fit_cli(["--telemetry", str(missing), *START_ARGS, "--free", "h1.sigma"], check=False)))
    with pytest.raises(ValueError, match="^" + re.escape(expected) + "$"):
        conescan.fit(missing, free=["h1.sigma"], **START)
    with pytest.raises(TypeError, match="^free: expected a list of parameter names"):
        conescan.fit(tel, free=3, **START)
    with pytest.raises(ValueError, match="^unknown option 'a_kms'"):
        conescan.fit(tel, free=["h1.sigma"], a_kms=7000)


def test_predict_is_the_clis(fit_cli):
    free = ["h1.sigma", "h1.phase", "h2.sigma", "horizon-km"]
    expected = json.loads(fit_cli([*START_ARGS, "--free", ",".join(free), "--predict",
                                   "--json"]).stdout)
    assert conescan.predict(free=free, **START) == expected
    assert expected["kind"] == "design"
    expected = python_named(
        cli_message(fit_cli([*START_ARGS, "--free", "h9.sigma", "--predict"], check=False)))
    with pytest.raises(ValueError, match="^" + re.escape(expected) + "$"):
        conescan.predict(free=["h9.sigma"], **START)


def test_apply_corrects_as_the_cli_does(sim, cli_fit, tmp_path):
    fit_file = tmp_path / "fit.json"
    fit_file.write_text(cli_fit)
    clean = {**TRUTH, "head": ["sigma=0.05,phase=60,dgamma=0.02",
                               "beta=-90,sigma=0.03,phase=200"]}
    args = [*TRUTH_ARGS[:-4], "--head", "sigma=0.05,phase=60,dgamma=0.02", "--head",
            "beta=-90,sigma=0.03,phase=200", "--apply", str(fit_file)]
    corrected = conescan.simulate(apply=fit_file, **clean)
    assert_same_table(corrected, sim(args).stdout)
    assert_same_table(conescan.summary(apply=fit_file, **clean), sim(args + ["--summary"]).stdout)
    raw = conescan.simulate(**clean)
    assert np.nanmax(np.abs(corrected["roll_err_deg"])) < np.nanmax(np.abs(raw["roll_err_deg"]))
    # conescan-sim's refusals: a bad fit file, a sweep.
    bad = tmp_path / "bad.json"
    bad.write_text("{}\n")
    done = sim([*args[:-1], str(bad)], check=False)
    with pytest.raises(ValueError, match="^" + re.escape(
            done.stderr.strip().removeprefix("conescan-sim: ")) + "$"):
        conescan.simulate(apply=bad, **clean)
    with pytest.raises(ValueError, match="^--apply: corrects one scene"):
        conescan.simulate(apply=fit_file, sweep="e=0:0.1:0.05", **clean)


def test_a_fit_with_intrusions_leaves_out_the_blinded_rows(sim, fit_cli, tmp_path):
    # MODEL §13: telemetry of a 09:00 sun-synchronous orbit in the +y head's Sun season; the fit's
    # scene with intrusions=True finds the rows the Sun blinded and says how many, as the CLI.
    scene = {"model": "scan", "earth": "wgs84", "intrusions": True,
             "epoch": "2026-05-01T00:00:00", "a_km": 7178.137, "e": 0, "sun_sync": True,
             "j2": True, "raan_deg": 353.93852694944263, "step_s": 5, "duration_s": 12000,
             "head": ["beta=90,sigma=0.03,phase=40,noise=0.01", "beta=-90,sigma=0,noise=0.01"]}
    args = ["--model", "scan", "--earth", "wgs84", "--intrusions", "--epoch",
            "2026-05-01T00:00:00", "--a-km", "7178.137", "--e", "0", "--sun-sync", "--j2",
            "--raan-deg", "353.93852694944263", "--step-s", "5", "--duration-s", "12000",
            "--head", "beta=90,sigma=0.03,phase=40,noise=0.01",
            "--head", "beta=-90,sigma=0,noise=0.01"]
    rows = conescan.simulate(**scene)
    sun_rows = int((rows["h1_status"] == conescan.Status.sun).sum())
    assert sun_rows > 0
    path = tmp_path / "blinded.csv"
    path.write_text(sim(args).stdout)
    free = ["h1.sigma", "h1.phase"]
    expected = json.loads(fit_cli(["--telemetry", str(path), *args, "--free", ",".join(free),
                                   "--json"]).stdout)
    result = conescan.fit(rows, free=free, **scene)
    assert result == expected
    assert result["blinded"] == {"sun": [sun_rows, 0], "moon": [0, 0]}


def test_the_gil_is_released_during_a_fit(telemetry_csv):
    assert another_thread_runs_during(
        lambda: conescan.fit(telemetry_csv, free=FREE, **START), tries=10), \
        "the worker ran only after fit returned: the GIL was held"
    assert another_thread_runs_during(
        lambda: conescan.predict(free=FREE, **{**START, "step_s": 1}), tries=10), \
        "the worker ran only after predict returned: the GIL was held"


def test_fit_arguments_are_checked_as_conescan_fit_checks_them(fit_cli, telemetry_csv):
    # The fit options go through conescan-fit's own table of checks (fit_request.hpp): a count
    # that is not a whole number, a bool, or one of 31 digits is refused in one short line,
    # never truncated or converted.
    tel = str(telemetry_csv)
    for value, text in [(1.5, "1.5"), (True, "true"), (10**30, str(10**30)), (0, "0")]:
        expected = cli_message(fit_cli(["--telemetry", tel, *START_ARGS, "--free", "h1.sigma",
                                         "--max-iterations", text], check=False))
        assert expected == f"--max-iterations: '{text}' is not a count in [1, 10000]"
        # conescan.fit's own argument, named as Python spells it (was --max-iterations).
        with pytest.raises(ValueError, match="^" + re.escape(python_named(expected)) + "$"):
            conescan.fit(tel, free=["h1.sigma"], max_iterations=value, **START)
    with pytest.raises(TypeError, match=r"^loss: expected a number, a bool, text or a path, "
                                        r"not NoneType$"):
        conescan.fit(tel, free=["h1.sigma"], loss=None, **START)
    # The telemetry: an argument of the wrong kind, and a column that is not numbers, named.
    with pytest.raises(TypeError, match=r"^telemetry: expected a file name, a mapping or a "
                                        r"structured array, not NoneType$"):
        conescan.fit(None, free=["h1.sigma"], **START)
    rows = conescan.simulate(**TRUTH)
    columns = {name: rows[name] for name in ("t_s", "h1_chord_deg", "h1_phase_deg",
                                              "h2_chord_deg", "h2_phase_deg")}
    columns["h2_phase_deg"] = np.array([object()] * len(rows), dtype=object)
    with pytest.raises(TypeError, match=r"^telemetry: column h2_phase_deg is not numbers"):
        conescan.fit(columns, free=["h1.sigma"], **START)
    # A time as utc text in arrays: read as the reader reads the file (was dropped, then the
    # reader asked for "a time as utc").
    utc = {"utc": np.array([f"2000-01-01T12:{k // 6:02d}:{k % 6 * 10:02d}" for k in range(12)]),
           **{name: rows[name][:12] for name in ("h1_chord_deg", "h1_phase_deg", "h2_chord_deg",
                                                   "h2_phase_deg")}}
    with pytest.raises(ValueError, match=r"absolute times \(utc, GPS\) need the scene's epoch"):
        conescan.fit(utc, free=["h1.sigma"], **START)
    at_epoch = conescan.fit(utc, free=["h1.sigma"], epoch="2000-01-01T12:00:00", **START)
    by_t_s = conescan.fit({"t_s": rows["t_s"][:12], **{n: utc[n] for n in utc if n != "utc"}},
                          free=["h1.sigma"], **START)
    assert at_epoch["parameters"]["h1.sigma"]["estimate"] == pytest.approx(
        by_t_s["parameters"]["h1.sigma"]["estimate"], rel=1e-9)
    # What conescan-fit does not honour is refused by name: the same message as the CLI's.
    for keyword, args in [("write_oem", ["--write-oem", "x.oem"]), ("shard", ["--shard", "1/2"]),
                          ("trace", ["--trace"])]:
        expected = cli_message(fit_cli(["--telemetry", tel, *START_ARGS, "--free", "h1.sigma",
                                        *args], check=False))
        assert "not an option of conescan-fit" in expected
        with pytest.raises(ValueError, match="^" + re.escape(expected) + "$"):
            conescan.fit(tel, free=["h1.sigma"], **{keyword: args[-1] if len(args) > 1 else True},
                         **START)
        assert keyword not in conescan._scenes.HONOURED["conescan-fit"]
    offered = set(re.findall(r"^\s+(--[a-z0-9-]+)", fit_cli(["--help"]).stdout, re.M))
    for option in ("--write-oem", "--write-aem", "--summary-state", "--shard", "--trace",
                   "--print-config", "--merge", "--sweep", "--runs", "--apply"):
        assert option not in offered, option
    # --threads is conescan-fit's and conescan.fit's too: the passes' worker threads.
    assert "--threads" in offered and "threads" in conescan._scenes.HONOURED["conescan-fit"]
    two = conescan.fit(tel, free=["h1.sigma"], threads=2, **START)
    assert two == json.loads(fit_cli(["--telemetry", tel, *START_ARGS, "--free", "h1.sigma",
                                      "--threads", "2", "--json"]).stdout)
    assert {"--telemetry", "--free", "--loss", "--max-iterations", "--json", "--predict",
            "--config", "--a-km", "--head"} <= offered


def test_an_empty_head_list_is_refused():
    with pytest.raises(ValueError, match=r"^--head: an empty list: give at least one head"):
        conescan.simulate(head=[])

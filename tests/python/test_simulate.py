"""conescan.simulate and conescan.summary against conescan-sim: the same options give the same
columns and, parsed from the CLI's shortest round-trip text, exactly the same doubles; bad options
give the CLI's message word for word.

ctest sets CONESCAN_SIM to the conescan-sim built beside the module."""
import csv
import io
import pathlib
import re

import numpy as np
import pytest
from conftest import another_thread_runs_during, program

import conescan

if not hasattr(conescan._conescan, "_simulate"):
    pytest.skip("the module was built without the scene layer", allow_module_level=True)

SCENES = pathlib.Path(__file__).resolve().parents[2] / "data" / "scenes"
STATUS_CODE = {name: code for code, name in enumerate(conescan.status_names)}


@pytest.fixture(scope="module")
def cli():
    return program("CONESCAN_SIM")


def read_csv(text):
    """(names, rows) of the CLI's output."""
    rows = list(csv.reader(io.StringIO(text)))
    return rows[0], rows[1:]


def value_of(text, dtype):
    """The value a CSV field holds, as the array stores it."""
    if dtype.kind == "f":
        return float(text)  # shortest round-trip text: exactly the double
    if dtype.kind == "u" and dtype.itemsize == 1:
        return STATUS_CODE[text]
    if dtype.kind == "u":
        return int(text)
    return text


def assert_same_table(array, text):
    """Every field of every record of `array` equals the CLI's CSV `text`: names and order,
    reals bit for bit (NaN where the CSV has nan; the CSV never writes -0), statuses by name."""
    names, rows = read_csv(text)
    if names.count(names[0]) > 1:  # a sweep of the seed: NumPy's fields have unique names
        names[0] = "sweep_" + names[0]
    assert list(array.dtype.names) == names
    assert len(array) == len(rows)
    for k, name in enumerate(names):
        dtype = array.dtype[name]
        expected = [value_of(row[k], dtype) for row in rows]
        actual = array[name]
        if dtype.kind == "f":
            expected = np.array(expected, dtype=np.float64)
            same = (np.isnan(actual) & np.isnan(expected)) | (
                actual.view(np.uint64) == expected.view(np.uint64))
            assert same.all(), f"{name}: first difference at row {np.argmin(same)}"
        else:
            assert actual.tolist() == expected, name


# Each scene as keyword arguments and as the same command line.
SCENE_CASES = {
    "paper": ({}, []),
    "fig2a sweep": ({"config": SCENES / "paper-fig2a.toml"},
                    ["--config", str(SCENES / "paper-fig2a.toml")]),
    "wgs84 scan, two heads, noise, runs": (
        {"earth": "wgs84", "model": "scan", "horizon_km": 40, "processing_radius": "local",
         "head": ["alpha=0,beta=90,sigma=0.05,phase=60,noise=0.01",
                  {"beta": -90, "sigma": 0.03, "phase": 200, "noise": 0.02, "lsb": 0.005}],
         "seed": 7, "runs": 2, "step_s": 30, "j2": True, "sun_sync": True, "a_km": 7028.137,
         "e": 0.0012},
        ["--earth", "wgs84", "--model", "scan", "--horizon-km", "40", "--processing-radius",
         "local", "--head", "alpha=0,beta=90,sigma=0.05,phase=60,noise=0.01", "--head",
         "beta=-90,sigma=0.03,phase=200,noise=0.02,lsb=0.005", "--seed", "7", "--runs", "2",
         "--step-s", "30", "--j2", "--sun-sync", "--a-km", "7028.137", "--e", "0.0012"]),
    "error budget scene file, wgs84": ({"config": str(SCENES / "error-budget.toml")},
                                       ["--config", str(SCENES / "error-budget.toml")]),
    "horizon vector, condition column": (
        {"processing": "horizon-vector", "head": ["beta=90", "beta=-90"], "roll_deg": 0.5},
        ["--processing", "horizon-vector", "--head", "beta=90", "--head", "beta=-90",
         "--roll-deg", "0.5"]),
    "sweep of a head key, statuses not ok": (
        {"sweep": "h1.alpha=-80:80:40", "model": "scan", "e": 0, "orbits": 0.2},
        ["--sweep", "h1.alpha=-80:80:40", "--model", "scan", "--e", "0", "--orbits", "0.2"]),
    "sweep of the seed with runs": (
        {"sweep": "seed=1:3:1", "runs": 2, "head": "noise=0.1", "duration_s": 600},
        ["--sweep", "seed=1:3:1", "--runs", "2", "--head", "noise=0.1", "--duration-s", "600"]),
    "full budget": ({"config": SCENES / "full-budget.toml", "budget": True},
                    ["--config", str(SCENES / "full-budget.toml"), "--budget"]),
    "budget of two heads on wgs84, in a scene file": (
        {"config": SCENES / "error-budget.toml", "budget": "true", "orbits": 0.5},
        ["--config", str(SCENES / "error-budget.toml"), "--budget", "--orbits", "0.5"]),
    # MODEL §13: a 09:00 sun-synchronous orbit in the +y head's Sun season (docs/SUN_MOON.md);
    # the RAAN of the node at 09:00 mean local time on the epoch.
    "intrusions, the Sun on a head's cone": (
        {"model": "scan", "earth": "wgs84", "intrusions": True, "epoch": "2026-05-01T00:00:00",
         "a_km": 7178.137, "e": 0, "sun_sync": True, "j2": True, "raan_deg": 353.93852694944263,
         "head": ["beta=90,sigma=0", "beta=-90,sigma=0"], "step_s": 2, "duration_s": 12000},
        ["--model", "scan", "--earth", "wgs84", "--intrusions", "--epoch", "2026-05-01T00:00:00",
         "--a-km", "7178.137", "--e", "0", "--sun-sync", "--j2", "--raan-deg",
         "353.93852694944263", "--head", "beta=90,sigma=0", "--head", "beta=-90,sigma=0",
         "--step-s", "2", "--duration-s", "12000"]),
    # MODEL §12: the radiance's options as keywords, the physics keys in a head's dict and text.
    "sensor physics": (
        {"model": "scan", "horizon_km": 40, "radiance_offset_km": 2, "radiance_season": 0.2,
         "sun_declination_deg": 23.44, "step_s": 600, "duration_s": 3600,
         "head": [{"fov": 1.5, "fov-shape": "circle", "spin-hz": 1, "tau-ms": 1},
                  "beta=-90,locator=fixed,threshold=0.4"]},
        ["--model", "scan", "--horizon-km", "40", "--radiance-offset-km", "2",
         "--radiance-season", "0.2", "--sun-declination-deg", "23.44", "--step-s", "600",
         "--duration-s", "3600", "--head", "fov=1.5,fov-shape=circle,spin-hz=1,tau-ms=1",
         "--head", "beta=-90,locator=fixed,threshold=0.4"]),
    "file and keywords": ({"config": SCENES / "paper-fig2b.toml", "e": 0.05, "step_s": 90},
                          ["--config", str(SCENES / "paper-fig2b.toml"), "--e", "0.05",
                           "--step-s", "90"]),
}


@pytest.mark.parametrize("case", SCENE_CASES)
def test_rows_are_the_clis(cli, case):
    options, args = SCENE_CASES[case]
    assert_same_table(conescan.simulate(**options), cli(args).stdout)


@pytest.mark.parametrize("case", SCENE_CASES)
def test_summary_is_the_clis(cli, case):
    options, args = SCENE_CASES[case]
    assert_same_table(conescan.summary(**options), cli(args + ["--summary"]).stdout)


def test_the_cases_cover_what_they_claim():
    rows = conescan.simulate(**SCENE_CASES["sweep of a head key, statuses not ok"][0])
    assert {conescan.status_names[s] for s in rows["h1_status"]} == {"ok", "miss", "engulfed"}
    assert np.isnan(rows["roll_err_deg"][rows["status"] == conescan.Status.none]).all()
    noisy = conescan.simulate(**SCENE_CASES["wgs84 scan, two heads, noise, runs"][0])
    assert noisy.dtype.names[:2] == ("run", "seed") and set(noisy["run"]) == {1, 2}
    assert "condition" in conescan.simulate(**SCENE_CASES["horizon vector, condition column"][0]
                                            ).dtype.names
    blinded = conescan.simulate(**SCENE_CASES["intrusions, the Sun on a head's cone"][0])
    assert conescan.Status.sun in set(blinded["h1_status"])
    assert np.isnan(blinded["h1_chord_deg"][blinded["h1_status"] == conescan.Status.sun]).all()
    assert (np.abs(blinded["h1_sun_deg"]) < 0.3).all()  # the Sun on the cone all day
    lost = conescan.summary(**SCENE_CASES["intrusions, the Sun on a head's cone"][0])
    assert lost["sun_lost_fraction"][0] == lost["sun"][0] / lost["rows"][0] > 0
    lost_budget = conescan.summary(**SCENE_CASES["intrusions, the Sun on a head's cone"][0],
                                   budget=True)
    assert lost_budget.dtype.names[-2:] == ("sun_lost_fraction", "moon_lost_fraction")
    budget = conescan.summary(**SCENE_CASES["full budget"][0])
    assert budget["source"].tolist() == ["misalignment", "oblateness", "horizon-pole",
                                         "horizon-season", "noise", "quantisation", "all", "sum",
                                         "interaction"]


def test_a_value_reads_as_its_text():
    # A float goes in as its shortest round-trip text: any double, exactly.
    a_km = np.nextafter(7100.1, 8000.0)
    assert conescan.simulate(a_km=a_km)["r_km"][0] == conescan.simulate(
        a_km=repr(float(a_km)))["r_km"][0]
    assert conescan.simulate(a_km=7100.100000000001)["r_km"][0] != conescan.simulate(
        a_km=7100.1)["r_km"][0]
    same = [conescan.simulate(e=e, duration_s=100)
            for e in (0, 0.0, "0", np.float32(0), np.int8(0))]
    assert all(np.array_equal(s, same[0]) for s in same)
    assert np.array_equal(conescan.simulate(head={"alpha": 20, "sigma": 0.02}, duration_s=100),
                          conescan.simulate(head="alpha=20,sigma=0.02", duration_s=100))
    assert np.array_equal(conescan.simulate(sun_sync=True, j2=False, duration_s=100),
                          conescan.simulate(sun_sync="true", duration_s=100))


# Bad options as keyword arguments and on the command line: the same message.
BAD_CASES = [
    ({"a_km": -1}, ["--a-km", "-1"]),
    ({"e": float("nan")}, ["--e", "nan"]),
    ({"e": float("inf")}, ["--e", "inf"]),
    ({"e": np.float64("-inf")}, ["--e", "-inf"]),
    ({"e": 1}, ["--e", "1"]),
    ({"e": True}, ["--e", "true"]),
    ({"e": "0x10"}, ["--e", "0x10"]),
    ({"e": ""}, ["--e", ""]),
    ({"a_km": 1e400}, ["--a-km", "inf"]),
    ({"i_deg": 180.5}, ["--i-deg", "180.5"]),
    ({"seed": -1, "head": "noise=0.1"}, ["--seed", "-1", "--head", "noise=0.1"]),
    ({"runs": 0}, ["--runs", "0"]),
    ({"runs": 2.0}, ["--runs", "2.0"]),
    ({"max_rows": 10}, ["--max-rows", "10"]),
    ({"step_s": 0}, ["--step-s", "0"]),
    ({"orbits": 2, "duration_s": 10}, ["--orbits", "2", "--duration-s", "10"]),
    ({"earth": "mars"}, ["--earth", "mars"]),
    ({"model": "bias", "earth": "wgs84"}, ["--model", "bias", "--earth", "wgs84"]),
    ({"processing_radius": "far"}, ["--processing-radius", "far"]),
    ({"date": "2026-13-01"}, ["--date", "2026-13-01"]),
    ({"head": "alpha=95"}, ["--head", "alpha=95"]),
    ({"intrusions": True}, ["--intrusions"]),
    ({"intrusions": True, "model": "scan", "date": "2026-01-01"},
     ["--intrusions", "--model", "scan", "--date", "2026-01-01"]),
    ({"intrusions": "maybe"}, ["--intrusions=maybe"]),
    ({"head": ["beta=90", {"gamma": "x"}]}, ["--head", "beta=90", "--head", "gamma=x"]),
    ({"head": "colour=red"}, ["--head", "colour=red"]),
    ({"radiance_season": 1, "model": "scan"}, ["--radiance-season", "1", "--model", "scan"]),
    ({"radiance_scale_km": 5}, ["--radiance-scale-km", "5"]),
    ({"head": {"tau-ms": 1}, "model": "scan"}, ["--head", "tau-ms=1", "--model", "scan"]),
    ({"head": {"locator": "steepest"}}, ["--head", "locator=steepest"]),
    ({"head": ["sigma=0"] * 17}, ["--head", "sigma=0"] * 17),
    ({"sweep": "e=0:1:0"}, ["--sweep", "e=0:1:0"]),
    ({"sweep": "e=0:0.1:0.05", "e": 0.5}, ["--sweep", "e=0:0.1:0.05", "--e", "0.5"]),
    ({"sweep": "max-rows=1:2:1"}, ["--sweep", "max-rows=1:2:1"]),
    ({"sweep": "h2.alpha=0:10:5"}, ["--sweep", "h2.alpha=0:10:5"]),
    ({"sweep": "seed=1:2:1"}, ["--sweep", "seed=1:2:1"]),
    ({"sweep": "e=0:0.99:0.01", "a_km": 7000}, ["--sweep", "e=0:0.99:0.01", "--a-km", "7000"]),
    ({"e": 0.9}, ["--e", "0.9"]),
    ({"horizon_preset": "co2-15um"}, ["--horizon-preset", "co2-15um"]),
    ({"budget": True, "sweep": "e=0:0.1:0.05"}, ["--budget", "--sweep", "e=0:0.1:0.05"]),
    ({"budget": True, "runs": 2}, ["--budget", "--runs", "2"]),
    ({"config": SCENES / "no-such-file.toml"}, ["--config", str(SCENES / "no-such-file.toml")]),
    ({"config": SCENES}, ["--config", str(SCENES)]),
    ({"config": ""}, ["--config", ""]),
    ({"config": SCENES / "paper-fig2a.toml", "a_km": 100},
     ["--config", str(SCENES / "paper-fig2a.toml"), "--a-km", "100"]),
]


@pytest.mark.parametrize("options,args", BAD_CASES, ids=[" ".join(a) for _, a in BAD_CASES])
def test_bad_options_give_the_clis_message(cli, options, args):
    done = cli(args, check=False)
    assert done.returncode == 2 and done.stdout == ""
    message = done.stderr.removeprefix("conescan-sim: ").removesuffix("\n")
    for function in (conescan.simulate, conescan.summary):
        with pytest.raises(ValueError) as raised:
            function(**options)
        assert str(raised.value) == message


def test_a_scene_files_line_is_named(tmp_path, cli):
    scene = tmp_path / "bad.toml"
    scene.write_text("a-km = 7280\ne = 1.5\n")
    message = cli(["--config", str(scene)], check=False).stderr
    assert message == f"conescan-sim: {scene}:2:5: --e: e = 1.5 is outside [0, 1)\n"
    with pytest.raises(ValueError, match="^" + re.escape(message[14:-1]) + "$"):
        conescan.simulate(config=scene)
    # A keyword argument wins over the file, as the command line does.
    assert np.array_equal(conescan.simulate(config=scene, e=0.05),
                          conescan.simulate(a_km=7280, e=0.05))


def test_what_python_does_not_do_is_refused_by_name(tmp_path):
    # The option table says which function honours what (scene_program): the others are
    # refused, naming what they are for.
    for options, message, functions in [
        ({"trace": True}, "--trace: not an option of FUNCTION: writes the root finder's "
                          "iterations to conescan-sim's standard error",
         (conescan.simulate, conescan.summary)),
        ({"summary": True}, "--summary: not an option of FUNCTION: statistics instead of rows: "
                            "conescan-sim --summary, conescan.summary()", (conescan.simulate,)),
        ({"threads": 2}, "--threads: not an option of FUNCTION: conescan-sim's worker threads "
                         "(from Python, run scenes in Python threads: the GIL is released)",
         (conescan.simulate, conescan.summary)),
        ({"runs": 4, "head": "noise=0.01", "shard": "1/2"},
         "--shard: not an option of FUNCTION: a campaign's shard is conescan-sim's (--shard, "
         "--summary-state, --merge)", (conescan.simulate, conescan.summary)),
        ({"summary_state": "x.state"}, "--summary-state: not an option of FUNCTION: a "
                                       "campaign's state file is conescan-sim's",
         (conescan.simulate, conescan.summary)),
        ({"write_oem": "x.oem"}, "--write-oem: not an option of FUNCTION: conescan-sim writes "
                                 "the scene's orbit as an OEM", (conescan.simulate, conescan.summary)),
        ({"write_aem": "x.aem"}, "--write-aem: not an option of FUNCTION: conescan-sim writes "
                                 "the scene's true attitude as an AEM",
         (conescan.simulate, conescan.summary)),
    ]:
        for function in functions:
            name = "conescan." + function.__name__
            with pytest.raises(ValueError,
                               match="^" + re.escape(message.replace("FUNCTION", name)) + "$"):
                function(**options)
            refused = next(iter(re.findall(r"^--([a-z-]+)", message))).replace("-", "_")
            assert refused not in conescan._scenes.HONOURED[name], "offered but not honoured"
    scene = tmp_path / "trace.toml"
    scene.write_text("model = \"scan\"\ntrace = true\n")
    with pytest.raises(ValueError, match=re.escape(f"{scene}:2:9: --trace: not an option of")):
        conescan.simulate(config=scene)
    # A scene file's line that asks for nothing (as --print-config writes it) is read; one that
    # asks for what the function does not do is refused; conescan.summary honours summary.
    scene.write_text("summary = false\ntrace = false\n")
    assert len(conescan.simulate(config=scene)) == 619
    scene.write_text("summary = true\n")
    with pytest.raises(ValueError, match=re.escape(f"{scene}:1:11: --summary: not an option of "
                                                   "conescan.simulate")):
        conescan.simulate(config=scene)
    assert len(conescan.summary(config=scene)) == 2
    assert len(conescan.summary(summary=True)) == 2


def test_unknown_keywords_and_wrong_types():
    with pytest.raises(ValueError, match=r"^unknown option 'a_kms'; options: a_km, e, i_deg, "):
        conescan.simulate(a_kms=7000)
    with pytest.raises(ValueError, match=r"^unknown option 'print_config'; options: "):
        conescan.simulate(print_config=True)
    for options, message in [
        ({"e": [0.1]}, "--e: expected a number, a bool, text or a path, not list"),
        ({"e": None}, "--e: expected a number, a bool, text or a path, not NoneType"),
        ({"a_km": 1j}, "--a-km: expected a number, a bool, text or a path, not complex"),
        ({"e": np.array([0.1])}, "--e: expected a number, a bool, text or a path, not ndarray"),
        ({"head": 3}, "--head: expected a head spec (text or dict), or a list of them, not int"),
        ({"head": [{"alpha": None}]},
         "--head: head 1: alpha: expected a number, a bool, text or a path, not NoneType"),
        ({"head": [{"beta": 90}, {"fov": None}]},
         "--head: head 2: fov: expected a number, a bool, text or a path, not NoneType"),
        ({"config": 3}, "--config: expected a path, not int"),
    ]:
        with pytest.raises(TypeError, match="^" + re.escape(message) + "$"):
            conescan.simulate(**options)


def test_every_option_of_the_cli_is_a_keyword(cli):
    # The keywords come from the option table, as --help does: a new option needs no Python.
    help_options = set(re.findall(r"^\s+--([a-z0-9-]+)", cli(["--help"]).stdout, re.M))
    keywords = {name.replace("_", "-") for name in conescan._scenes.OPTIONS}
    # --merge is a mode of conescan-sim of its own, not a scene option; --version is the program's.
    assert help_options - keywords == {"config", "print-config", "merge", "version"}
    assert keywords <= help_options


def test_the_gil_is_released_during_a_long_run():
    # conftest.another_thread_runs_during: deterministic, no time threshold.
    assert another_thread_runs_during(lambda: conescan.simulate(orbits=300), tries=10), \
        "the worker ran only after simulate returned: the GIL was held"  # 185 000 rows a call
    assert another_thread_runs_during(lambda: conescan.summary(orbits=300), tries=10), \
        "the worker ran only after summary returned: the GIL was held"


def test_a_coarse_ephemeris_accepted_with_its_bound_as_a_warning(cli, tmp_path):
    # An OEM of SGP4's states read with HERMITE: refused at the default tolerance with the cause
    # (the CLI's message), accepted with interpolation_tolerance_deg raised, its bound given once
    # as a UserWarning (what conescan-sim prints on standard error).
    tle = pathlib.Path(__file__).resolve().parents[1] / "data" / "tle" / "delta-1-deb.tle"
    written = tmp_path / "sgp4.oem"
    cli(["--tle", str(tle), "--step-s", "60", "--duration-s", "1200", "--write-oem", str(written)])
    hermite = tmp_path / "hermite.oem"
    hermite.write_text(written.read_text().replace("INTERPOLATION = LAGRANGE",
                                                   "INTERPOLATION = HERMITE"))
    scene = ["--oem", str(hermite), "--step-s", "10", "--duration-s", "600"]
    message = cli(scene, check=False).stderr
    assert "the velocities are inconsistent with the positions" in message
    with pytest.raises(ValueError, match="^" + re.escape(message[14:-1]) + "$"):
        conescan.simulate(oem=hermite, step_s=10, duration_s=600)
    note = cli(scene + ["--interpolation-tolerance-deg", "0.001"]).stderr
    with pytest.warns(UserWarning) as warned:
        rows = conescan.simulate(oem=hermite, step_s=10, duration_s=600,
                                 interpolation_tolerance_deg=0.001)
    assert len(rows) == 61
    assert [str(w.message) for w in warned] == [note.removeprefix("conescan-sim: note: ")[:-1]]

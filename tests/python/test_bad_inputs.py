"""Bad inputs: shapes and dtypes raise with a message naming the function, the argument and what
was wrong; bad values (NaN, infinities, out of range) are not errors but the core's status
invalid, as from C++."""
import re

import numpy as np
import pytest

import conescan

DEG = np.pi / 180
FRAME = conescan.scan_frame_from_mounting(0.0, 90 * DEG).frame


def raises(error, message, function, *args):
    with pytest.raises(error, match="^" + re.escape(message) + "$"):
        function(*args)


def test_shapes_that_do_not_broadcast():
    raises(ValueError, "conescan.half_chord: the shapes of psi (3,), eta (4,) and rho () do not "
           "broadcast together", conescan.half_chord, np.zeros(3), np.zeros(4), 1.0)
    raises(ValueError, "conescan.disk_angular_radius: the shapes of radius (2, 3) and r (2,) do "
           "not broadcast together", conescan.disk_angular_radius, np.ones((2, 3)), np.ones(2))
    # Core dimensions do not broadcast against loop dimensions: (2, 3, 3) is 2 frames, v 5 vectors.
    raises(ValueError, "conescan.scan_angles_of: the shapes of frame (2, 3, 3) and v (5, 3) do "
           "not broadcast together", conescan.scan_angles_of, np.zeros((2, 3, 3)),
           np.zeros((5, 3)))


def test_missing_core_dimensions():
    raises(ValueError, "conescan.roll_pitch_from_nadir: n must have shape (..., 3), got (4, 2)",
           conescan.roll_pitch_from_nadir, np.zeros((4, 2)))
    raises(ValueError, "conescan.roll_pitch_from_nadir: n must have shape (..., 3), got ()",
           conescan.roll_pitch_from_nadir, 1.0)
    raises(ValueError, "conescan.process_head: frame must have shape (..., 3, 3), got (3,)",
           conescan.process_head, np.zeros(3), 1.0, 1.0, -1.0, 1.0)
    raises(ValueError, "conescan.scan_model_crossings_ellipsoid: frame_eci must have shape "
           "(..., 3, 3), got (3, 4)", conescan.scan_model_crossings_ellipsoid, 0.7, 0.0, 0.0,
           np.zeros((3, 4)), np.ones(3), 1.0, 1.0)


@pytest.mark.parametrize("value, dtype", [
    (np.array([1 + 2j]), "complex128"),
    ([1.0, None], "object"),
    (["1.0"], "<U3"),
    (np.array([1.0], dtype=np.longdouble), "float128"),
    (np.array(["2024-01-01"], dtype="datetime64[D]"), "datetime64[D]"),
])
def test_dtypes_numpy_does_not_cast_safely(value, dtype):
    raises(TypeError, f"conescan.half_chord: eta has dtype {dtype}, which numpy does not cast to "
           "float64 safely (expected real numbers)", conescan.half_chord, 1.0, value, 1.0)


def test_status_arguments():
    raises(TypeError, "conescan.process_head: status has dtype float64, which numpy does not cast"
           " to int64 safely (expected status codes)", conescan.process_head, FRAME, 1.0, 1.0,
           -1.0, 1.0, 0.0)
    count = len(conescan.status_names)  # the core's one status list
    raises(ValueError, f"conescan.quantised: status holds {count}, which is not a status code "
           f"(0 to {count - 1}, conescan.status_names)", conescan.quantised, -1.0, 1.0, 0.0,
           np.array([0, count, count + 2]))
    raises(ValueError, "conescan.with_crossing_noise: status holds -1, which is not a status code"
           f" (0 to {count - 1}, conescan.status_names)", conescan.with_crossing_noise, -1.0, 1.0,
           0.0, 0.0, -1)


def test_wrong_argument_count_is_pythons_type_error():
    with pytest.raises(TypeError, match="incompatible function arguments"):
        conescan.half_chord(1.0, 1.0)


# A valid call of each function with a status, and the arguments whose NaN the core answers
# with invalid. Two exceptions, the core's own (test_agreement.py holds them to it): the
# measurement-error steps take NaN crossings for a chord that vanished (status grazing), and
# scan_model_crossings_ellipsoid does not check frame_eci (docs/API.md; a NaN frame misses).
VALID = {
    "misaligned_cone_angle": (45 * DEG, 0.02 * DEG, 0.0),
    "disk_angular_radius": (6378137.0, 6552000.0),
    "half_chord": (45.02 * DEG, 90 * DEG, 64 * DEG),
    "scan_frame_from_mounting": (0.0, 90 * DEG),
    "bias_model_crossings": (45 * DEG, 0.02 * DEG, 0.0, 90 * DEG, 0.0, 64 * DEG),
    "scan_model_crossings_sphere": (45 * DEG, 0.02 * DEG, 0.0, 90 * DEG, 0.0, 64 * DEG),
    "scan_model_crossings_ellipsoid": (45 * DEG, 0.02 * DEG, 0.0, np.eye(3),
                                       np.array([-7e6, 0.0, 0.0]), 6378137.0, 6356752.0),
    "nadir_angle_roots_from_chord": (45 * DEG, 64 * DEG, 71 * DEG),
    "nadir_angle_from_chord": (45 * DEG, 64 * DEG, 71 * DEG, 90 * DEG),
    "process_head": (FRAME, 45 * DEG, 64 * DEG, -71 * DEG, 71 * DEG),
    "with_crossing_noise": (-1.2, 1.2, 1e-3, -1e-3),
    "quantised": (-1.2, 1.2, 1e-3),
}
NAN_NOT_INVALID = {("with_crossing_noise", 0), ("with_crossing_noise", 1), ("quantised", 0),
                   ("quantised", 1), ("scan_model_crossings_ellipsoid", 3)}


@pytest.mark.parametrize("name", sorted(VALID))
def test_nan_in_any_argument_is_status_invalid(name):
    function, args = getattr(conescan, name), VALID[name]
    assert function(*args).status == conescan.Status.ok
    for i, arg in enumerate(args):
        if (name, i) in NAN_NOT_INVALID:
            continue
        bad = list(args)
        bad[i] = np.full(np.shape(arg), np.nan)
        result = function(*bad)
        assert result.status == conescan.Status.invalid, f"NaN as argument {i}"
        for value, field in zip(result, result._fields):
            if field not in ("status", "iterations"):
                assert np.isnan(value).all(), f"NaN as argument {i}: {field} = {value}"


@pytest.mark.parametrize("name, args", [
    ("misaligned_cone_angle", (45 * DEG, 45 * DEG, 0.0)),  # sigma >= gamma
    ("misaligned_cone_angle", (90 * DEG, 0.0, 0.0)),  # gamma >= pi/2
    ("disk_angular_radius", (7e6, 6.9e6)),  # inside the sphere
    ("half_chord", (45 * DEG, 90 * DEG, 91 * DEG)),  # rho > pi/2
    ("half_chord", (45 * DEG, -1e-300, 64 * DEG)),  # eta < 0
    ("scan_frame_from_mounting", (np.pi / 2, 0.0)),  # body +z on the spin axis
    ("nadir_angle_from_chord", (45 * DEG, 64 * DEG, np.pi + 1e-15, 90 * DEG)),
    ("quantised", (-1.2, 1.2, -1e-3)),  # negative lsb
    ("half_chord", (np.inf, 90 * DEG, 64 * DEG)),
])
def test_out_of_range_is_status_invalid(name, args):
    assert getattr(conescan, name)(*args).status == conescan.Status.invalid

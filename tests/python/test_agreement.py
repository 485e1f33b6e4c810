"""Every binding against the core called from plain C++ (tests/python/reference.cpp), bit for bit,
on random inputs that cover the domain, its edges and beyond, with NaN, infinities and signed
zeros sprinkled in. Fixed seeds: a failure reproduces."""
import subprocess

import numpy as np
import pytest

import conescan
from conftest import flat_rows, same_bits

ROWS = 2000
SPECIALS = np.array([np.nan, np.inf, -np.inf, 0.0, -0.0, 5e-324, 1e300, -1.0, 4.0])


def real(rng, lo, hi, special=0.03):
    """Uniform in [lo, hi), a fraction `special` of them replaced by SPECIALS."""
    x = rng.uniform(lo, hi, ROWS)
    hit = rng.random(ROWS) < special
    x[hit] = rng.choice(SPECIALS, hit.sum())
    return x


def vectors(rng, scale=1.0, special=0.02):
    """Random directions times scale, some components replaced by SPECIALS."""
    v = rng.normal(size=(ROWS, 3))
    v *= scale / np.linalg.norm(v, axis=1, keepdims=True)
    hit = rng.random((ROWS, 3)) < special / 3
    v[hit] = rng.choice(SPECIALS, hit.sum())
    return v


def mounted_frames(rng):
    """Scan frames of heads mounted anywhere (rows e1, e2, e3), a few of them NaN."""
    return conescan.scan_frame_from_mounting(real(rng, -1.6, 1.6), rng.uniform(-4, 4, ROWS)).frame


def rotated_frames(rng):
    """Random proper rotations: a frame's axes expressed in ECI."""
    q, r = np.linalg.qr(rng.normal(size=(ROWS, 3, 3)))
    q *= np.sign(np.diagonal(r, axis1=1, axis2=2))[:, np.newaxis, :]
    q[np.linalg.det(q) < 0] *= -1
    return np.swapaxes(q, 1, 2)


def status_codes(rng):
    """Mostly ok, every other status now and then."""
    codes = np.zeros(ROWS, dtype=np.int64)
    hit = rng.random(ROWS) < 0.1
    codes[hit] = rng.integers(1, len(conescan.status_names), hit.sum())
    return codes


def measured(rng):
    """Crossings phi_in, phi_out about a random phase, half chords over (0, pi) and beyond."""
    phase, half = real(rng, -np.pi, np.pi), real(rng, -0.1, np.pi + 0.1)
    return [phase - half, phase + half]


def optics(rng, sigma_max):
    gamma = real(rng, -0.1, 1.7)
    return [gamma, gamma * rng.uniform(-0.05, sigma_max, ROWS), real(rng, -7, 7)]


INPUTS = {
    "misaligned_cone_angle": lambda rng: optics(rng, 1.1),
    "disk_angular_radius": lambda rng: [real(rng, 6e6, 7e6), real(rng, 6e6, 2e7)],
    "half_chord": lambda rng: [real(rng, -0.1, 3.3), real(rng, -0.1, 3.3), real(rng, -0.1, 1.7)],
    "scan_frame_from_mounting": lambda rng: [real(rng, -1.7, 1.7), real(rng, -7, 7)],
    "direction_in_scan_frame": lambda rng: [mounted_frames(rng), real(rng, -4, 4),
                                            real(rng, -7, 7)],
    "scan_angles_of": lambda rng: [mounted_frames(rng), vectors(rng, 3.0)],
    "nominal_nadir_angle": lambda rng: [mounted_frames(rng)],
    "bias_model_crossings": lambda rng: optics(rng, 0.1) + [
        real(rng, 0, np.pi), real(rng, -7, 7), real(rng, 0.3, 1.4)],
    "scan_model_crossings_sphere": lambda rng: optics(rng, 0.3) + [
        real(rng, 0, np.pi), real(rng, -7, 7), real(rng, 0.3, 1.4)],
    "scan_model_crossings_ellipsoid": lambda rng: optics(rng, 0.3) + [
        rotated_frames(rng), vectors(rng, 7.5e6) * rng.uniform(0.8, 1.6, (ROWS, 1)),
        6378137 + real(rng, -1e4, 5e4), 6356752 + real(rng, -1e4, 5e4)],
    "with_crossing_noise": lambda rng: measured(rng) + [
        real(rng, -0.5, 0.5), real(rng, -0.5, 0.5), status_codes(rng)],
    "quantised": lambda rng: measured(rng) + [
        rng.choice([0.0, 1e-3, 0.07, -1e-3, np.nan, np.inf], ROWS), status_codes(rng)],
    "nadir_angle_roots_from_chord": lambda rng: [
        real(rng, -0.1, 1.7), real(rng, -0.1, 1.7), real(rng, -0.1, 3.3)],
    "nadir_angle_from_chord": lambda rng: [
        real(rng, -0.1, 1.7), real(rng, -0.1, 1.7), real(rng, -0.1, 3.3), real(rng, 0, 3.2)],
    "process_head": lambda rng: [mounted_frames(rng), real(rng, 0.2, 1.3), real(rng, 0.4, 1.4)] +
    measured(rng) + [status_codes(rng)],
    "roll_pitch_from_nadir": lambda rng: [vectors(rng, 2.0)],
    "nadir_in_body": lambda rng: [real(rng, -4, 4), real(rng, -4, 4)],
    "dcm_body_from_orbit": lambda rng: [real(rng, -4, 4), real(rng, -4, 4), real(rng, -7, 7)],
    "dcm_eci_from_orbit": lambda rng: [vectors(rng, 7e6), vectors(rng, 7.5e3)],
}

FUNCTIONS = sorted(name for name in conescan.__all__
                   if type(getattr(conescan, name)).__name__ == "builtin_function_or_method")


def test_every_binding_has_inputs_here():
    assert sorted(INPUTS) == FUNCTIONS


@pytest.mark.parametrize("name", FUNCTIONS)
def test_bit_for_bit_with_cpp(name, reference):
    rng = np.random.default_rng(sum(map(ord, name)))
    inputs = INPUTS[name](rng)
    result = getattr(conescan, name)(*inputs)
    columns, real_column = flat_rows(result, ROWS)
    expected = reference(name, inputs)
    assert len(expected) == ROWS and all(len(row) == len(columns) for row in expected)
    for k, (column, is_real) in enumerate(zip(columns, real_column)):
        tokens = [row[k] for row in expected]
        if is_real:
            want = np.array([float.fromhex(t) for t in tokens])
            agree = same_bits(column, want)
        else:
            want = np.array([int(t) for t in tokens])
            agree = column.astype(np.int64) == want
        if not agree.all():
            i = int(np.argmin(agree))
            row_inputs = [np.asarray(arg)[i].tolist() for arg in inputs]
            pytest.fail(f"{name}: column {k} of the result differs at row {i}: Python "
                        f"{column[i]!r}, C++ {want[i]!r}; inputs {row_inputs}")
    statuses = [f for f, field in zip(result, getattr(result, "_fields", ())) if field == "status"]
    for status in statuses:  # the inputs reach both sides of the domain
        assert {conescan.Status.ok, conescan.Status.invalid} <= set(np.unique(status).tolist())
        assert status.max() < len(conescan.status_names)


def test_status_names_match_to_string(reference_program):
    names = subprocess.run([reference_program, "status_names"], text=True, capture_output=True,
                           check=True).stdout.split()
    assert tuple(names) == conescan.status_names
    assert [s.name for s in conescan.Status] == names
    assert [int(s) for s in conescan.Status] == list(range(len(names)))

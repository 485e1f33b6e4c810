"""Broadcasting and dtype rules: every layout NumPy can hand over gives, element by element, the
bits of the plain one-dimensional call (which test_agreement.py holds to the C++ core)."""
import numpy as np
import pytest

import conescan
from conftest import same_bits

RNG = np.random.default_rng(18)
DEG = np.pi / 180


def paper_geometry(n):
    """psi, eta, rho around the paper's head: mostly ok, some miss and engulfed."""
    return (RNG.uniform(40, 50, n) * DEG, RNG.uniform(60, 120, n) * DEG,
            RNG.uniform(55, 75, n) * DEG)


def assert_same(actual, expected):
    """Same named tuple (or array), same shapes and dtypes, same bits."""
    if isinstance(expected, tuple):
        assert type(actual) is type(expected)
        for a, e in zip(actual, expected):
            assert_same(a, e)
        return
    actual, expected = np.asarray(actual), np.asarray(expected)
    assert actual.shape == expected.shape and actual.dtype == expected.dtype
    if actual.dtype == np.float64:
        assert same_bits(actual, expected).all()
    else:
        assert np.array_equal(actual, expected)


def elementwise(function, *args):
    """The plain call on broadcast, flattened copies, reshaped to the broadcast shape, as the
    result of the vectorised call must be."""
    shape = np.broadcast_shapes(*(np.shape(a) for a in args))
    flat = [np.ascontiguousarray(np.broadcast_to(a, shape)).ravel() for a in args]
    result = function(*flat)
    return type(result)(*(np.asarray(f).reshape(shape + np.shape(f)[1:]) for f in result))


def test_scalars_in_numpy_scalars_out():
    r = conescan.half_chord(45.02 * DEG, 90 * DEG, 64 * DEG)
    assert type(r.value) is np.float64 and type(r.status) is np.uint8
    assert r.status == conescan.Status.ok
    one = conescan.half_chord(*(np.array([x]) for x in (45.02 * DEG, 90 * DEG, 64 * DEG)))
    assert r.value == one.value[0]


@pytest.mark.parametrize("shapes", [
    [(5,), (), ()],
    [(3, 1), (1, 4), ()],
    [(2, 1, 4), (3, 1), (4,)],
    [(2, 3, 1, 2, 2), (1, 2, 1), (3, 1, 1, 1)],  # five loop dimensions: the odometer
    [(0,), (), (1,)],
    [(4, 0), (4, 1), ()],
])
def test_broadcast_shapes(shapes):
    psi, eta, rho = paper_geometry(1)
    args = [np.broadcast_to(x, s).copy() + RNG.uniform(-1e-3, 1e-3, s) if s else x[0]
            for x, s in zip((psi, eta, rho), shapes)]
    r = conescan.half_chord(*args)
    assert r.value.shape == np.broadcast_shapes(*shapes)
    assert_same(r, elementwise(conescan.half_chord, *args))


def test_layouts_numpy_hands_over():
    """Strided, transposed, zero-stride (broadcast_to), unaligned, big-endian and read-only
    arrays, and lists, all give the contiguous result."""
    psi, eta, rho = (x.reshape(6, 4) for x in paper_geometry(24))
    expected = conescan.half_chord(psi, eta, rho)
    unaligned = np.frombuffer(b"\0" + rho.tobytes(), dtype=np.float64, offset=1).reshape(6, 4)
    assert not unaligned.flags.aligned
    readonly = eta.copy()
    readonly.flags.writeable = False
    for args in [
        (np.asfortranarray(psi), eta.T.copy().T, rho),
        (psi, readonly, unaligned),
        (psi.astype(">f8"), eta, rho.tolist()),
    ]:
        assert_same(conescan.half_chord(*args), expected)
    wide = np.empty((6, 8))
    wide[:, ::2] = psi
    assert_same(conescan.half_chord(wide[:, ::2], eta, rho), expected)
    zero_stride = np.broadcast_to(eta[0], (6, 4))
    assert zero_stride.strides[0] == 0
    assert_same(conescan.half_chord(psi[0], zero_stride, rho[0]),
                elementwise(conescan.half_chord, psi[0], zero_stride, rho[0]))


def test_vector_and_frame_core_dimensions():
    alpha, beta = RNG.uniform(-1, 1, (2, 1)), RNG.uniform(-3, 3, 5)
    f = conescan.scan_frame_from_mounting(alpha, beta)
    assert f.frame.shape == (2, 5, 3, 3) and f.status.shape == (2, 5)
    v = RNG.normal(size=(7, 1, 1, 3))
    angles = conescan.scan_angles_of(f.frame, v)
    assert angles.polar.shape == (7, 2, 5)
    for i, j, k in [(0, 0, 0), (6, 1, 4), (3, 0, 2)]:
        one = conescan.scan_angles_of(f.frame[j, k][np.newaxis], v[i, 0, 0][np.newaxis])
        assert angles.polar[i, j, k] == one.polar[0] and angles.azimuth[i, j, k] == one.azimuth[0]
    # A vector argument of the right core shape, with the frame's core stride not contiguous.
    frames_f = np.asfortranarray(f.frame.reshape(10, 3, 3))
    assert_same(conescan.nominal_nadir_angle(frames_f),
                conescan.nominal_nadir_angle(f.frame.reshape(10, 3, 3).copy()))
    # Results with core dimensions of their own.
    assert conescan.nadir_in_body(RNG.uniform(size=(4, 1)), RNG.uniform(size=3)).shape == (4, 3, 3)
    assert conescan.dcm_body_from_orbit(0.1, 0.2, np.zeros((2, 5))).shape == (2, 5, 3, 3)
    assert conescan.nadir_in_body(0.1, 0.2).shape == (3,)
    assert conescan.roll_pitch_from_nadir(np.zeros((0, 3))).roll.shape == (0,)


def test_result_dtypes():
    c = conescan.scan_model_crossings_sphere(45 * DEG, 0.02 * DEG, 0.0, 90 * DEG, 0.0,
                                             np.array([64 * DEG]))
    assert [np.asarray(x).dtype for x in c] == [np.float64, np.float64, np.uint8, np.int32]
    assert c._fields == ("phi_in", "phi_out", "status", "iterations")
    assert c.iterations[0] == 0  # the sphere's crossings are in closed form


@pytest.mark.parametrize("dtype", [np.float32, np.float16, np.int32, np.int64, np.uint8, bool])
def test_real_dtypes_numpy_casts_safely_are_converted(dtype):
    x = np.array([1, 0, 2, 3]).astype(dtype)
    assert_same(conescan.nadir_in_body(x, x), conescan.nadir_in_body(x.astype(np.float64),
                                                                      x.astype(np.float64)))


def test_float32_values_are_taken_exactly():
    psi32 = np.float32(45.02 * DEG)
    r = conescan.half_chord(psi32, 90 * DEG, 64 * DEG)
    assert r.value == conescan.half_chord(float(psi32), 90 * DEG, 64 * DEG).value


@pytest.mark.parametrize("dtype", [np.int8, np.int64, np.uint16, bool])
def test_status_arguments_take_integers(dtype):
    codes = np.array([0, 1, 0, 1]).astype(dtype)
    c = conescan.quantised(np.full(4, -1.0), np.full(4, 1.0), 0.0, codes)
    assert c.status.tolist() == [0, 1, 0, 1]


def test_keywords_and_defaults():
    f = conescan.scan_frame_from_mounting(0.0, 90 * DEG).frame
    h = conescan.process_head(frame=f, gamma=45 * DEG, rho_p=64 * DEG, phi_in=-1.2, phi_out=1.2)
    assert h.status == conescan.Status.ok
    same = conescan.process_head(f, 45 * DEG, 64 * DEG, -1.2, 1.2, conescan.Status.ok)
    assert_same(h, same)
    assert_same(conescan.half_chord(rho=1.0, psi=0.8, eta=1.5), conescan.half_chord(0.8, 1.5, 1.0))

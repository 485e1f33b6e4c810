#!/usr/bin/python3
"""The paper's scene (MODEL §8) as a straightforward NumPy program: the yardstick that
bench/cli_speed.sh compares conescan-sim with. Same model and columns as conescan-sim
(MODEL §3-§6, §9): two-body Kepler orbit, geodetic latitude and altitude on WGS84, the bias model's
stable closed forms, the chord inversion (root nearest eta0), roll and pitch; the whole time
series is computed as arrays, then written with numpy.savetxt in shortest round-trip form (%r).

Usage: /usr/bin/python3 bench/numpy_paper_scene.py [STEP_S [ORBITS]] > /dev/null
"""
import sys

import numpy as np

# The paper's scene and WGS84 (MODEL §3, §8).
A_M, E, I_DEG = 7280e3, 0.1, 97.7
WGS84_A, WGS84_F, GM = 6378137.0, 1 / 298.257223563, 3.986004418e14
WGS84_B = WGS84_A * (1 - WGS84_F)
GAMMA, SIGMA, PHI_A = np.radians(45.0), np.radians(0.02), 0.0
ALPHA, BETA = 0.0, np.radians(90.0)


def kepler(mean_anomaly, e):
    """E - e sin E = M by Newton, all rows at once."""
    ecc = mean_anomaly.copy()
    for _ in range(8):
        ecc -= (ecc - e * np.sin(ecc) - mean_anomaly) / (1 - e * np.cos(ecc))
    return ecc


def geodetic(x, y, z):
    """Geodetic latitude and height on WGS84 by fixed-point iteration (converged to < 1 mm)."""
    e2 = WGS84_F * (2 - WGS84_F)
    p = np.hypot(x, y)
    lat = np.arctan2(z, p * (1 - e2))
    for _ in range(5):
        n = WGS84_A / np.sqrt(1 - e2 * np.sin(lat) ** 2)
        h = p / np.cos(lat) - n
        lat = np.arctan2(z, p * (1 - e2 * n / (n + h)))
    n = WGS84_A / np.sqrt(1 - e2 * np.sin(lat) ** 2)
    return lat, p / np.cos(lat) - n


def main():
    step_s = float(sys.argv[1]) if len(sys.argv) > 1 else 10.0
    orbits = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0
    n = np.sqrt(GM / A_M**3)
    duration = orbits * 2 * np.pi / n
    t = np.arange(int(np.floor(duration / step_s)) + 1) * step_s
    t = t[t <= duration]

    ecc = kepler(np.remainder(n * t, 2 * np.pi), E)
    r = A_M * (1 - E * np.cos(ecc))
    nu = 2 * np.arctan2(np.sqrt(1 + E) * np.sin(ecc / 2), np.sqrt(1 - E) * np.cos(ecc / 2))
    inc = np.radians(I_DEG)
    x, y, z = r * np.cos(nu), r * np.sin(nu) * np.cos(inc), r * np.sin(nu) * np.sin(inc)
    lat, alt = geodetic(x, y, z)
    rho = np.arcsin(WGS84_A / r)

    # The head: spin axis S = (cos a cos b, cos a sin b, sin a); zero attitude, so the nadir is
    # at eta = 90 deg - alpha, azimuth 0 about S.
    eta = np.pi / 2 - ALPHA
    h = np.sin(SIGMA) * np.cos(-PHI_A)
    psi = np.arctan2(h, np.cos(SIGMA)) + np.arccos(np.cos(GAMMA) / np.hypot(np.cos(SIGMA), h))
    p1 = np.sin((rho + psi - eta) / 2) * np.sin((rho - psi + eta) / 2)
    p2 = np.sin((psi + eta + rho) / 2) * np.sin((psi + eta - rho) / 2)
    half_chord = 2 * np.arctan2(np.sqrt(p1), np.sqrt(p2))
    k = np.sin(GAMMA) * np.cos(half_chord)
    delta = np.arctan2(k, np.cos(GAMMA))
    spread = np.arccos(np.cos(rho) / np.hypot(np.cos(GAMMA), k))
    plus, minus = delta + spread, delta - spread
    eta_s = np.where(np.abs(plus - eta) <= np.abs(minus - eta), plus, minus)
    e1 = np.array([-np.sin(ALPHA) * np.cos(BETA), -np.sin(ALPHA) * np.sin(BETA), np.cos(ALPHA)])
    e3 = np.array([np.cos(ALPHA) * np.cos(BETA), np.cos(ALPHA) * np.sin(BETA), np.sin(ALPHA)])
    nadir = np.outer(np.cos(eta_s), e3) + np.outer(np.sin(eta_s), e1)  # phase 0
    roll = np.arctan2(nadir[:, 1], nadir[:, 2])
    pitch = np.arctan2(-nadir[:, 0], np.hypot(nadir[:, 1], nadir[:, 2]))

    deg = np.degrees
    table = np.empty((t.size, 15), dtype=object)
    columns = [t, np.remainder(deg(nu), 360), r / 1000, alt / 1000, deg(lat), deg(rho),
               deg(2 * half_chord), np.zeros_like(t), deg(eta_s - eta), deg(roll), deg(pitch),
               None, deg(roll), deg(pitch), None]
    for j, column in enumerate(columns):
        table[:, j] = "ok" if column is None else column
    fmt = ["%r"] * 11 + ["%s"] + ["%r"] * 2 + ["%s"]
    header = ("t_s,nu_deg,r_km,alt_km,lat_deg,rho_deg,h1_chord_deg,h1_phase_deg,h1_eta_err_deg,"
              "h1_roll_err_deg,h1_pitch_err_deg,h1_status,roll_err_deg,pitch_err_deg,status")
    np.savetxt(sys.stdout, table, fmt=fmt, delimiter=",", header=header, comments="")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Rotations into the true equator and equinox of date by other routes: the oracle of
tests/sources/test_scene_frame.cpp.

Usage: /usr/bin/python3 frames_oracle.py SEED COUNT

Draws COUNT instants, uniform in TAI over 1960-01-02 .. 2099-12-30 (a fixed seed), and for each
writes the matrices M (row-major, r_tod = M r) of GCRF, EME2000, TEME and ITRF into TOD, built
by python3-erfa (Debian's bindings of the same liberfa) along routes that src/sources/scene_frame.cpp
does not take:
  GCRF     CIO-based: the GCRS-to-CIRS matrix from the X, Y series (eraXy06, not the
           Fukushima-Williams angles of eraPnm06a), then R3(EO) from CIRS to TOD with the
           equation of the origins EO = ERA - GST = -(GMST06 - ERA) - EqE06a (IERS
           Conventions 2010, Eq. 5.31: alpha_TOD = alpha_CIRS - EO);
  EME2000  that times the IAU 2000 frame bias transposed (eraBp00's rb, not eraPn06's);
  TEME     R3(-(GST06a - GMST06)): the equation of the equinoxes as a difference of sidereal
           times (not eraEe00's series);
  ITRF     the GCRF matrix above times the transpose of GCRS-to-ITRS by the CIO route
           (eraC2i06a, then R3(ERA); no polar motion, as conescan takes it), UT1 = UTC.
Output, one record a line (repr: round-trip exact):
  TIME <TAI MJD> <TAI seconds of day>
  <FRAME> m00 m01 m02 m10 m11 m12 m20 m21 m22
"""
import random
import sys
import warnings

import erfa
import numpy as np

warnings.simplefilter('ignore')  # "dubious year" after ERFA's leap-second table, as conescan

FIRST_MJD = 36935  # 1960-01-02
LAST_MJD = 88067   # 2099-12-30
DJM0 = 2400000.5


def rz(angle):
    """R3(angle), the frame rotation about z."""
    return erfa.rz(angle, np.eye(3))


def matrices(tai_mjd, tai_seconds):
    tai1, tai2 = DJM0 + tai_mjd, tai_seconds / 86400.0
    tt1, tt2 = erfa.taitt(tai1, tai2)
    utc1, utc2 = erfa.taiutc(tai1, tai2)
    ut11, ut12 = erfa.utcut1(utc1, utc2, 0.0)
    x, y = erfa.xy06(tt1, tt2)
    gcrs_to_cirs = erfa.c2ixys(x, y, erfa.s06(tt1, tt2, x, y))
    era = erfa.era00(ut11, ut12)
    equation_of_equinoxes = erfa.ee06a(tt1, tt2)
    eo = -(erfa.gmst06(ut11, ut12, tt1, tt2) - era) - equation_of_equinoxes
    tod_from_gcrf = rz(eo) @ gcrs_to_cirs
    rb, _, _ = erfa.bp00(tt1, tt2)
    tod_from_eme2000 = tod_from_gcrf @ rb.T
    eqe_by_sidereal_times = erfa.gst06a(ut11, ut12, tt1, tt2) - erfa.gmst06(ut11, ut12, tt1, tt2)
    tod_from_teme = rz(-eqe_by_sidereal_times)
    itrf_from_gcrs = erfa.c2tcio(erfa.c2i06a(tt1, tt2), era, np.eye(3))
    tod_from_itrf = tod_from_gcrf @ itrf_from_gcrs.T
    return [('GCRF', tod_from_gcrf), ('EME2000', tod_from_eme2000), ('TEME', tod_from_teme),
            ('ITRF', tod_from_itrf)]


def main():
    seed, count = int(sys.argv[1]), int(sys.argv[2])
    rng = random.Random(seed)
    for _ in range(count):
        tai_mjd = rng.randrange(FIRST_MJD, LAST_MJD)
        tai_seconds = rng.uniform(0.0, 86400.0)
        print('TIME %d %r' % (tai_mjd, tai_seconds))
        for name, m in matrices(tai_mjd, tai_seconds):
            print(name + ' ' + ' '.join(repr(float(v)) for v in m.flatten()))


if __name__ == '__main__':
    main()

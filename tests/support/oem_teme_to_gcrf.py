#!/usr/bin/python3
"""A TEME OEM turned into a GCRF OEM with python3-erfa, independently of conescan's frames.

Usage: /usr/bin/python3 oem_teme_to_gcrf.py IN.oem OUT.oem

Each state (UTC epochs, km, km/s) goes TEME -> TOD by the equation of the equinoxes (eraEe06a),
then TOD -> GCRF by the transpose of the bias-precession-nutation matrix (eraPnm06a, IAU
2006/2000A): r_gcrf = rbpn^T Rz(-EqE) r_teme, the velocity alike (the frames' own turning,
~1e-11 rad/s, neglected as MODEL §10 does). conescan's src/sources/scene_frame.cpp takes another
route (eraPn06 from one nutation call, eraEe00 with its obliquity). Every other line is copied,
REF_FRAME TEME becomes GCRF; numbers are written with repr (round-trip exact).
"""
import sys

import erfa
import numpy as np


def tt_of(epoch):
    """TT two-part Julian date of an OEM epoch in UTC (YYYY-MM-DDThh:mm:ss.f)."""
    date, time = epoch.split('T')
    year, month, day = (int(x) for x in date.split('-'))
    hour, minute, second = time.split(':')
    utc1, utc2 = erfa.dtf2d('UTC', year, month, day, int(hour), int(minute), float(second))
    tai1, tai2 = erfa.utctai(utc1, utc2)
    return erfa.taitt(tai1, tai2)


def gcrf_from_teme(epoch):
    tt1, tt2 = tt_of(epoch)
    tod_from_teme = erfa.rz(-erfa.ee06a(tt1, tt2), np.identity(3))
    tod_from_gcrf = erfa.pnm06a(tt1, tt2)
    return tod_from_gcrf.T @ tod_from_teme


def main():
    source, target = sys.argv[1], sys.argv[2]
    out = []
    in_data = False
    for line in open(source).read().splitlines():
        if line.replace(' ', '') == 'REF_FRAME=TEME':
            out.append('REF_FRAME = GCRF')
            continue
        fields = line.split()
        if line == 'META_STOP':
            in_data = True
        elif in_data and len(fields) == 7:
            m = gcrf_from_teme(fields[0])
            r = m @ np.array([float(x) for x in fields[1:4]])
            v = m @ np.array([float(x) for x in fields[4:7]])
            line = ' '.join([fields[0]] + [repr(float(x)) for x in list(r) + list(v)])
        out.append(line)
    open(target, 'w').write('\n'.join(out) + '\n')


if __name__ == '__main__':
    main()

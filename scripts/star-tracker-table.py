#!/usr/bin/python3
"""A star tracker's quaternion table from an AEM that conescan-sim --write-aem wrote.

Usage: /usr/bin/python3 scripts/star-tracker-table.py IN.aem OUT.csv

IN.aem: conescan's AEM, REF_FRAME_A TOD (the scene frame), A2B, QUATERNION_TYPE LAST. OUT.csv:
utc,q_w,q_x,q_y,q_z, the same attitude inertial -> body relative to EME2000 (the J2000 a star
tracker reports), as conescan-sim --attitude-csv reads it with --attitude-frame EME2000:
A_body_eme2000 = A_body_tod N P, with N P the nutation and precession matrices of python3-erfa's
eraPn06a at each row's TT (the frame's bias left out: EME2000 is the mean J2000 dynamical frame).
Numbers in repr (round-trip exact). Made data/satellite/star-tracker.csv (data/satellite/README.md).
"""
import sys

import erfa
import numpy as np


def attitude_matrix(q1, q2, q3, qc):
    """Shuster's A(Q) (CCSDS 504.0-B): v_B = A v_A."""
    q = np.array([q1, q2, q3])
    cross = np.array([[0, -q3, q2], [q3, 0, -q1], [-q2, q1, 0]])
    return (qc * qc - q @ q) * np.identity(3) + 2 * np.outer(q, q) - 2 * qc * cross


def quaternion_of(a):
    """(qc, q1, q2, q3), qc >= 0, of an attitude matrix (Shepperd: from the largest component)."""
    d = [np.trace(a), a[0, 0], a[1, 1], a[2, 2]]
    k = int(np.argmax(d))
    if k == 0:
        qc = 0.5 * np.sqrt(1 + d[0])
        q = (qc, (a[1, 2] - a[2, 1]) / (4 * qc), (a[2, 0] - a[0, 2]) / (4 * qc),
             (a[0, 1] - a[1, 0]) / (4 * qc))
    elif k == 1:
        q1 = 0.5 * np.sqrt(1 + a[0, 0] - a[1, 1] - a[2, 2])
        q = ((a[1, 2] - a[2, 1]) / (4 * q1), q1, (a[0, 1] + a[1, 0]) / (4 * q1),
             (a[0, 2] + a[2, 0]) / (4 * q1))
    elif k == 2:
        q2 = 0.5 * np.sqrt(1 - a[0, 0] + a[1, 1] - a[2, 2])
        q = ((a[2, 0] - a[0, 2]) / (4 * q2), (a[0, 1] + a[1, 0]) / (4 * q2), q2,
             (a[1, 2] + a[2, 1]) / (4 * q2))
    else:
        q3 = 0.5 * np.sqrt(1 - a[0, 0] - a[1, 1] + a[2, 2])
        q = ((a[0, 1] - a[1, 0]) / (4 * q3), (a[0, 2] + a[2, 0]) / (4 * q3),
             (a[1, 2] + a[2, 1]) / (4 * q3), q3)
    return q if q[0] >= 0 else tuple(-x for x in q)


def tod_from_eme2000(epoch):
    date, time = epoch.split('T')
    year, month, day = (int(x) for x in date.split('-'))
    hour, minute, second = time.split(':')
    utc1, utc2 = erfa.dtf2d('UTC', year, month, day, int(hour), int(minute), float(second))
    tt1, tt2 = erfa.taitt(*erfa.utctai(utc1, utc2))
    rn, rp = erfa.pn06a(tt1, tt2)[6], erfa.pn06a(tt1, tt2)[4]
    return rn @ rp


def main():
    rows = ['utc,q_w,q_x,q_y,q_z']
    in_data = False
    for line in open(sys.argv[1]).read().splitlines():
        if line == 'DATA_STOP':
            in_data = False
        if in_data and line.strip():
            epoch, q1, q2, q3, qc = line.split()
            a = attitude_matrix(float(q1), float(q2), float(q3), float(qc)) @ \
                tod_from_eme2000(epoch)
            w, x, y, z = quaternion_of(a)
            rows.append(','.join([epoch[:19]] + [repr(float(v)) for v in (w, x, y, z)]))
        if line == 'DATA_START':
            in_data = True
    open(sys.argv[2], 'w').write('\n'.join(rows) + '\n')


if __name__ == '__main__':
    main()

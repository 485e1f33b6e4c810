#!/usr/bin/python3
"""Random element sets propagated by python-sgp4, the oracle of tests/orbit/test_sgp4_oracle.cpp.

Usage: /usr/bin/python3 sgp4_oracle.py SEED COUNT

Writes COUNT random but well-formed TLEs (checksums included) covering SGP4's branches: low
orbits with drag (perigees from below 98 km to 1000 km, the simplified-drag and s-modified
cases), deep space with and without the 12-hour and 24-hour resonances, inclinations near 0
(Lyddane's modification) and 180 deg, eccentricities from 0 to 0.95, epochs 1957-2056. Each
set is followed by states at random times within +-10 days, in both of Vallado's operation
modes: 'i' (improved; sgp4.api.Satrec) and 'a' (AFSPC; the legacy sgp4.io.twoline2rv path).

Output, one record a line:
  TLE <line 1>
  TLE <line 2>
  STATE <mode i|a> <t min> <error code> <x y z km> <vx vy vz km/s>   (repr, round-trip exact)

Debian's python3-sgp4 2.15 is pure Python (no C++ extension), an implementation independent
of src/orbit/sgp4.cpp.
"""
import math
import random
import sys

from sgp4 import io, propagation
from sgp4.api import Satrec
from sgp4.earth_gravity import wgs72

MU = 398600.8  # WGS-72, km^3/s^2
RE = 6378.135  # km


def checksum(line):
    return sum(int(c) if c.isdigit() else c == '-' for c in line[:68]) % 10


def exponential(value_mantissa, exponent):
    """' 12345-6' for +0.12345e-6: a signed 5-digit mantissa and a one-digit exponent."""
    sign = '-' if value_mantissa < 0 else ' '
    return '%s%05d%s%d' % (sign, abs(value_mantissa), '-' if exponent < 0 else '+',
                           abs(exponent))


def mean_motion_for(rng, kind):
    """rev/day of an orbit of the given kind, and a fitting eccentricity."""
    if kind == 'leo':
        perigee_km = rng.choice([rng.uniform(80, 160), rng.uniform(160, 240),
                                 rng.uniform(240, 1000)])
        e = rng.choice([0.0, rng.uniform(0, 1e-4), rng.uniform(0, 0.02), rng.uniform(0, 0.2)])
        a = (RE + perigee_km) / (1 - e)
    elif kind == 'geo':  # the 24-hour resonance: 0.8 .. 1.2 rev/day
        return rng.uniform(0.85, 1.15), rng.choice([rng.uniform(0, 0.01), rng.uniform(0, 0.3)])
    elif kind == 'half_day':  # the 12-hour resonance: 1.9 .. 2.1 rev/day, e >= 0.5
        return rng.uniform(1.90, 2.11), rng.uniform(0.5, 0.8)
    else:  # deep space without resonance
        period_min = rng.uniform(226, 8000)
        a = (MU * (period_min * 60 / (2 * math.pi)) ** 2) ** (1 / 3)
        e = rng.uniform(0, min(0.95, 1 - (RE + 200) / a)) if a > RE + 200 else 0.0
    n = 86400 / (2 * math.pi * math.sqrt(a ** 3 / MU))
    return n, e


def random_tle(rng, number):
    kind = rng.choice(['leo', 'leo', 'deep', 'geo', 'half_day'])
    n, e = mean_motion_for(rng, kind)
    inclination = rng.choice([rng.uniform(0, 180), rng.uniform(0, 11), rng.uniform(175, 180),
                              rng.uniform(62, 65), 0.0])
    year = rng.randint(1957, 2056)
    leap = year % 4 == 0 and (year % 100 != 0 or year % 400 == 0)
    day = rng.uniform(1, 366 if leap else 365)
    ndot = rng.uniform(-1e-3, 1e-3)
    nddot = exponential(rng.randint(-99999, 99999), rng.randint(-9, 0))
    bstar = exponential(rng.choice([0, rng.randint(-99999, 99999)]), rng.randint(-7, -1))
    ndot_text = ('%.8f' % ndot).replace('0.', '.')
    line1 = '1 %05dU 20001A   %02d%012.8f %10s %s %s 0 %4d' % (
        number, year % 100, day, ndot_text.rjust(10), nddot, bstar, rng.randint(0, 9999))
    line2 = '2 %05d %8.4f %8.4f %07d %8.4f %8.4f %11.8f%5d' % (
        number, inclination, rng.uniform(0, 360), round(e * 1e7), rng.uniform(0, 360),
        rng.uniform(0, 360), n, rng.randint(0, 99999))
    return line1 + str(checksum(line1)), line2 + str(checksum(line2))


def write_state(mode, t, error, r, v):
    print('STATE', mode, repr(t), error, *(repr(float(x)) for x in (*r, *v)))


def main():
    seed, count = int(sys.argv[1]), int(sys.argv[2])
    rng = random.Random(seed)
    for k in range(count):
        line1, line2 = random_tle(rng, 10000 + k)
        print('TLE', line1)
        print('TLE', line2)
        improved = Satrec.twoline2rv(line1, line2)
        afspc = io.twoline2rv(line1, line2, wgs72, opsmode='a')
        for t in [0.0] + [rng.uniform(-14400, 14400) for _ in range(5)]:
            error, r, v = improved.sgp4_tsince(t)
            write_state('i', t, error, r, v)
            r, v = propagation.sgp4(afspc, t)
            write_state('a', t, afspc.error, r, v)


if __name__ == '__main__':
    main()

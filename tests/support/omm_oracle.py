#!/usr/bin/python3
"""python-sgp4's own OMM reader (sgp4.omm) as the oracle of tests/orbit/test_omm.cpp.

Usage: /usr/bin/python3 omm_oracle.py DIR

Writes into DIR the 33 element sets of Vallado's SGP4-VER.TLE (shipped with python-sgp4) as
OMMs in four formats, every number in Python's repr (exact, shortest round trip):
  ver.xml   CCSDS OMM XML, an <ndm> of 33 <omm> (as CelesTrak's FORMAT=XML)
  ver.csv   CelesTrak's CSV (the header of python-sgp4's sample_omm.csv)
  ver.json  CelesTrak's JSON, an array of 33 objects
  ver.kvn   33 CCSDS OMM KVN messages, one after the other
The fields are those of python-sgp4's exporter.export_omm (the designator "UNKNOWN" where the
TLE has none, which export_omm cannot convert).

Then prints, for python-sgp4's sample_omm.xml and sample_omm.csv and for ver.xml and ver.csv,
each set as python-sgp4 reads it (omm.parse_xml / omm.parse_csv, omm.initialize) and its states
(improved mode, sgp4_tsince), one record a line:
  SET <path> <index from 0>
  STATE <t min> <error code> <x y z km> <vx vy vz km/s>     (repr, round-trip exact)
Times: the samples every 6 h over 7 days; the SGP4-VER sets at the start, stop and step their
line 2 gives (as Vallado's tcppver.out), at most 40 a set.

Debian's python3-sgp4 2.15 is pure Python, an implementation independent of src/orbit/.
"""
import json
import math
import os
import sys

from sgp4 import omm
from sgp4.api import Satrec
from sgp4.conveniences import sat_epoch_datetime

SGP4_DIR = os.path.dirname(omm.__file__)
XPDOTP = 1440.0 / (2.0 * math.pi)
DEG = math.pi / 180.0
CSV_FIELDS = ['OBJECT_NAME', 'OBJECT_ID', 'EPOCH', 'MEAN_MOTION', 'ECCENTRICITY',
              'INCLINATION', 'RA_OF_ASC_NODE', 'ARG_OF_PERICENTER', 'MEAN_ANOMALY',
              'EPHEMERIS_TYPE', 'CLASSIFICATION_TYPE', 'NORAD_CAT_ID', 'ELEMENT_SET_NO',
              'REV_AT_EPOCH', 'BSTAR', 'MEAN_MOTION_DOT', 'MEAN_MOTION_DDOT']
METADATA = ['OBJECT_NAME', 'OBJECT_ID', 'CENTER_NAME', 'REF_FRAME', 'TIME_SYSTEM',
            'MEAN_ELEMENT_THEORY']
MEAN_ELEMENTS = ['EPOCH', 'MEAN_MOTION', 'ECCENTRICITY', 'INCLINATION', 'RA_OF_ASC_NODE',
                 'ARG_OF_PERICENTER', 'MEAN_ANOMALY']
TLE_PARAMETERS = ['EPHEMERIS_TYPE', 'CLASSIFICATION_TYPE', 'NORAD_CAT_ID', 'ELEMENT_SET_NO',
                  'REV_AT_EPOCH', 'BSTAR', 'MEAN_MOTION_DOT', 'MEAN_MOTION_DDOT']


def text(value):
    return repr(value) if isinstance(value, float) else str(value)


def fields_of(sat):
    """export_omm's fields, every value as text."""
    designator = sat.intldesg.strip()
    if designator:
        year = int(designator[:2])
        object_id = '%d-%s' % (year + (2000 if year < 57 else 1900), designator[2:])
    else:
        object_id = 'UNKNOWN'
    fields = {
        'OBJECT_NAME': 'SGP4-VER %05d' % sat.satnum, 'OBJECT_ID': object_id,
        'CENTER_NAME': 'EARTH', 'REF_FRAME': 'TEME', 'TIME_SYSTEM': 'UTC',
        'MEAN_ELEMENT_THEORY': 'SGP4',
        'EPOCH': sat_epoch_datetime(sat).strftime('%Y-%m-%dT%H:%M:%S.%f'),
        'MEAN_MOTION': sat.no_kozai * XPDOTP, 'ECCENTRICITY': sat.ecco,
        'INCLINATION': sat.inclo / DEG, 'RA_OF_ASC_NODE': sat.nodeo / DEG,
        'ARG_OF_PERICENTER': sat.argpo / DEG, 'MEAN_ANOMALY': sat.mo / DEG,
        'EPHEMERIS_TYPE': 0, 'CLASSIFICATION_TYPE': sat.classification or 'U',
        'NORAD_CAT_ID': sat.satnum, 'ELEMENT_SET_NO': sat.elnum, 'REV_AT_EPOCH': sat.revnum,
        'BSTAR': sat.bstar, 'MEAN_MOTION_DOT': sat.ndot * (XPDOTP * 1440.0),
        'MEAN_MOTION_DDOT': sat.nddot * (XPDOTP * 1440.0 * 1440),
    }
    return {k: text(v) for k, v in fields.items()}


def verification_sets():
    """(fields, times) of each set of SGP4-VER.TLE."""
    sets = []
    lines = open(os.path.join(SGP4_DIR, 'SGP4-VER.TLE')).read().splitlines()
    lines = [l for l in lines if l.startswith('1 ') or l.startswith('2 ')]
    for line1, line2 in zip(lines[0::2], lines[1::2]):
        sat = Satrec.twoline2rv(line1, line2[:69])
        start, stop, step = (float(x) for x in line2[69:].split()[:3])
        times = [start]
        while times[-1] + step <= stop + 1e-9 and len(times) < 40:
            times.append(times[-1] + step)
        sets.append((fields_of(sat), times))
    return sets


def write_formats(directory, sets):
    with open(os.path.join(directory, 'ver.csv'), 'w') as f:
        f.write(','.join(CSV_FIELDS) + '\n')
        for fields, _ in sets:
            f.write(','.join(fields[k] for k in CSV_FIELDS) + '\n')
    with open(os.path.join(directory, 'ver.json'), 'w') as f:
        objects = [{k: (float(v) if k in MEAN_ELEMENTS[1:] + ['BSTAR', 'MEAN_MOTION_DOT',
                                                              'MEAN_MOTION_DDOT'] else
                        int(v) if k in ('EPHEMERIS_TYPE', 'NORAD_CAT_ID', 'ELEMENT_SET_NO',
                                        'REV_AT_EPOCH') else v)
                    for k, v in fields.items() if k in CSV_FIELDS} for fields, _ in sets]
        json.dump(objects, f, indent=1)
    with open(os.path.join(directory, 'ver.kvn'), 'w') as f:
        for fields, _ in sets:
            f.write('CCSDS_OMM_VERS = 2.0\nCREATION_DATE = 2026-11-26T00:00:00\n'
                    'ORIGINATOR = conescan tests\n')
            for k in METADATA + MEAN_ELEMENTS + TLE_PARAMETERS:
                f.write('%s = %s\n' % (k, fields[k]))
    with open(os.path.join(directory, 'ver.xml'), 'w') as f:
        f.write('<?xml version="1.0" encoding="UTF-8"?>\n<ndm>\n')
        for fields, _ in sets:
            def block(tag, keys):
                return '<%s>%s</%s>' % (tag, ''.join('<%s>%s</%s>' % (k, fields[k], k)
                                                     for k in keys), tag)
            f.write('<omm id="CCSDS_OMM_VERS" version="2.0">\n<header><CREATION_DATE/>'
                    '<ORIGINATOR/></header>\n<body><segment>%s<data>%s%s</data></segment>'
                    '</body>\n</omm>\n' % (block('metadata', METADATA),
                                           block('meanElements', MEAN_ELEMENTS),
                                           block('tleParameters', TLE_PARAMETERS)))
        f.write('</ndm>\n')


def print_states(path, parsed, times_of):
    for index, fields in enumerate(parsed):
        sat = Satrec()
        omm.initialize(sat, fields)
        print('SET %s %d' % (path, index))
        for t in times_of(index):
            error, r, v = sat.sgp4_tsince(t)
            print('STATE %r %d %r %r %r %r %r %r' % ((t, error) + tuple(r) + tuple(v)))


def main():
    directory = sys.argv[1]
    sets = verification_sets()
    write_formats(directory, sets)
    week = [360.0 * k for k in range(29)]
    for name in ('sample_omm.xml', 'sample_omm.csv'):
        path = os.path.join(SGP4_DIR, name)
        with open(path) as f:
            parsed = list(omm.parse_xml(f) if name.endswith('.xml') else omm.parse_csv(f))
        print_states(path, parsed, lambda i: week)
    for name in ('ver.xml', 'ver.csv'):
        path = os.path.join(directory, name)
        with open(path) as f:
            parsed = list(omm.parse_xml(f) if name.endswith('.xml') else omm.parse_csv(f))
        print_states(path, parsed, lambda i: sets[i][1])


if __name__ == '__main__':
    main()

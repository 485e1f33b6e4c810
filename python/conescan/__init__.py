"""conescan from Python: the core of conescan (attitude errors of conical scanning Earth sensors)
over NumPy arrays, computed by the same C++ as the library and conescan-sim.

Every function broadcasts its arguments by NumPy's rules, as a ufunc does: angles in radians,
lengths in one unit per call. Vectors take a last dimension of 3, scan frames and direction
cosine matrices a last two of (3, 3) (a frame's rows are e1, e2, e3). Results are named tuples
of arrays; a status field holds integer codes (uint8) whose names are ``status_names`` (also the
IntEnum ``Status``): a value whose status is not ok is NaN. Bad values (NaN, out of range) give
status ``invalid``, as in C++; bad shapes raise ValueError, non-real dtypes TypeError.

>>> import numpy as np, conescan
>>> rho = np.arcsin(6378137.0 / 6552000.0)  # the paper's Earth disk at perigee
>>> r = conescan.half_chord(np.radians(45.02), np.radians([90.0, 170.0]), rho)
>>> np.degrees(r.value)
array([71.12435593,         nan])
>>> [conescan.status_names[s] for s in r.status]
['ok', 'miss']

The functions and their domains are those of the C++ core: docs/API.md.
"""
import enum

from . import _conescan
from ._conescan import *  # noqa: F401,F403  (the functions and result types; listed in __all__)
from ._conescan import __version__, status_names
from ._fit import FitNotConverged, fit, predict
from ._scenes import simulate, summary

#: The status codes as an IntEnum: ``result.status == Status.miss`` works on arrays.
Status = enum.IntEnum("Status", [(name, code) for code, name in enumerate(status_names)],
                      module=__name__)

__all__ = [name for name in dir(_conescan) if not name.startswith("_")] + [
    "Status", "simulate", "summary", "fit", "predict", "FitNotConverged"]

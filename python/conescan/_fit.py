"""conescan-fit from Python: conescan.fit and conescan.predict.

The scene options are conescan.simulate's (keyword arguments through the option table, or a
scene file as ``config``); the fit's own options are conescan-fit's (``free``, ``loss``,
``max_iterations``). The result is the dict of ``conescan-fit --json``'s object, made from the
text of the same C++ writer (src/calibration/fit_json.hpp), so it has its content and shape.
"""
import json
import os
from collections.abc import Mapping

import numpy as np

from . import _conescan
from ._scenes import _config_path, _option_texts, _value_text


class FitNotConverged(RuntimeError):
    """A fit that did not converge: conescan-fit prints its last state and exits 1, never an
    estimate. ``result`` is that JSON object as a dict (``converged`` False, ``iterations``,
    ``cost``, ``solver_message``, ``last_state``; no ``parameters``)."""

    def __init__(self, result):
        super().__init__(f"the fit did not converge after {result.get('iterations')} iterations: "
                         f"{result.get('solver_message')} (its last state is .result)")
        self.result = result


def _require_fit():
    if not hasattr(_conescan, "_fit"):
        raise RuntimeError("conescan was built without the scene layer "
                           "(-DCONESCAN_BUILD_APPS=OFF): fit and predict need it")


def _free_text(free):
    if isinstance(free, str):
        return free
    if isinstance(free, (list, tuple)) and all(isinstance(name, str) for name in free):
        return ",".join(free)
    raise TypeError(f"free: expected a list of parameter names, not {type(free).__name__}")


#: The time columns a telemetry may have (one kind: t_s, utc, or gps_week and gps_s), as the
#: reader takes them (src/calibration/telemetry.hpp); utc is text, the others numbers.
_TIME_COLUMNS = ("t_s", "utc", "gps_week", "gps_s")


def _telemetry_columns(telemetry):
    """([(name, list of str)], [(name, float64 array)]) of a mapping or structured array: its
    time columns (t_s, utc, gps_week, gps_s: every one given, the reader refuses two kinds) and
    every hK_chord_deg and hK_phase_deg it has (the reader checks that the scene's heads are all
    there)."""
    if isinstance(telemetry, np.ndarray):
        names = telemetry.dtype.names
    elif isinstance(telemetry, Mapping):
        names = list(telemetry)
    else:
        names = None
    if names is None:
        raise TypeError("telemetry: expected a file name, a mapping or a structured array, not "
                        f"{type(telemetry).__name__}")
    wanted = [name for name in names if isinstance(name, str) and (name in _TIME_COLUMNS or (
        name.startswith("h") and (name.endswith("_chord_deg") or name.endswith("_phase_deg"))))]
    texts, columns = [], []
    for name in wanted:
        if name == "utc":
            values = [str(v) for v in np.asarray(telemetry[name]).ravel()]
            if any(("," in v or "\n" in v or "\r" in v) for v in values):
                raise ValueError("telemetry: column utc holds a comma or a line end: not a time")
            texts.append((name, values))
            continue
        try:
            values = np.ascontiguousarray(telemetry[name], dtype=np.float64)
        except (TypeError, ValueError) as error:
            raise TypeError(f"telemetry: column {name} is not numbers: {error}") from None
        columns.append((name, values))
    lengths = [(name, len(values), np.ndim(values)) for name, values in texts] + \
              [(name, len(values), values.ndim) for name, values in columns]
    for name, length, ndim in lengths:
        if ndim != 1 or length != lengths[0][1]:
            raise ValueError(f"telemetry: column {name} is not 1-d of the length of "
                             f"{lengths[0][0]}")
    return texts, columns


def _fit_texts(free, telemetry_path=None, **settings):
    """The fit options' entries [(name, text)], as conescan-fit's command line would give them:
    free, each setting (its keyword with '-' for '_'), and the telemetry file when there is one.
    The values are checked by conescan-fit's own checks (a count of 1.5 or True is refused)."""
    texts = [("free", _free_text(free))]
    for keyword, value in settings.items():
        name = keyword.replace("_", "-")
        texts.append((name, _value_text(keyword, value)))
    if telemetry_path is not None:
        texts.append(("telemetry", telemetry_path))
    return texts


def fit(telemetry, free, loss="huber", max_iterations=100, config=None, **options):
    """``conescan-fit --telemetry FILE --free LIST --json`` with the scene's options, as a dict.

    ``telemetry``: a CSV file name (t_s and per head hK_chord_deg, hK_phase_deg; conescan-sim's
    CSV is one), or a mapping or structured array with those fields (what conescan.simulate
    returns; the time may be ``utc`` text or ``gps_week`` and ``gps_s`` instead of ``t_s``), read
    by the same reader with the same checks as a file (errors name the file "<array>").
    ``free``: the parameters to estimate, a list (``["h1.sigma", "h1.phase"]``) or conescan-fit's
    comma-separated text. ``loss``: "huber" or "none"; ``max_iterations``: [1, 10000]. Scene
    options as conescan.simulate. Bad input raises ValueError with conescan-fit's message, naming
    this function's own arguments as Python spells them (``max_iterations: '2.5' is not a count
    in [1, 10000]``) and the scene's options as the command line does.

    Returns the converged fit: {"kind": "fit", "converged": True, "parameters": {name:
    {"estimate", "sigma", "unit", "free"[, "withheld"]}}, "parameter_order", "correlation",
    "chi2_dof", "residual_rms_deg", "condition", "unobservable", "rank", "outliers", ...} (None
    where the JSON has null). A fit that does not converge raises FitNotConverged (a
    RuntimeError) holding its last state, as conescan-fit exits 1 without an estimate. The GIL is
    released while the telemetry is read and Ceres iterates.
    """
    _require_fit()
    path, texts, columns = None, [], []
    if isinstance(telemetry, (str, bytes, os.PathLike)):
        path = os.fsdecode(telemetry)
    else:
        texts, columns = _telemetry_columns(telemetry)
    fit_texts = _fit_texts(free, path, loss=loss, max_iterations=max_iterations)
    converged, text = _conescan._fit(_option_texts(options), _config_path(config), fit_texts,
                                     texts, columns, path is None)
    result = json.loads(text)
    if not converged:
        raise FitNotConverged(result)
    return result


def predict(free, config=None, **options):
    """``conescan-fit --predict --free LIST --json``: the 1 sigma each free parameter would reach
    for the scene as planned (its time grid, the heads' noise), as a dict {"kind": "design",
    "parameters", "parameter_order", "correlation", "condition", "unobservable", ...}. Options
    and errors as conescan.fit; the GIL is released while it is computed."""
    _require_fit()
    return json.loads(_conescan._predict(_option_texts(options), _config_path(config),
                                         _fit_texts(free)))

"""conescan-sim's scenes from Python: conescan.simulate and conescan.summary.

Keyword arguments are conescan-sim's options with '_' for '-' (``a_km=7000`` is ``--a-km 7000``);
each value becomes the text the option would be given on the command line, and the scene layer
reads and validates it as conescan-sim does (src/scene/scene_plan.hpp), so a bad value raises
ValueError with conescan-sim's message, naming the option as the command line spells it. Options
come from the C++ option table: an option added there is a keyword argument here.
"""
import numbers
import os

import numpy as np

from . import _conescan

_TABLE = _conescan._options() if hasattr(_conescan, "_options") else ()

#: Every option of conescan-sim's option table: {keyword: (option name, kind, help)}.
OPTIONS = {name.replace("-", "_"): (name, kind, help) for name, kind, help, _ in _TABLE}

#: The keywords each function honours (the others are refused by name, with what they are for):
#: {"conescan.simulate": [...], "conescan.summary": [...], "conescan-fit": [...]}; conescan.fit
#: and conescan.predict take conescan-fit's.
HONOURED = {program: [name.replace("-", "_") for name, _, _, by in _TABLE if program in by]
            for program in ("conescan.simulate", "conescan.summary", "conescan-fit")}


def _number_text(value):
    """The text a number would be typed as: an integer's digits, a float's shortest round-trip
    text (repr), which the option parser reads back to the same double."""
    if isinstance(value, numbers.Integral):
        return str(int(value))
    return float.__repr__(float(value))


def _value_text(option, value):
    """The command-line text of one value of `option` ('--a-km'), or TypeError."""
    if isinstance(value, str):
        return value
    if isinstance(value, os.PathLike):  # a file name (--config, options naming files)
        return os.fsdecode(value)
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, numbers.Real):
        return _number_text(value)
    raise TypeError(f"{option}: expected a number, a bool, text or a path, not "
                    f"{type(value).__name__}")


def _head_text(value, index=1):
    """Head `index`'s spec: 'alpha=0,beta=90' as typed, or a dict {'alpha': 0, 'beta': 90}."""
    if isinstance(value, dict):
        return ",".join(f"{key}={_value_text(f'--head: head {index}: {key}', v)}"
                        for key, v in value.items())
    if isinstance(value, str):
        return value
    raise TypeError(f"--head: expected a head spec (text or dict), or a list of them, "
                    f"not {type(value).__name__}")


def _option_texts(options):
    """[(option name, text), ...] of keyword arguments, heads one entry each."""
    texts = []
    for keyword, value in options.items():
        if keyword not in OPTIONS:
            raise ValueError(f"unknown option {keyword!r}; options: " + ", ".join(OPTIONS)
                             + ", config")
        name, kind, _ = OPTIONS[keyword]
        if kind == "head":
            heads = value if isinstance(value, (list, tuple)) else [value]
            if not heads:
                raise ValueError("--head: an empty list: give at least one head, or leave head "
                                 "out for the default one")
            texts.extend((name, _head_text(head, k + 1)) for k, head in enumerate(heads))
        else:
            texts.append((name, _value_text("--" + name, value)))
    return texts


def _config_path(config):
    if config is None:
        return None
    if not isinstance(config, (str, bytes, os.PathLike)):
        raise TypeError(f"--config: expected a path, not {type(config).__name__}")
    return os.fsdecode(config)


def _require_scenes():
    if not hasattr(_conescan, "_simulate"):
        raise RuntimeError("conescan was built without the scene layer "
                           "(-DCONESCAN_BUILD_APPS=OFF): simulate and summary need it")


def simulate(config=None, **options):
    """The rows conescan-sim writes for the same options, as a NumPy structured array.

    ``conescan.simulate(e=0, head=["beta=90", {"beta": -90, "noise": 0.01}])`` is
    ``conescan-sim --e 0 --head beta=90 --head beta=-90,noise=0.01``; ``config`` is a scene file
    (``--config``), whose options the keyword arguments replace as the command line's do.

    Values: numbers (int, float, NumPy scalars: written as their exact shortest text), bools for
    flags (``sun_sync=True``), or the text conescan-sim would be given (``a_km="7000.5"``,
    ``sweep="e=0:0.1:0.025"``, ``processing_radius="local"``). ``head`` takes a spec
    ('alpha=0,beta=90' or a dict of keys) or a list of them. Bad values raise ValueError with
    conescan-sim's message (``--e: e = 2 is outside [0, 1)``), other types TypeError.
    ``budget=True`` gives --budget's rows. Not from Python (ValueError naming them, and what
    they are for): ``trace``, the campaign options ``threads``, ``shard``, ``summary_state``, and
    ``write_oem``, ``write_aem``; ``summary`` is conescan.summary() (``HONOURED`` lists the
    keywords each function takes).
    ``apply="fit.json"`` corrects every row with a fit (conescan-fit --json, conescan.fit), as
    ``conescan-sim --apply``.

    One record per row, fields named and ordered as the CSV's columns (MODEL §9), in its units
    (s, km, degrees): [swept option] [run] [seed] t_s, nu_deg, r_km, alt_km, lat_deg, rho_deg,
    per head hK_chord_deg ... hK_status, roll_err_deg, pitch_err_deg, status [, condition].
    Reals are float64, bit for bit the numbers of the CSV (NaN where it writes nan, 0 where it
    writes 0); statuses are uint8 codes (``conescan.status_names[code]`` is the CSV's word);
    run and seed uint64. The GIL is released while the rows are computed.
    """
    _require_scenes()
    return _conescan._simulate(_option_texts(options), _config_path(config))


_SUMMARY_FORMATS = {"real": "<f8", "count": "<u8", "text": "<U16"}


def summary(config=None, **options):
    """conescan-sim --summary's lines for the same options, as a NumPy structured array.

    Options as conescan.simulate. One record per head ('h1', ...) and the system ('system'),
    per sweep value: [swept option] [run: the number of runs] [seed] source, rows, a count per
    status (fields named as conescan.status_names), then over the ok rows roll_min_deg,
    roll_max_deg, roll_mean_deg, roll_rms_deg, roll_std_deg, roll_3sigma_deg and the same of
    pitch (degrees; NaN where the CLI writes nan): the numbers conescan-sim prints, bit for bit.
    """
    _require_scenes()
    columns, lines = _conescan._summary(_option_texts(options), _config_path(config))
    dtype = np.dtype([(name, _SUMMARY_FORMATS[kind]) for name, kind in columns])
    return np.array(lines, dtype=dtype)

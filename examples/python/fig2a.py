#!/usr/bin/python3
"""The paper's Fig. 2(a): one head's roll error against true anomaly for e = 0 ... 0.1.

Usage: PYTHONPATH=build/python /usr/bin/python3 examples/python/fig2a.py [OUT.png]  (fig2a.png)
"""
import pathlib
import sys

import matplotlib.pyplot as plt
import numpy as np

import conescan

scene = pathlib.Path(__file__).resolve().parents[2] / "data" / "scenes" / "paper-fig2a.toml"
rows = conescan.simulate(config=scene)  # the sweep e = 0:0.1:0.025, one orbit each
for e in np.unique(rows["e"]):
    orbit = rows[rows["e"] == e]
    plt.plot(orbit["nu_deg"], orbit["roll_err_deg"], label=f"e = {e:g}")
plt.xlabel("true anomaly (deg)")
plt.ylabel("roll error (deg)")
plt.title("Fig. 2(a): a = 7280 km, one head, sigma = 0.02 deg")
plt.legend()
plt.savefig(sys.argv[1] if len(sys.argv) > 1 else "fig2a.png", dpi=100)

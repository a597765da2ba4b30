#!/usr/bin/env python3
"""Figure 13 with the 2D model (`granbench case figure13`): growth rate against k = 2 pi / Lx,
the three exact theories as lines ((7.11), chi = 5/4, the 2D surface mode) and the 2D sweep's
points by the paper's protocol (sine start, (7.12) over the linear period) and by eigenmode
seeding (matrix-pencil fit); inset: the same in the non-dimensional variables (7.13).

usage: case_figure13.py THEORY.h5 OUT.png SINE.h5 EIGENMODE.h5
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def points(path):
    with h5py.File(path, "r") as f:
        if "twod" not in f:
            return None
        return {k: f["twod"][k][:] for k in f["twod"]}


def main(theory, png, sine, eigen):
    with h5py.File(theory, "r") as f:
        u0, h0 = float(f.attrs["u_mean"]), float(f.attrs["h0"])
        c = {k: f["curve"][k][:] for k in f["curve"]}
    k = 2 * np.pi / c["Lx"]
    fig, a = plt.subplots(figsize=(7.5, 5))
    a.semilogx(k, c["depthavg_growth_rate"], "k-", label="(7.11), chi = 1")
    a.semilogx(k, c["bagnold_growth_rate"], "k-.", label="(7.11), chi = 5/4")
    a.semilogx(k, c["twod_growth_rate"], "k:", lw=2, label="exact 2D linear")
    ins = a.inset_axes([0.07, 0.6, 0.3, 0.3])
    ins.semilogx(c["k_hat"], h0 / u0 * c["depthavg_growth_rate"], "k-")
    ins.semilogx(c["k_hat"], h0 / u0 * c["twod_growth_rate"], "k:")
    for path, key, mark, name in ((sine, "growth_rate_712", "o", "2D, sine a0 = 0.2 mm, (7.12)"),
                                  (eigen, "growth_rate", "s", "2D, eigenmode, matrix pencil")):
        d = points(path)
        if d is None:
            continue
        km = 2 * np.pi / d["Lx"]
        a.semilogx(km, d[key], mark, ms=7, mfc="none", label=name)
        ins.semilogx(d["k_hat"], h0 / u0 * d[key], mark, ms=3, mfc="none")
    a.axhline(0, color="0.5", lw=0.8)
    # The unstable band and a little of the stable side: the lines' largest growth sets the scale.
    top = np.nanmax(np.concatenate([c["depthavg_growth_rate"], c["twod_growth_rate"]]))
    a.set_ylim(-0.8 * top, 1.9 * top)
    shown = c["twod_growth_rate"] > -0.8 * top
    a.set_xlim(k[shown].min() / 1.5, k[shown].max() * 1.5)
    a.set(xlabel="k = 2 pi / Lx [1/m]", ylabel="growth rate [1/s]",
          title="figure 13 with the 2D model")
    a.legend(fontsize=8, loc="upper right")
    ins.set_xlabel(r"$\hat k$", fontsize=7)
    ins.set_ylabel(r"Re $\hat\lambda$", fontsize=7)
    ins.set_ylim(-0.02, None)
    ins.tick_params(labelsize=6)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main(*sys.argv[1:5])

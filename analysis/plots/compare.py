#!/usr/bin/env python3
"""The comparison figure from `granbench compare` (compare.h5).

usage: compare.py compare.h5 compare.png
(a) h at x = 1 cm against t for both models (figure 12a); (b) ln |h_k| of the seeded mode against
t with the fitted growth-rate lines and the theories' slopes; (c) the final wave shapes.
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

STYLE = {"depthavg": ("tab:blue", "depth-averaged"), "twod": ("tab:red", "2D")}


def mode_amplitude(x, h, Lx):
    # the wave's amplitude in metres, 2 |h_k| / n, so that models on different grids compare
    k = 2 * np.pi / Lx
    return 2.0 / len(x) * np.abs((h * np.exp(-1j * k * x)[None, :]).sum(axis=1))


def main(data, png):
    with h5py.File(data, "r") as f:
        Lx, h0 = float(f.attrs["Lx"]), float(f.attrs["h0"])
        th = dict(f["theory"].attrs)
        runs = {}
        for m in ("depthavg", "twod"):
            g = f[m]
            runs[m] = dict(x=g["x"][:], t=g["t"][:], h=g["h"][:], attrs=dict(g.attrs))
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.3))
    x_probe = min(0.01, 0.5 * Lx)
    for m, r in runs.items():
        color, label = STYLE[m]
        i = int(np.argmin(np.abs(r["x"] - x_probe)))
        ax[0].plot(r["t"], 1e3 * r["h"][:, i], color=color, label=label)
        amp = mode_amplitude(r["x"], r["h"], Lx)
        ok = amp > 0
        ax[1].plot(r["t"][ok], np.log(amp[ok]), color=color, label=label)
        a = r["attrs"]
        t0, t1 = a["fit_t_first"], a["fit_t_last"]
        tt = np.linspace(t0, t1, 10)
        # the fit's intercept is ln |h_k| of the unnormalised sum
        ax[1].plot(tt, a["fit_intercept"] + np.log(2.0 / len(r["x"])) + a["growth_rate"] * tt, "k--", lw=1)
        ax[2].plot(1e2 * r["x"], 1e3 * r["h"][-1], color=color, label=f"{label}, t = {r['t'][-1]:.2f} s")
    ax[0].set(xlabel="t [s]", ylabel=f"h at x = {100 * x_probe:.0f} cm [mm]", title="surface at a probe (fig. 12a)")
    ax[0].legend()
    # Theory slopes drawn from the depth-averaged curve's start for reference.
    r = runs["depthavg"]
    amp0 = np.log(mode_amplitude(r["x"], r["h"], Lx)[0])
    tt = np.array([0.0, r["t"][-1]])
    for key, style, name in (("exact", ":", "(7.11)"), ("exact_bagnold", "-.", "chi = 5/4"), ("exact_2d", "-", "2D linear")):
        ax[1].plot(tt, amp0 + th[key + "_growth_rate"] * tt, color="0.4", ls=style, lw=0.9, label=f"slope {name}")
    ax[1].set(xlabel="t [s]", ylabel=r"ln (amplitude of $h_k$ [m])", title="growth of the seeded mode (dashed: fits)")
    ax[1].legend(fontsize=8)
    ax[2].axhline(1e3 * h0, color="0.5", lw=0.8)
    ax[2].set(xlabel="x [cm]", ylabel="h [mm]", title="final wave shapes")
    ax[2].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])

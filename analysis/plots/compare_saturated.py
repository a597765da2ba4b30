#!/usr/bin/env python3
"""The saturated-wave figure from `granbench compare --saturated` (compare_saturated.h5).

usage: compare_saturated.py compare_saturated.h5 compare_saturated.png
(a) both models' waves in the wave's frame, the steepest point of each front at xi = 0, at the
last sample; (b) the amplitude max h - min h against t, with the measured window shaded: the
wave is saturated where the curve is flat.
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

STYLE = {"depthavg": ("tab:blue", "depth-averaged"), "twod": ("tab:red", "2D")}


def main(data, png):
    with h5py.File(data, "r") as f:
        h0 = float(f.attrs["h0"])
        runs = {}
        for m in ("depthavg", "twod"):
            g = f[m]
            runs[m] = dict(xi=g["wave_frame/xi"][:], h=g["wave_frame/h"][:], t=g["t"][:],
                           amp=g["amplitude"][:], attrs=dict(g.attrs))
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.3))
    for m, r in runs.items():
        color, label = STYLE[m]
        a = r["attrs"]
        desc = (f"{label}: A = {1e3 * a['amplitude']:.2f} mm, max |h'| = {a['max_slope']:.3f}, "
                f"width {1e3 * a['front_width']:.2f} mm, c = {a['wave_speed']:.3f} m/s")
        ax[0].plot(1e2 * r["xi"], 1e3 * r["h"], color=color, marker=".", ms=2, lw=1, label=desc)
        ax[1].plot(r["t"], 1e3 * r["amp"], color=color, lw=1, label=label)
        ax[1].axvspan(a["window_t_from"], a["window_t_to"], color=color, alpha=0.12)
    ax[0].axhline(1e3 * h0, color="0.5", lw=0.8)
    ax[0].axvline(0.0, color="0.5", lw=0.6, ls=":")
    ax[0].set(xlabel="xi = x - x_front [cm]", ylabel="h [mm]",
              title=f"saturated waves in the wave's frame, t = {runs['twod']['t'][-1]:.2f} s")
    ax[0].legend(fontsize=7, loc="lower left")
    ax[1].set(xlabel="t [s]", ylabel="max h - min h [mm]", title="amplitude (shaded: measured window)")
    ax[1].legend(fontsize=8)
    fig.savefig(png, dpi=110, bbox_inches="tight")


if __name__ == "__main__":
    main(*sys.argv[1:3])

#!/usr/bin/python3
"""The three linear theories of the steady chute flow side by side (docs/linear-theory.md).

Usage: linear_theory.py data.h5 out.png

data.h5 is written by `granbench dispersion --theory twod --out`: the exact 2D linear stability
(surface branch and the fastest-growing other mode), the depth-averaged relation (7.11) with the
paper's shape factor chi = 1 and with the Bagnold value chi = 5/4, over k_hat = 2 pi h0/Lx, and the
requested Lx as points. Panels: growth rate Re(lambda) [1/s] and phase speed -Im(lambda)/k [m/s].
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main(h5_path, png_path):
    with h5py.File(h5_path, "r") as f:
        c = {k: np.asarray(f["curve/" + k]) for k in f["curve"].keys()}
        pts = {k: np.asarray(f["points/" + k]) for k in f["points"].keys()}
        attrs = dict(f.attrs)
    k = c["k_hat"]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax1.semilogx(k, c["depthavg_growth_rate"], "C0-", label=r"depth-averaged (7.11), $\chi=1$")
    ax1.semilogx(k, c["bagnold_growth_rate"], "C1--", label=r"depth-averaged, $\chi=5/4$")
    ax1.semilogx(k, c["twod_growth_rate"], "k-", lw=2, label="exact 2D, surface mode")
    other = c["twod_other_growth_rate"]
    ax1.semilogx(k, np.where(other > -5, other, np.nan), "C3:", label="exact 2D, least-stable other mode")
    ax1.plot(pts["k_hat"], pts["growth_rate"], "ko")
    ax1.axhline(0, color="0.6", lw=0.8)
    ymax = np.nanmax(np.concatenate([c["twod_growth_rate"], other, c["depthavg_growth_rate"]]))
    ax1.set_ylim(-3, 1.15 * ymax)
    ax1.set_xlabel(r"$\hat k = 2\pi h_0/L_x$")
    ax1.set_ylabel(r"growth rate Re$\,\lambda$ [1/s]")
    ax1.legend(fontsize=8, loc="upper left")
    ax2.semilogx(k, c["depthavg_phase_speed"], "C0-", label=r"$\chi=1$")
    ax2.semilogx(k, c["bagnold_phase_speed"], "C1--", label=r"$\chi=5/4$")
    ax2.semilogx(k, c["twod_phase_speed"], "k-", lw=2, label="exact 2D, surface")
    ax2.semilogx(k, np.where(other > 0, c["twod_other_phase_speed"], np.nan), "C3:", lw=2,
                 label="exact 2D, slow mode (where it grows)")
    ax2.plot(pts["k_hat"], pts["phase_speed"], "ko")
    u0 = attrs["u_mean"]
    ax2.axhline(2.5 * u0, color="0.6", lw=0.8, ls="--")
    ax2.text(k[0], 2.5 * u0, r" $\frac{5}{2}\bar u_0$", va="bottom", fontsize=8)
    ax2.set_xlabel(r"$\hat k$")
    ax2.set_ylabel(r"phase speed $-$Im$\,\lambda/k$ [m/s]")
    ax2.legend(fontsize=8)
    fig.suptitle(
        r"$\zeta$ = %.1f$^\circ$, $h_0$ = %.1f mm, F = %.3f, $\Gamma$ = %.4f"
        % (attrs["angle_deg"], 1e3 * attrs["h0"], attrs["F"], attrs["Gamma"]), fontsize=10)
    fig.tight_layout()
    fig.savefig(png_path, dpi=130)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit("usage: linear_theory.py data.h5 out.png")
    main(sys.argv[1], sys.argv[2])

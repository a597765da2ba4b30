#!/usr/bin/env python3
"""Growth rate and phase speed against wavenumber from `granbench dispersion --out` data.

usage: dispersion.py DATA.h5 OUT.png
Dimensional growth rate against 2 pi/Lx with the chosen Lx as points (figure 13 style), the
non-dimensional curve Re(lambda_hat) against k_hat as an inset, and the phase speed.
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main(data, png):
    with h5py.File(data, "r") as f:
        c = {k: f["curve/" + k][:] for k in f["curve"]}
        p = {k: f["points/" + k][:] for k in f["points"]}
        chi = float(f.attrs["chi"])
    k = 2 * np.pi / c["Lx"]
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.5))
    a.plot(k, c["growth_rate"], "k-", label=f"exact, chi = {chi:g}")
    a.plot(2 * np.pi / p["Lx"], p["growth_rate"], "ro", label="chosen Lx")
    a.axhline(0, color="0.5", lw=0.8)
    a.set(xlabel="k = 2 pi / Lx [1/m]", ylabel="growth rate [1/s]", title="temporal growth rate")
    # Show the unstable band and as much again beyond the cutoff.
    gmax = max(np.nanmax(c["growth_rate"]), 1e-9)
    unstable = k[c["growth_rate"] > 0]
    k_show = 2.2 * unstable.max() if unstable.size else 2.0 * (2 * np.pi / p["Lx"]).max()
    k_show = max(k_show, 1.2 * (2 * np.pi / p["Lx"]).max())
    a.set_xlim(0, k_show)
    a.set_ylim(-1.0 * gmax, 1.4 * gmax)
    a.legend(loc="upper right", fontsize=8)
    ins = a.inset_axes([0.6, 0.12, 0.35, 0.3])
    ins.plot(c["k_hat"], c["lambda_hat_re"], "k-")
    ins.plot(p["k_hat"], np.interp(p["k_hat"], c["k_hat"], c["lambda_hat_re"]), "ro", ms=3)
    ins.axhline(0, color="0.5", lw=0.6)
    kh_show = k_show * c["k_hat"][0] / k[0]
    lmax = max(np.nanmax(c["lambda_hat_re"]), 1e-12)
    ins.set_xlim(0, kh_show)
    ins.set_ylim(-lmax, 1.4 * lmax)
    ins.set_xlabel(r"$\hat k$", fontsize=8)
    ins.set_ylabel(r"Re $\hat\lambda$", fontsize=8)
    ins.tick_params(labelsize=7)
    b.plot(k, c["phase_speed"], "k-")
    b.plot(2 * np.pi / p["Lx"], p["phase_speed"], "ro")
    b.set(xlabel="k [1/m]", ylabel="phase speed [m/s]", title="phase speed")
    b.set_xlim(a.get_xlim())
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])

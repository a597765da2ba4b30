#!/usr/bin/env python3
"""Figure 13 from `granbench sweep --out` data: measured linear growth rates beside (7.11).

usage: sweep.py DATA.h5 OUT.png
Left: the dimensional growth rate against k = 2 pi / Lx, the exact relation (7.11) (with the
run's shape factor chi) as a line and the model's measured points, with the non-dimensional
curve Re(lambda_hat) against k_hat (7.13) as an inset. Right: the phase speed, same layout.
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
        p = {k: f["depthavg/" + k][:] for k in f["depthavg"]}
        chi = float(f.attrs["depthavg_chi"])
        h0 = float(f.attrs["h0"])
        u0 = float(f.attrs["u_mean"])
    model = "depthavg"
    k = 2 * np.pi / c["Lx"]
    kp = 2 * np.pi / p["Lx"]
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.5))
    a.plot(k, c["growth_rate"], "k-", label=f"(7.11), chi = {chi:g}")
    a.plot(kp, p["growth_rate"], "ro", ms=4, label=f"{model} (measured)")
    a.axhline(0, color="0.5", lw=0.8)
    a.set(xlabel="k = 2 pi / Lx [1/m]", ylabel="growth rate [1/s]",
          title="linear growth rate (figure 13)")
    a.set_xlim(0, 1.3 * kp.max())
    gmax = max(np.nanmax(c["growth_rate"]), np.nanmax(p["growth_rate"]), 1e-9)
    gmin = min(np.nanmin(p["growth_rate"]), 0.0)
    a.set_ylim(min(gmin * 1.2, -0.6 * gmax), 1.5 * gmax)
    a.legend(loc="lower left", fontsize=8)
    # Inset: the same in the scales (7.13), lambda_hat = lambda h0 / u0, k_hat = 2 pi h0 / Lx.
    ins = a.inset_axes([0.6, 0.58, 0.36, 0.34])
    ins.plot(c["k_hat"], c["growth_rate"] * h0 / u0, "k-")
    ins.plot(p["k_hat"], p["growth_rate"] * h0 / u0, "ro", ms=2.5)
    ins.axhline(0, color="0.5", lw=0.6)
    ins.set_xlim(0, 1.3 * p["k_hat"].max())
    shown = c["k_hat"] <= 1.3 * p["k_hat"].max()
    lam = c["growth_rate"][shown] * h0 / u0
    ins.set_ylim(1.3 * min(lam.min(), 0.0), 1.3 * max(lam.max(), 0.0))
    ins.set_xlabel(r"$\hat k$", fontsize=8)
    ins.set_ylabel(r"Re $\hat\lambda$", fontsize=8)
    ins.tick_params(labelsize=7)
    b.plot(k, c["phase_speed"], "k-", label="(7.11)")
    b.plot(kp, p["phase_speed"], "ro", ms=4, label=f"{model} (measured)")
    b.set(xlabel="k [1/m]", ylabel="phase speed [m/s]", title="phase speed")
    b.set_xlim(a.get_xlim())
    b.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])

#!/usr/bin/env python3
"""Figure 13 with both models: growth rate against k = 2 pi/Lx from `granbench sweep --model
twod|both` data, with the three exact theories ((7.11), chi = 5/4, 2D linear) as lines through
the swept points and each model's measured points (with --extrapolate also the 2D growth
extrapolated in the cell height, bounds as error bars); third panel: non-dimensional
Re(lambda_hat) vs k_hat.

usage: sweep_models.py DATA.h5 OUT.png
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main(data, png):
    with h5py.File(data, "r") as f:
        u0, h0 = float(f.attrs["u_mean"]), float(f.attrs["h0"])
        models = {m: {k: f[m][k][:] for k in f[m]} for m in ("depthavg", "twod") if m in f}
    # (the non-dimensional panel on its own: as an inset it covered the shortest waves' points)
    fig, (a, b, ins) = plt.subplots(1, 3, figsize=(16, 4.6),
                                    gridspec_kw={"width_ratios": [3, 3, 2]})
    ref = next(iter(models.values()))
    order = np.argsort(ref["Lx"])
    k = 2 * np.pi / ref["Lx"][order]
    for key, style, name in (("exact", "k-", "(7.11), chi = 1"), ("exact_bagnold", "k-.", "chi = 5/4"),
                             ("exact_2d", "k:", "2D linear")):
        a.plot(k, ref[key + "_growth_rate"][order], style, label=name)
        b.plot(k, ref[key + "_phase_speed"][order], style, label=name)
    marks = {"depthavg": ("s", "tab:blue", "depth-averaged"), "twod": ("o", "tab:red", "2D")}
    for m, d in models.items():
        mk, c, name = marks[m]
        km = 2 * np.pi / d["Lx"]
        a.plot(km, d["growth_rate"], mk, color=c, label=name + " (measured)")
        b.plot(km, d["phase_speed"], mk, color=c, label=name + " (measured)")
        # sweep --extrapolate: the 2D growth extrapolated to cells of no height, with the bounds of
        # the orders 1.3 and 1.7 as error bars (absent from files written before it existed)
        ext = d.get("growth_rate_extrapolated")
        if ext is not None and np.isfinite(ext).any():
            low, high = d["growth_rate_extrapolated_low"], d["growth_rate_extrapolated_high"]
            a.errorbar(km, ext, yerr=[ext - low, high - ext], fmt="x", color="tab:green", capsize=3,
                       label=name + " (extrapolated in dz)")
    a.axhline(0, color="0.5", lw=0.8)
    a.set(xlabel="k = 2 pi / Lx [1/m]", ylabel="growth rate [1/s]", title="figure 13: growth rate")
    a.legend(fontsize=8, loc="lower left")
    scale = h0 / u0
    ins.plot(ref["k_hat"][order], scale * ref["exact_growth_rate"][order], "k-")
    for m, d in models.items():
        mk, c, _ = marks[m]
        ins.plot(d["k_hat"], scale * d["growth_rate"], mk, color=c, ms=3)
    ins.axhline(0, color="0.5", lw=0.8)
    ins.set(xlabel=r"$\hat k$", ylabel=r"Re $\hat\lambda$ (scaled by $h_0/\bar u$)",
            title="(7.11), non-dimensional")
    b.set(xlabel="k [1/m]", ylabel="phase speed [m/s]", title="phase speed")
    b.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])

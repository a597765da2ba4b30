#!/usr/bin/env python3
"""Figures 1, 2 and 7 of Barker & Gray (2017) from `granbench wellposed --out` data.

usage: wellposed.py DATA.h5 OUT.png
(a) mu(I) of the chosen curve and of Jop (2.12), well-posed ranges shaded (figures 1, 7);
(b) C(I) (3.9); (c)/(d) neutral curves I_pm^N(mu) (4.3) through the lower and upper neutral
points (figure 2), with mu = sqrt(2) and I_max dashed.
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main(data, png):
    with h5py.File(data, "r") as f:
        curve = f.attrs["curve"]
        curve = curve.decode() if isinstance(curve, bytes) else str(curve)
        I = f["figure1/I"][:]
        mu, C = f["figure1/mu"][:], f["figure1/C"][:]
        mu_j, C_j = f["figure1/mu_jop"][:], f["figure1/C_jop"][:]
        lo, hi = f["wellposed/interval_lo"][:], f["wellposed/interval_hi"][:]
        mu_grid = f["figure2/mu"][:]
        low = {k: f["figure2/" + k][:] for k in ("I_plus_low", "I_minus_low") if "figure2/" + k in f}
        high = {k: f["figure2/" + k][:] for k in ("I_plus_high", "I_minus_high") if "figure2/" + k in f}
        I_max = float(f.attrs["I_max"])
    fig, ax = plt.subplots(2, 2, figsize=(11, 8))
    a = ax[0, 0]
    for l, h in zip(lo, hi):
        a.axvspan(max(l, I[0]), min(h, I[-1]), color="0.88")
    a.semilogx(I, mu, "k-", label=f"{curve}")
    a.semilogx(I, mu_j, "b-.", label="Jop (2.12)")
    a.set(xlabel="I", ylabel=r"$\mu(I)$", title="friction curves; grey: well posed (figs 1, 7)")
    a.set_ylim(0, max(1.0, 1.1 * np.nanmax(mu_j)))
    a.legend()
    a = ax[0, 1]
    a.semilogx(I, C, "k-", label=curve)
    a.semilogx(I, C_j, "b-.", label="Jop")
    a.axhline(0, color="0.5", lw=0.8)
    a.set(xlabel="I", ylabel="C(I)", title="(3.9): C > 0 ill posed")
    a.set_ylim(-0.5, 1.0)
    a.legend()
    for a, data_, title in ((ax[1, 0], low, "low-I neutral curves (fig 2a)"),
                            (ax[1, 1], high, "high-I neutral curves (fig 2b)")):
        for k, style in (("I_plus", "r-"), ("I_minus", "g-")):
            for key, v in data_.items():
                if key.startswith(k + "_"):
                    a.loglog(v, mu_grid, style, label=k.replace("_", " ") + "$^N$")
        a.semilogx(I, mu_j, "b-.", label="Jop")
        a.axhline(np.sqrt(2), color="k", ls="--", lw=0.8)
        if data_ is high and I_max > 0:
            a.axvline(I_max, color="k", ls="--", lw=0.8, label=f"I_max = {I_max:.3g}")
        a.set(xlabel="I", ylabel=r"$\mu$", title=title)
        a.set_xlim(1e-8, 1e3)
        a.set_ylim(1e-2 if data_ is low else 0.2, 1.6)
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])

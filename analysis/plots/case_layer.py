#!/usr/bin/env python3
"""Figures of the uniform-layer paper cases (`granbench case decelerating|high-speed`).

usage: case_layer.py CASE.h5 PREFIX [SNAPSHOT_TIME]
writes PREFIX_profiles.png   downslope averages u(z) and I(z) at the sampled times, one column per
                             run (figures 3, 5 and 8b/d; I on a log scale, with the initial and the
                             run curve's steady I_zeta as vertical lines where they exist)
       PREFIX_snapshots.png  the 2D field of I in the grains at the sample nearest SNAPSHOT_TIME
                             (default: the last sample) of each run (figures 4 and 8a/c)
       PREFIX_grid_dependence.png  rms of log10(I_fine / I_coarse) over the layer against t, per
                             curve (when a case has two resolutions)
"""
import json
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.colors import LogNorm


def main(data, prefix, snapshot_time=None):
    with h5py.File(data, "r") as f:
        summary = json.loads(f.attrs["results_json"])
        h0 = float(f.attrs["h0"])
        title = f.attrs["title"]
        title = title.decode() if isinstance(title, bytes) else str(title)
        runs = []
        for r in summary["runs"]:
            g = f["runs"][r["label"]]
            runs.append(dict(meta=r, t=g["t"][:], z=g["z"][:], u=g["u_profile"][:], I=g["I_profile"][:],
                             field=g["I_field"][:], Lx=float(g.attrs["Lx"]), Lz=float(g.attrs["Lz"])))
        gd = {name: (np.asarray(d["t"]), np.array([np.nan if v is None else v for v in d["rms_log10_I"]]))
              for name, d in summary["grid_dependence"].items()}
        # Samples at which both grids of a pair still flow (grid_dependence.hpp): outside them a
        # layer is stopping or at rest, and the difference measures when each grid stops.
        flowing = {name: np.asarray(d.get("both_flowing", []), dtype=bool)
                   for name, d in summary["grid_dependence"].items()}

    # Profiles: u(z) top row, I(z) bottom row; colour runs from early (light) to late (dark).
    n = len(runs)
    fig, ax = plt.subplots(2, n, figsize=(3.2 * n, 6.4), squeeze=False)
    for j, r in enumerate(runs):
        inside = r["z"] < h0
        colours = plt.cm.viridis(np.linspace(0.9, 0.0, len(r["t"])))
        for m, c in enumerate(colours):
            ax[0, j].plot(r["u"][m, inside], r["z"][inside] / h0, color=c, lw=1)
            I = r["I"][m, inside]
            ok = np.isfinite(I) & (I > 0)
            ax[1, j].semilogx(I[ok], r["z"][inside][ok] / h0, color=c, lw=1)
        meta = r["meta"]
        ax[0, j].set_title(f"{meta['curve']} {meta['nx']}x{meta['nz']}\n({meta['status']}, t = {meta['t_reached']:.3g} s)",
                           fontsize=9)
        ax[0, j].set_xlabel("downslope mean u [m/s]")
        ax[1, j].set_xlabel("downslope mean I")
        ax[1, j].axvline(meta["initial_I"], color="k", ls="--", lw=0.8, label="initial I")
        if meta["steady_I"] is not None and meta["steady_I"] > 1e-12:
            ax[1, j].axvline(meta["steady_I"], color="k", ls="-", lw=0.8, label="steady I of the run's curve")
        ax[1, j].legend(fontsize=7, loc="lower left")
    for a in ax[:, 0]:
        a.set_ylabel("z / h0")
    fig.suptitle(title + f"\nlines at t = {runs[0]['t'][0]:.3g} ... {runs[0]['t'][-1]:.3g} s, light to dark",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(prefix + "_profiles.png", dpi=120)
    plt.close(fig)

    # Snapshots of I at the last sample, log colour scale shared by all runs.
    for r in runs:
        r["snap"] = len(r["t"]) - 1 if snapshot_time is None else int(np.argmin(np.abs(r["t"] - snapshot_time)))
    finite = np.concatenate([r["field"][r["snap"]][np.isfinite(r["field"][r["snap"]]) & (r["field"][r["snap"]] > 0)]
                             for r in runs])
    lo, hi = (np.percentile(finite, 1), np.percentile(finite, 99.5)) if finite.size else (1e-6, 1)
    fig, ax = plt.subplots(n, 1, figsize=(7, 1.9 * n + 0.6), squeeze=False)
    for j, r in enumerate(runs):
        field = np.ma.masked_invalid(r["field"][r["snap"]])
        nz, nx = field.shape
        keep = int(np.ceil(min(1.05 * h0, r["Lz"]) / (r["Lz"] / nz)))
        im = ax[j, 0].imshow(field[:keep], origin="lower", aspect="auto", cmap="magma",
                             norm=LogNorm(vmin=max(lo, 1e-12), vmax=max(hi, 2 * lo)),
                             extent=[0, r["Lx"] / h0, 0, keep * r["Lz"] / nz / h0])
        meta = r["meta"]
        ax[j, 0].set_title(f"{meta['curve']} {meta['nx']}x{meta['nz']}: I at t = {r['t'][r['snap']]:.3g} s", fontsize=9)
        ax[j, 0].set_ylabel("z / h0")
        fig.colorbar(im, ax=ax[j, 0], label="I")
    ax[-1, 0].set_xlabel("x / h0")
    fig.tight_layout()
    fig.savefig(prefix + "_snapshots.png", dpi=120)
    plt.close(fig)

    if gd:
        fig, ax = plt.subplots(figsize=(6, 4))
        for name, (t, v) in gd.items():
            line, = ax.semilogy(t, v, "-", label=name.replace("_vs_", " vs "))
            both = flowing[name] if flowing[name].size == t.size else np.ones(t.size, dtype=bool)
            ax.semilogy(t[both], v[both], "o", color=line.get_color())
            ax.semilogy(t[~both], v[~both], "o", color=line.get_color(), mfc="none")
        ax.plot([], [], "ko", label="both grids flowing")
        ax.plot([], [], "ko", mfc="none", label="a grid stopping or at rest")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("rms over the layer of log10(I_fine / I_coarse)")
        ax.set_title("Grid dependence of the downslope-averaged I", fontsize=10)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(prefix + "_grid_dependence.png", dpi=120)
        plt.close(fig)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], float(sys.argv[3]) if len(sys.argv) > 3 else None)

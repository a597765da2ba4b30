#!/usr/bin/env python3
"""Figures of the rollwave paper cases (`granbench case rollwave-8cm|rollwave-12cm`), from the
HDF5 file of `granbench run --model twod`.

usage: case_rollwave.py RUN.h5 PREFIX PROBE_X T0 T1 FIELD_TIME
writes PREFIX_fields.png       u, w and I below the surface at the snapshot nearest FIELD_TIME
                               (figure 9)
       PREFIX_streamlines.png  streamlines of (u - c, w) in the frame moving with the measured wave
                               speed c (figure 10)
       PREFIX_surface.png      h at x = PROBE_X over [T0, T1] and the largest h against t (figure 12)
"""
import json
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main(data, prefix, probe_x, t0, t1, field_time):
    with h5py.File(data, "r") as f:
        results = json.loads(f.attrs["results_json"])
        s = f["surface"]
        x, t, h = s["x"][:], s["t"][:], s["h"][:]
        snaps = f["snapshots"]
        xn, zn = snaps["x_nodes"][:], snaps["z_nodes"][:]
        names = sorted(k for k in snaps.keys() if k.isdigit())
        times = np.array([float(snaps[k].attrs["t"]) for k in names])
        pick = names[int(np.argmin(np.abs(times - field_time)))]
        g = snaps[pick]
        t_field = float(g.attrs["t"])
        u, w, I, frac = g["u"][:], g["w"][:], g["I"][:], g["f"][:]
    xc, zc = 0.5 * (xn[1:] + xn[:-1]), 0.5 * (zn[1:] + zn[:-1])
    grains = frac >= 0.5
    h_snap = frac.sum(axis=0) * (zn[1] - zn[0])
    zmax = 1.1 * h_snap.max()
    keep = zc <= zmax
    c = results.get("wave_speed") or results.get("phase_speed") or 0.0

    fig, ax = plt.subplots(3, 1, figsize=(9, 7), sharex=True)
    for a, (field, label, cmap) in zip(ax, [(u, "u [m/s]", "viridis"), (w, "w [m/s]", "RdBu_r"),
                                             (I, "I", "magma")]):
        shown = np.ma.masked_where(~grains | ~np.isfinite(field), field)[keep]
        kw = {}
        if label == "w [m/s]":
            m = np.nanmax(np.abs(shown)) if shown.count() else 1.0
            kw = dict(vmin=-m, vmax=m)
        im = a.pcolormesh(xn * 100, zn[: keep.sum() + 1] * 1000, shown, cmap=cmap, shading="flat", **kw)
        a.plot(xc * 100, h_snap * 1000, "k", lw=0.8)
        a.set_ylabel("z [mm]")
        fig.colorbar(im, ax=a, label=label)
    ax[0].set_title(f"Fields below the surface at t = {t_field:.2f} s (figure 9)", fontsize=10)
    ax[-1].set_xlabel("x [cm]")
    fig.tight_layout()
    fig.savefig(prefix + "_fields.png", dpi=120)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(9, 3.2))
    X, Z = np.meshgrid(xc, zc[keep])
    U = np.where(grains, u - c, np.nan)[keep]
    W = np.where(grains, w, np.nan)[keep]
    ax.streamplot(X * 100, Z * 1000, U * 100, W * 1000, density=1.4, linewidth=0.7, color="k")
    ax.plot(xc * 100, h_snap * 1000, "tab:red", lw=1)
    ax.set_xlabel("x [cm]")
    ax.set_ylabel("z [mm]")
    ax.set_ylim(0, zmax * 1000)
    ax.set_title(f"Streamlines in the frame moving at the measured wave speed {c:.4g} m/s, "
                 f"t = {t_field:.2f} s (figure 10)", fontsize=10)
    fig.tight_layout()
    fig.savefig(prefix + "_streamlines.png", dpi=120)
    plt.close(fig)

    i_probe = int(np.argmin(np.abs(x - probe_x)))
    window = (t >= t0) & (t <= t1)
    fig, ax = plt.subplots(1, 3, figsize=(14, 3.6))
    ax[0].plot(t, h[:, i_probe] * 1000, "k", lw=0.5)
    ax[0].axvspan(t0, t1, color="0.85")
    ax[0].set_xlabel("t [s]")
    ax[0].set_ylabel(f"h at x = {x[i_probe] * 100:.2f} cm [mm]")
    ax[0].set_title("(a) at the probe, the whole run (grey: panel b)", fontsize=10)
    ax[1].plot(t[window], h[window, i_probe] * 1000, "k.-", ms=3)
    ax[1].set_xlabel("t [s]")
    ax[1].set_ylabel(f"h at x = {x[i_probe] * 100:.2f} cm [mm]")
    ax[1].set_title("(b) at the probe, the developed wave", fontsize=10)
    ax[2].plot(t, h.max(axis=1) * 1000, "k", lw=1)
    ax[2].set_xlabel("t [s]")
    ax[2].set_ylabel("max h [mm]")
    ax[2].set_title("(c) largest height", fontsize=10)
    fig.suptitle(f"Surface of the rollwave run (figure 12); status {results.get('status')}, "
                 f"t reached {results.get('t_reached', 0):.3g} s", fontsize=10)
    fig.tight_layout()
    fig.savefig(prefix + "_surface.png", dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], *map(float, sys.argv[3:7]))

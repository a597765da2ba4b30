#!/usr/bin/env python3
"""Measures of x-dependence in the layer cases' HDF5 output (docs/paper-cases.md, issue 16).

The decelerating and high-speed cases write, per run, the inertial number I(x, z) of every cell
that is at least half grains at each sample (/runs/<label>/I_field, [t][z][x], NaN elsewhere),
the x-averaged velocity profile (/runs/<label>/u_profile) and the largest speed.  They do not
write the velocity field, so both measures below are built from I(x, z).

  decelerating FILE [FILE...]
      P(t) = the largest, over the rows of cells at heights z <= 0.8 h0 that are grains across
      the whole domain, of the standard deviation over x of log10 I, in decades.  An x-uniform
      layer gives P ~ 0 (about 1e-5 in the decelerating runs, fed from the surface row); P = 0.1
      means I varies by about 26 % along x somewhere in the layer.  The top 0.2 h0 is left out:
      its surface row carries a 0.06-0.1 decade x-variation from the first sample on, while the
      flow is well posed, and at rest the light fluid's shear keeps the top few rows creeping;
      both are interface effects.  Also printed: the time the layer stops (the x-averaged speed
      below 1e-3 m/s at every height below h0) and the largest P over the run.

  high-speed FILE [--window T1 T2]
      E(t) = the mean, over the cells of the rows at z <= 0.8 h0 that are grains across the
      whole domain, of ((I - <I>_x) / <I>_x)^2, where <I>_x is the average along x at that
      height.  The top 0.2 h0 is left out for the reason above: the rows next to the surface
      carry an x-variation of their own (1e-7 to 1e-3 in this measure, largest at the surface
      row) that stays there while the interior follows the flow's instability or stability.
      In the linear regime I' is linear in the velocity perturbation, so E grows at the same
      rate as the perturbation kinetic energy, twice the amplitude rate.  Printed: E at every
      sample, the rate d ln E / dt between samples, and the least-squares slope of ln E over
      [T1, T2] with the largest misfit of that line in ln E.

  high-speed-figure FILE [FILE...] --out PNG [--window LABEL T1 T2]...
      The figure of that measure against grid, like the paper's figure 8: ln E(t) of every run
      in the files, Jop's curve and the regularised curve in two panels, with the least-squares
      line over each run's window (given per run label, e.g. jop_128x32 0.07 0.25), and the
      fitted rates against the cells across the layer in a third panel.  Also printed: each
      run's rate and largest misfit.

  twod-run FILE --h0 H0 [--window T1 T2]
      A cross-check on a `granbench run --model twod` file, whose snapshots hold u, w, f and I:
      the perturbation kinetic energy per unit density,
      E_u(t) = sum over the cells of the rows that are at least half grains all along x of
      ((u - <u>_x)^2 + (w - <w>_x)^2) dx dz, next to E(t) of I as above, with their slopes over
      [T1, T2], to show that the two grow at the same rate.
"""
import argparse

import h5py
import numpy as np


def runs(path):
    f = h5py.File(path, "r")
    h0 = float(f.attrs["h0"])
    for label in f["runs"]:
        yield label, h0, f["runs"][label]


def full_rows(field):
    return np.all(np.isfinite(field) & (field > 0), axis=1)


def decelerating(paths):
    for path in paths:
        for label, h0, g in runs(path):
            t, I, z = g["t"][:], g["I_field"][:], g["z"][:]
            u = g["u_profile"][:]
            inside = z < h0
            stopped = [tt for tt, row in zip(t, u) if np.max(np.abs(row[inside])) < 1e-3]
            print(f"{path}: {label}  stops at t = {stopped[0] if stopped else 'not'} s")
            P = []
            for n in range(len(t)):
                rows = full_rows(I[n]) & (z <= 0.8 * h0)
                s = np.log10(I[n][rows]).std(axis=1)
                k = int(np.argmax(s))
                P.append(s[k])
                mean_log = np.log10(I[n][rows]).mean()
                print(f"  t = {t[n]:.3f} s  P = {s[k]:.2e} decade at z = {z[rows][k] / h0:.2f} h0"
                      f"  (mean log10 I = {mean_log:.2f})")
            n = int(np.argmax(P))
            print(f"  largest P = {P[n]:.2e} decade at t = {t[n]:.3f} s")


def energy(g, h0):
    """E(t) of a layer case's run (high-speed above)."""
    t, I, z = g["t"][:], g["I_field"][:], g["z"][:]
    E = []
    for n in range(len(t)):
        F = I[n][full_rows(I[n]) & (z <= 0.8 * h0)]
        m = F.mean(axis=1, keepdims=True)
        E.append(np.mean(((F - m) / m) ** 2))
    return t, np.array(E)


def high_speed(path, window):
    for label, h0, g in runs(path):
        t, E = energy(g, h0)
        print(f"{path}: {label}")
        for n in range(len(t)):
            rate = (np.log(E[n]) - np.log(E[n - 1])) / (t[n] - t[n - 1]) if n else float("nan")
            print(f"  t = {t[n]:.3f} s  E = {E[n]:.3e}  d ln E/dt = {rate:+.2f} 1/s")
        if window:
            sel = (t >= window[0] - 1e-9) & (t <= window[1] + 1e-9)
            line = np.polyfit(t[sel], np.log(E[sel]), 1)
            misfit = np.max(np.abs(np.polyval(line, t[sel]) - np.log(E[sel])))
            print(f"  fit over [{window[0]}, {window[1]}] s ({sel.sum()} samples): "
                  f"d ln E/dt = {line[0]:.2f} 1/s, largest misfit {misfit:.2f} in ln E")


def high_speed_figure(paths, out, windows):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    rates = {"jop": [], "regularised": []}
    found = []  # (curve, cells across h0, path, label, t, E)
    for path in paths:
        for label, h0, g in runs(path):
            curve = g.attrs["curve"]
            curve = curve.decode() if isinstance(curve, bytes) else str(curve)
            across = int(round(float(g.attrs["nz"]) * h0 / float(g.attrs["Lz"])))
            size = f"{int(g.attrs['nx'])} x {int(g.attrs['nz'])}"
            found.append((curve, across, path, label, size, *energy(g, h0)))
    colours = {n: f"C{j}" for j, n in enumerate(sorted({r[1] for r in found}))}  # one per grid
    for curve, across, path, label, size, t, E in sorted(found, key=lambda r: (r[0], r[1])):
        ax = axes[0] if curve == "jop" else axes[1]
        ax.semilogy(1e3 * t, E, lw=1.2, color=colours[across],
                    label=f"{size} ({across} cells across h0)")
        if label not in windows:
            continue
        t1, t2 = windows[label]
        sel = (t >= t1 - 1e-9) & (t <= t2 + 1e-9)
        a, b = np.polyfit(t[sel], np.log(E[sel]), 1)
        misfit = np.max(np.abs(a * t[sel] + b - np.log(E[sel])))
        ax.semilogy(1e3 * t[sel], np.exp(a * t[sel] + b), "--", color=colours[across], lw=2.2,
                    label=f"  fit {t1:g}-{t2:g} s: {a:.0f} 1/s")
        rates.setdefault(curve, []).append((across, a))
        print(f"{path}: {label}  {across} cells across h0  d ln E/dt = {a:.1f} 1/s over "
              f"[{t1}, {t2}] s ({sel.sum()} samples), largest misfit {misfit:.2f} in ln E")
    for ax, title in zip(axes[:2], ["Jop's curve (2.12): ill posed at I = 0.99",
                                    "regularised curve (6.3): well posed"]):
        ax.set_xlabel("t [ms]")
        ax.set_ylabel("E = <((I - <I>x) / <I>x)^2> over the layer below 0.8 h0")
        ax.set_title(title)
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
    ax = axes[2]
    for curve, marker in (("jop", "o-"), ("regularised", "s--")):
        pts = sorted(rates.get(curve, []))
        if pts:
            n, r = zip(*pts)
            ax.plot(n, r, marker, label=curve)
    ax.set_xscale("log", base=2)
    if all(r > 0 for pts in rates.values() for _, r in pts):
        ax.set_yscale("log")
    else:  # a decaying run: a scale that shows the sign
        ax.set_yscale("symlog", linthresh=10)
    ax.set_xlabel("cells across the layer")
    ax.set_ylabel("fitted rate of E [1/s]")
    ax.set_title("growth of the perturbation against grid")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


def fit(t, E, window):
    sel = (t >= window[0] - 1e-9) & (t <= window[1] + 1e-9)
    return np.polyfit(t[sel], np.log(E[sel]), 1)[0], int(sel.sum())


def twod_run(path, h0, window):
    s = h5py.File(path, "r")["snapshots"]
    xn, zn = s["x_nodes"][:], s["z_nodes"][:]
    zc, cell = 0.5 * (zn[1:] + zn[:-1]), (xn[1] - xn[0]) * (zn[1] - zn[0])
    t, Eu, EI = [], [], []
    for name in sorted(k for k in s if k.isdigit()):
        g = s[name]
        u, w, f, I = g["u"][:], g["w"][:], g["f"][:], g["I"][:]
        full = np.all(f >= 0.5, axis=1)
        du = u[full] - u[full].mean(axis=1, keepdims=True)
        dw = w[full] - w[full].mean(axis=1, keepdims=True)
        F = I[full & (zc <= 0.8 * h0)]
        m = F.mean(axis=1, keepdims=True)
        t.append(float(g.attrs["t"]))
        Eu.append(np.sum(du ** 2 + dw ** 2) * cell)
        EI.append(np.mean(((F - m) / m) ** 2))
    t, Eu, EI = map(np.array, (t, Eu, EI))
    for n in range(len(t)):
        print(f"  t = {t[n]:.4f} s  E_u = {Eu[n]:.3e} m^4/s^2  E = {EI[n]:.3e}")
    if window:
        (a, k), (b, _) = fit(t, Eu, window), fit(t, EI, window)
        print(f"  fit over [{window[0]}, {window[1]}] s ({k} snapshots): "
              f"d ln E_u/dt = {a:.2f} 1/s, d ln E/dt = {b:.2f} 1/s")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = p.add_subparsers(dest="kind", required=True)
    d = sub.add_parser("decelerating")
    d.add_argument("files", nargs="+")
    h = sub.add_parser("high-speed")
    h.add_argument("file")
    h.add_argument("--window", nargs=2, type=float)
    hf = sub.add_parser("high-speed-figure")
    hf.add_argument("files", nargs="+")
    hf.add_argument("--out", required=True)
    hf.add_argument("--window", nargs=3, action="append", default=[],
                    metavar=("LABEL", "T1", "T2"))
    r = sub.add_parser("twod-run")
    r.add_argument("file")
    r.add_argument("--h0", type=float, required=True)
    r.add_argument("--window", nargs=2, type=float)
    a = p.parse_args()
    if a.kind == "decelerating":
        decelerating(a.files)
    elif a.kind == "high-speed":
        high_speed(a.file, a.window)
    elif a.kind == "high-speed-figure":
        windows = {w[0]: (float(w[1]), float(w[2])) for w in a.window}
        high_speed_figure(a.files, a.out, windows)
    else:
        twod_run(a.file, a.h0, a.window)


if __name__ == "__main__":
    main()

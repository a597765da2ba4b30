#!/usr/bin/python3
"""Growth rate and phase speed of the first Fourier mode of a Gerris (or granbench) rollwave run.

Reads the VOF snapshots that ../shared/gerris/rollwave.gfs writes (OUTDIR/h/snap-<t>.txt, columns
x y z T in units of h0, t in units of sqrt(h0/g)), forms h(x, t) as the column integral of T and
its Fourier coefficient h_k(t) = sum_j h(x_j, t) exp(-i k x_j) at k = 2 pi / Lx, and fits it over
a window [t0, t1] two ways:
  - a straight line through ln|h_k| (one growth rate, whatever the waves in it);
  - a sum of M damped travelling waves a_j exp(lambda_j t) by the matrix pencil (Hua & Sarkar
    1990), the same model as granbench's measurement (analysis/spectral/spectral_modes.hpp):
    growth Re(lambda_j), phase speed -Im(lambda_j) / k for h ~ exp(i k x + lambda t).
The reported wave is the one whose speed is nearest --expected-speed; when the waves do not
describe the data (relative residual above --max-residual, granbench's own default 5e-4) the
growth rate and speed are null, as in granbench's measurement. Prints JSON.
Given a granbench HDF5 file (`granbench run --out run.h5`) instead of OUTDIR, it fits that run's
surface/h the same way, so that the two codes are measured by one fit.

  bench/gerris_growth.py OUTDIR|run.h5 --t0 0.2 --t1 1.2 [--modes 2] [--expected-speed 1.138]
"""
import argparse
import glob
import json
import math
import os
import re

import numpy as np

H0 = 0.004  # m, the case's depth (Gerris' length unit)
G = 9.81
T_UNIT = math.sqrt(H0 / G)  # s, Gerris' time unit
LX_H0 = 20.0  # Lx = 8 cm in units of h0


def read_height(path):
    """h(x) [m] on the snapshot's uniform columns, as the column integral of T."""
    data = np.loadtxt(path, comments="#")
    x, y, t = data[:, 0], data[:, 1], data[:, 3]
    xs = np.unique(x)
    ys = np.unique(y)
    dy = float(np.min(np.diff(ys))) if len(ys) > 1 else 2.0
    order = np.searchsorted(xs, x)
    h = np.bincount(order, weights=t * dy, minlength=len(xs))
    return xs, h * H0


def pencil(samples, dt, modes):
    """Matrix-pencil fit of samples y_n = sum_j a_j z_j^n; returns lambdas and amplitudes."""
    n = len(samples)
    rows = n // 2
    hankel = np.array([samples[i:i + n - rows] for i in range(rows)]).T  # (n-rows) x rows
    y0, y1 = hankel[:, :-1], hankel[:, 1:]
    u, s, vh = np.linalg.svd(y0, full_matrices=False)
    m = min(modes, len(s))
    reduced = (u[:, :m].conj().T @ y1 @ vh[:m].conj().T) / s[:m]
    z = np.linalg.eigvals(reduced)
    lam = np.log(z) / dt
    basis = np.vander(z, n, increasing=True).T  # n x m
    amp, *_ = np.linalg.lstsq(basis, samples, rcond=None)
    fit = basis @ amp
    residual = float(np.linalg.norm(fit - samples) / np.linalg.norm(samples))
    return lam, amp, residual


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("outdir")
    ap.add_argument("--t0", type=float, default=0.2, help="window start [s]")
    ap.add_argument("--t1", type=float, default=float("inf"), help="window end [s]")
    ap.add_argument("--modes", type=int, default=2)
    ap.add_argument("--max-residual", type=float, default=5e-4,
                    help="largest relative residual at which the waves describe the data")
    ap.add_argument("--expected-speed", type=float, default=1.1380,
                    help="phase speed [m/s] that picks the reported wave (2D theory's)")
    a = ap.parse_args()

    k = 2.0 * math.pi / (LX_H0 * H0)
    times, coeffs = [], []
    if a.outdir.endswith(".h5"):  # granbench: surface/h [m] on surface/x [m] at surface/t [s]
        import h5py
        with h5py.File(a.outdir, "r") as f:
            xs_m = np.asarray(f["surface/x"])
            for t, h in zip(np.asarray(f["surface/t"]), np.asarray(f["surface/h"])):
                times.append(float(t))
                coeffs.append(np.sum(h * np.exp(-1j * k * xs_m)))
        xs = xs_m
    else:
        snaps = []
        for path in glob.glob(os.path.join(a.outdir, "h", "snap-*.txt")):
            t = float(re.search(r"snap-(.*)\.txt$", path).group(1)) * T_UNIT
            snaps.append((t, path))
        snaps.sort()
        for t, path in snaps:
            xs, h = read_height(path)
            coeffs.append(np.sum(h * np.exp(-1j * k * xs * H0)))
            times.append(t)
    times, coeffs = np.array(times), np.array(coeffs)
    inside = (times >= a.t0 - 1e-9) & (times <= a.t1 + 1e-9)
    tw, cw = times[inside], coeffs[inside]
    if len(tw) < 2 * a.modes + 2:
        raise SystemExit(f"gerris_growth: {len(tw)} samples in [{a.t0}, {a.t1}] s, too few")
    dt = float(np.mean(np.diff(tw)))
    slope = float(np.polyfit(tw, np.log(np.abs(cw)), 1)[0])
    lam, amp, residual = pencil(cw, dt, a.modes)
    waves = [{"growth_rate": float(l.real), "phase_speed": float(-l.imag / k),
              "amplitude": float(2.0 * abs(c) / len(xs))} for l, c in zip(lam, amp)]
    seeded = min(waves, key=lambda w: abs(w["phase_speed"] - a.expected_speed))
    print(json.dumps({
        "outdir": a.outdir, "columns": int(len(xs)), "window": [float(tw[0]), float(tw[-1])],
        "samples": int(len(tw)), "line_fit_growth_rate": slope,
        "describes_data": residual <= a.max_residual,
        "growth_rate": seeded["growth_rate"] if residual <= a.max_residual else None,
        "phase_speed": seeded["phase_speed"] if residual <= a.max_residual else None,
        "modes": waves, "pencil_relative_residual": residual,
        "amplitude_m": [float(2.0 * abs(c) / len(xs)) for c in coeffs],
        "times_s": [float(t) for t in times]}, indent=2))


if __name__ == "__main__":
    main()

# Opens a granbench 2D run's .xdmf with each of ParaView's XDMF readers and checks what a user
# would see: the whole grid (nx x nz cells), every field and the velocity vector, every time, and a
# Threshold f > 0.5 that keeps part of the cells. Run by test_xdmf_output under pvpython:
#   pvpython open_xdmf.py run.xdmf NX NZ
import os
import sys

from paraview import simple as pv

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "support"))
from paraview_readers import open_with_each_reader  # noqa: E402

path, nx, nz = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
failures = []
for reader, source, times, cells, arrays in open_with_each_reader(path):
    if cells != nx * nz:
        failures.append(f"{reader}: {cells} cells, not {nx * nz}")
    missing = {"u", "w", "p", "f", "I", "eta", "C", "velocity"} - arrays
    if missing:
        failures.append(f"{reader}: no {sorted(missing)}")
    if len(times) < 2:
        failures.append(f"{reader}: {len(times)} times")
    threshold = pv.Threshold(Input=source, Scalars=["CELLS", "f"])
    if hasattr(threshold, "LowerThreshold"):
        threshold.LowerThreshold, threshold.UpperThreshold = 0.5, 2.0
    else:
        threshold.ThresholdRange = [0.5, 2.0]
    threshold.UpdatePipeline(times[-1] if times else 0.0)
    kept = pv.servermanager.Fetch(threshold)
    kept_cells = kept.GetNumberOfCells() if kept else 0
    if not 0 < kept_cells < nx * nz:
        failures.append(f"{reader}: threshold f > 0.5 kept {kept_cells} cells")
    print(reader, cells, "cells,", len(times), "times,", kept_cells, "granular cells")
if failures:
    print("\n".join(failures))
    sys.exit(1)

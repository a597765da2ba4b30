# Opens a layer case's .xdmf with each of ParaView's XDMF readers and checks what a user would
# see: every run's grid (the sum of nx * nz over the runs), the field I, and every sample time.
# Run by test_cases_layer_xdmf under pvpython:
#   pvpython open_layer_xdmf.py case.xdmf CELLS TIMES
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "support"))
from paraview_readers import open_with_each_reader  # noqa: E402

path, cells_expected, times_expected = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
failures = []
for reader, source, times, cells, arrays in open_with_each_reader(path):
    if cells != cells_expected:
        failures.append(f"{reader}: {cells} cells, not {cells_expected}")
    if "I" not in arrays:
        failures.append(f"{reader}: no I")
    if len(times) != times_expected:
        failures.append(f"{reader}: {len(times)} times, not {times_expected}")
print("\n".join(failures) if failures else "ok")
sys.exit(1 if failures else 0)

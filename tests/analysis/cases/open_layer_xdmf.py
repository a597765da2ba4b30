# Opens a layer case's .xdmf with each of ParaView's XDMF readers and checks what a user would
# see: every run's grid (the sum of nx * nz over the runs), the field I, and every sample time.
# Run by test_cases_layer_xdmf under pvpython:
#   pvpython open_layer_xdmf.py case.xdmf CELLS TIMES
import sys

from paraview import simple as pv

path, cells_expected, times_expected = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
failures = []
for reader in ("XDMFReader", "Xdmf3ReaderS", "Xdmf3ReaderT"):
    name = "FileNames" if reader == "XDMFReader" else "FileName"
    source = getattr(pv, reader)(**{name: [path]})
    times = list(source.TimestepValues or [])
    merged = pv.MergeBlocks(Input=source)
    merged.UpdatePipeline(times[-1] if times else 0.0)
    block = pv.servermanager.Fetch(merged)
    cells = block.GetNumberOfCells() if block else 0
    data = block.GetCellData() if block else None
    arrays = {data.GetArrayName(i) for i in range(data.GetNumberOfArrays())} if data else set()
    if cells != cells_expected:
        failures.append(f"{reader}: {cells} cells, not {cells_expected}")
    if "I" not in arrays:
        failures.append(f"{reader}: no I")
    if len(times) != times_expected:
        failures.append(f"{reader}: {len(times)} times, not {times_expected}")
print("\n".join(failures) if failures else "ok")
sys.exit(1 if failures else 0)

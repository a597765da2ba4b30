# What a ParaView user sees when opening an .xdmf with each of the three XDMF readers (the legacy
# "XDMF Reader" and the two Xdmf3 readers): the source, its times, and at the last time the cell
# count and cell arrays of the merged data set. Shared by the pvpython scripts of the XDMF tests.
from paraview import simple as pv

READERS = ("XDMFReader", "Xdmf3ReaderS", "Xdmf3ReaderT")


def open_with_each_reader(path):
    """Yields (reader, source, times, cells, array names) for each reader."""
    for reader in READERS:
        # The legacy reader names its file property FileNames, the Xdmf3 readers FileName.
        name = "FileNames" if reader == "XDMFReader" else "FileName"
        source = getattr(pv, reader)(**{name: [path]})
        times = list(source.TimestepValues or [])
        # MergeBlocks gives one data set whatever the reader's output (a grid, or blocks of one).
        merged = pv.MergeBlocks(Input=source)
        merged.UpdatePipeline(times[-1] if times else 0.0)
        block = pv.servermanager.Fetch(merged)
        cells = block.GetNumberOfCells() if block else 0
        data = block.GetCellData() if block else None
        arrays = {data.GetArrayName(i) for i in range(data.GetNumberOfArrays())} if data else set()
        yield reader, source, times, cells, arrays

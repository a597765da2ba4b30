// `granbench sweep`, after its options are read (cmd_sweep.cpp): runs the SweepSpec on the
// resumable engine (analysis/comparison/sweep.hpp), shared among the processes when started by
// mpirun (mpi_session.hpp), and reports it: the table or JSON, the HDF5 file and the figure.
//
// Under MPI, with R ranks:
//   1. rank 0 reads the completed points kept in --out and in the part files "<out>.rank<r>.h5"
//      beside it (left by a killed multi-process run) and sends them to every rank;
//   2. each rank runs its share of the rest (point i on rank i % R) on --jobs threads, keeping
//      every finished point at once in its own part file;
//   3. the new points are gathered on rank 0, which writes --out once, complete, and removes the
//      part files; then each rank removes its own (a file system of its own machine).
// A run killed between 2 and 3 leaves the part files, and the next run — with any number of
// ranks, or one process — resumes from them (parts of other machines that rank 0 cannot see are
// run again). Only rank 0 prints (progress of its own points, the table or JSON) and plots.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/cli/cli_common.hpp"
#include "analysis/comparison/sweep.hpp"

namespace granbench::cli {

// `settings`: the command's own keys for the JSON (chi, nx, ...); `title`: the table's first line;
// `warnings`: printed once every check has passed, before the points run (physics_warnings.hpp).
void run_sweep_command(SweepSpec spec, const OutputOptions& output, const nlohmann::json& settings,
                       const std::string& title, const std::vector<std::string>& warnings);

}  // namespace granbench::cli

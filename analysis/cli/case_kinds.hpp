// The kinds of case that `granbench case` runs (cmd_case.cpp), each from its case file in this
// process: the uniform-layer cases (decelerating §5.2, high-speed §6.2), the rollwave cases (§7,
// `run --model twod` with the file's [run] table) and the well-posedness figures.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/cases/case_file.hpp"
#include "analysis/cli/cli_common.hpp"
#include "analysis/cli/shipped_files.hpp"

namespace granbench::cli {

struct CaseOptions {
  std::string name;
  bool list = false;
  std::string resolution = "paper";
  std::string out_dir = ".";
  std::string cases_dir = shipped_cases_dir();
  unsigned jobs = 2;
  OutputOptions output;
};

// <out-dir>/file
std::string path_in(const CaseOptions& o, const std::string& file);

// Each runs its kind of case and draws its figures; returns the JSON summary. `exit_code` gets
// the failure policy's code of a run that stopped early (the figures of what was computed are
// drawn first).
nlohmann::json run_layer_kind(const cases::CaseFile& file, const CaseOptions& o, int& exit_code);
nlohmann::json run_rollwave_kind(const cases::CaseFile& file, const CaseOptions& o, int& exit_code);
// Figure 13 with the 2D model, in the paper's protocol and with eigenmode seeding
// (case_figure13.cpp).
nlohmann::json run_figure13_kind(const cases::CaseFile& file, const CaseOptions& o, int& exit_code);
nlohmann::json run_wellposed_kind(const cases::CaseFile& file, const CaseOptions& o);

}  // namespace granbench::cli

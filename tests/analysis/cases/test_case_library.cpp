// Case files (typed keys, resolution overrides, errors naming the key) and the grid-dependence
// measure against exact answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>

#include "analysis/cases/case_file.hpp"
#include "analysis/cases/grid_dependence.hpp"
#include "analysis/cases/layer_case.hpp"
#include "analysis/cases/perturbation_energy.hpp"
#include "tests/support/scratch_dir.hpp"

namespace granbench::cases {
namespace {

// A case file in this process' scratch directory (its name is the case's name).
std::string write_file(const std::string& name, const std::string& text) {
  static const granbench::testing::ScratchDir dir("gb_case_library");
  const std::string path = dir / name;
  std::ofstream(path) << text;
  return path;
}

TEST(CaseFile, ResolutionTablesOverrideTopLevelKeys) {
  const CaseFile f = read_case_file(
      write_file("gb_case_a.toml",
                 "kind = \"decelerating\"\nt_end = 0.2\ncurves = [\"jop\", \"low-i\"]\n"
                 "[smoke]\nt_end = 0.01\nnx = [16, 32]\n[run]\nnx = 160\n[smoke.run]\nnx = "
                 "32\nt_end = 0.2\n"));
  EXPECT_EQ(f.name(), "gb_case_a");
  EXPECT_EQ(f.text("kind"), "decelerating");
  EXPECT_DOUBLE_EQ(f.number("t_end", "paper"), 0.2);
  EXPECT_DOUBLE_EQ(f.number("t_end", "smoke"), 0.01);
  EXPECT_EQ(f.texts("curves"), (std::vector<std::string>{"jop", "low-i"}));
  EXPECT_EQ(f.numbers("nx", "smoke"), (std::vector<double>{16, 32}));
  const auto paper = f.table("run", "paper");
  ASSERT_EQ(paper.size(), 1u);
  EXPECT_EQ(paper.at("nx"), std::vector<std::string>{"160"});
  const auto smoke = f.table("run", "smoke");
  EXPECT_EQ(smoke.at("nx"), std::vector<std::string>{"32"});
  EXPECT_EQ(smoke.at("t_end"), std::vector<std::string>{"0.2"});
}

// The progress of a layer case: a status line naming every run, and a fraction of the work done
// that only grows and ends at 1 (the ETA of `granbench case` is computed from it).
TEST(LayerCase, ProgressFractionGrowsToOne) {
  const CaseFile f = read_case_file(write_file(
      "gb_case_progress.toml",
      "kind = \"decelerating\"\nname = \"p\"\ncurves = [\"jop\"]\nangle0 = 24.0\nangle = 10.0\n"
      "h0 = 0.004\nLx_over_h0 = 2.0\nLz_over_h0 = 1.5\nt_end = 0.004\nsamples = 3\n"
      "nx = [8, 16]\nnz = [6, 12]\n"));
  const LayerCaseSpec spec = layer_case_spec(f, "paper");
  std::vector<double> fractions;
  std::string last_status;
  const LayerCaseResult r =
      run_layer_case(spec, 1, nullptr, [&](const std::string& status, double done) {
        fractions.push_back(done);
        last_status = status;
      });
  ASSERT_EQ(r.runs.size(), 2u);
  ASSERT_GE(fractions.size(), 6u);  // three samples of each run
  for (std::size_t i = 1; i < fractions.size(); ++i) EXPECT_GE(fractions[i], fractions[i - 1]);
  EXPECT_DOUBLE_EQ(fractions.front(), 0.0);  // the first sample is the initial state
  EXPECT_NEAR(fractions.back(), 1.0, 1e-12);
  // The fine run costs (2 * 2)^(3/2) = 8 times the coarse one: 1/9 of the work is done when the
  // coarse run ends (runs go in order on one worker).
  EXPECT_NE(last_status.find(spec.runs[0].label), std::string::npos);
  EXPECT_NE(last_status.find(spec.runs[1].label), std::string::npos);
  const auto coarse_end = std::find_if(fractions.begin(), fractions.end(),
                                       [](double x) { return x > 1.0 / 9.0 + 1e-12; });
  ASSERT_NE(coarse_end, fractions.begin());
  EXPECT_NEAR(*(coarse_end - 1), 1.0 / 9.0, 1e-12);
}

// A layer put on a slope below its static angle (24 -> 10 degrees, tan 10 = 0.18 < mu_s) stops
// and stays at rest. With the whole low-I stress explicit (the tangent's remainder at eta_max =
// 1e7 Pa s, viscous_step.cpp) it stopped at 0.06 s and then sped up again, to 0.03 m/s at this
// grid and 0.09-0.36 m/s at finer ones by 0.1-0.2 s, for both curves.
TEST(LayerCase, ALayerBelowItsStaticAngleStaysAtRest) {
  const CaseFile f = read_case_file(write_file(
      "gb_case_rest.toml",
      "kind = \"decelerating\"\ncurves = [\"jop\", \"low-i\"]\nangle0 = 24.0\nangle = 10.0\n"
      "h0 = 0.004\nLx_over_h0 = 2.0\nLz_over_h0 = 1.5\nt_end = 0.15\nsamples = 16\n"
      "eta_max = 1.0e7\ndt_max = 1.0e-4\nnoise = 1.0e-6\nnx = [32]\nnz = [24]\n"));
  const LayerCaseResult r = run_layer_case(layer_case_spec(f, "paper"), 2, nullptr, nullptr);
  ASSERT_EQ(r.runs.size(), 2u);
  for (const auto& run : r.runs) {
    ASSERT_EQ(run.max_speed.size(), 16u);
    EXPECT_GT(run.max_speed.front(), 0.15);  // the 24-degree Bagnold layer at the start
    // from 0.1 s on: at rest, up to the light fluid's and the noise's motion
    for (std::size_t n = 10; n < run.max_speed.size(); ++n) EXPECT_LT(run.max_speed[n], 0.01);
  }
}

// The momentum transport of a layer case: the solver's default unless the file names one; an
// unknown name is refused with the key and the valid values.
TEST(LayerCase, MomentumTransportKey) {
  const std::string base =
      "kind = \"decelerating\"\ncurves = [\"jop\"]\nangle0 = 24.0\nangle = 10.0\n"
      "h0 = 0.004\nLx_over_h0 = 2.0\nLz_over_h0 = 1.5\nt_end = 0.004\nsamples = 3\n"
      "nx = [8]\nnz = [6]\n";
  const auto consistent_of = [&](const std::string& extra, const std::string& name) {
    const LayerCaseSpec spec =
        layer_case_spec(read_case_file(write_file(name, base + extra)), "paper");
    return spec.runs.at(0).params.consistent_momentum;
  };
  EXPECT_EQ(consistent_of("", "gb_case_mt0.toml"), twod::SolverParams{}.consistent_momentum);
  EXPECT_FALSE(consistent_of("momentum_transport = \"velocity\"\n", "gb_case_mt1.toml"));
  EXPECT_TRUE(consistent_of("momentum_transport = \"consistent\"\n", "gb_case_mt2.toml"));
  try {
    consistent_of("momentum_transport = \"mass\"\n", "gb_case_mt3.toml");
    FAIL();
  } catch (const CaseFileError& e) {
    EXPECT_NE(std::string(e.what()).find("'momentum_transport' = 'mass'; valid values"),
              std::string::npos);
  }
}

TEST(CaseFile, ErrorsNameTheKeyAndTheRange) {
  const CaseFile f = read_case_file(write_file("gb_case_b.toml", "angle = 95\nname = \"x\"\n"));
  try {
    f.number_in("angle", "paper", 0.0, 89.0);
    FAIL();
  } catch (const CaseFileError& e) {
    EXPECT_NE(std::string(e.what()).find("'angle' = 95 out of range; valid range [0, 89]"),
              std::string::npos);
  }
  EXPECT_THROW(f.number("name"), CaseFileError);         // not a number
  EXPECT_THROW(f.number("h0", "smoke"), CaseFileError);  // missing
  EXPECT_THROW(read_case_file("/nonexistent/case.toml"), CaseFileError);
}

// Case files are read as strictly as --config files (common/toml_reader.hpp): text that is not
// TOML is an error naming the file and the line, not a table silently read as something else
// (CLI11's reader, used before, took "[run" and "t_end = 1 2" without a word).
TEST(CaseFile, TextThatIsNotTomlIsRefusedWithTheLine) {
  for (const auto& [text, line] : std::vector<std::pair<std::string, std::string>>{
           {"kind = \"rollwave\"\n[run\nnx = 32\n", ":2:"},
           {"kind = \"rollwave\"\nt_end = 1 2\n", ":2:"},
           {"kind = rollwave\n", ":1:"},
           {"kind = \"a\"\nkind = \"b\"\n", ":2:"}}) {
    const std::string path = write_file("gb_case_bad.toml", text);
    try {
      (void)read_case_file(path);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const CaseFileError& e) {
      EXPECT_NE(std::string(e.what()).find(path + line), std::string::npos) << e.what();
    }
  }
}

LayerRunRecord profile_record(int nz, double Lz, std::vector<double> I) {
  LayerRunRecord r;
  r.nz = nz, r.Lz = Lz, r.nx = 1, r.Lx = 1.0;
  r.t = {0.0};
  r.I_profile = {std::move(I)};
  return r;
}

TEST(GridDependence, ExactForKnownProfiles) {
  // Coarse: 4 cells on Lz = 2 h0 (h0 = 1): cells wholly below h0 - dz = 0.5: only k = 0.
  // Use 8 coarse cells instead: dz = 0.25, bulk cells k = 0, 1, 2 (tops 0.25, 0.5, 0.75).
  const double h0 = 1.0, Lz = 2.0;
  std::vector<double> coarse(8, 1e-2), fine(16, 1e-2);
  EXPECT_DOUBLE_EQ(grid_dependence(profile_record(8, Lz, coarse), profile_record(16, Lz, fine), h0)
                       .rms_log10_I[0],
                   0.0);
  // The fine profile ten times larger in every bulk cell: one decade everywhere.
  for (int k = 0; k < 6; ++k) fine[k] = 1e-1;
  EXPECT_NEAR(grid_dependence(profile_record(8, Lz, coarse), profile_record(16, Lz, fine), h0)
                  .rms_log10_I[0],
              1.0, 1e-14);
  // Only one of three bulk cells off by a decade (the pair of fine cells it covers): sqrt(1/3).
  std::fill(fine.begin(), fine.end(), 1e-2);
  fine[2] = fine[3] = 1e-1;
  EXPECT_NEAR(grid_dependence(profile_record(8, Lz, coarse), profile_record(16, Lz, fine), h0)
                  .rms_log10_I[0],
              std::sqrt(1.0 / 3.0), 1e-14);
  // Cells at and above h0 - dz are ignored.
  std::fill(fine.begin(), fine.end(), 1e-2);
  fine[6] = fine[7] = fine[12] = 5.0;
  EXPECT_DOUBLE_EQ(grid_dependence(profile_record(8, Lz, coarse), profile_record(16, Lz, fine), h0)
                       .rms_log10_I[0],
                   0.0);
  // Flowing: some bulk row's mean speed above 1e-3 m/s in both runs. Without u_profile, never.
  EXPECT_FALSE(grid_dependence(profile_record(8, Lz, coarse), profile_record(16, Lz, fine), h0)
                   .both_flowing[0]);
  auto moving = [&](int nz, double u_bulk, double u_top) {
    LayerRunRecord r = profile_record(nz, Lz, std::vector<double>(nz, 1e-2));
    r.u_profile = {std::vector<double>(nz, u_top)};
    for (int k = 0; k < bulk_cells(nz, Lz, h0); ++k) r.u_profile[0][k] = u_bulk;
    return r;
  };
  EXPECT_TRUE(grid_dependence(moving(8, 2e-3, 0.0), moving(16, -2e-3, 0.0), h0).both_flowing[0]);
  EXPECT_FALSE(grid_dependence(moving(8, 2e-3, 0.0), moving(16, 5e-4, 0.0), h0).both_flowing[0]);
  // Speed above the bulk (the surface rows, the light fluid) does not count.
  EXPECT_FALSE(grid_dependence(moving(8, 2e-3, 0.0), moving(16, 0.0, 1.0), h0).both_flowing[0]);
  // Not a refinement in z: rejected.
  EXPECT_THROW(grid_dependence(profile_record(8, Lz, coarse),
                               profile_record(12, Lz, std::vector<double>(12, 1.0)), h0),
               std::invalid_argument);
}

// E of a layer whose I is known cell by cell: rows at z <= 0.8 h0 that are grains all along x
// count, others not; a row I = m (1 + e cos(2 pi i / nx)) gives ((I - m)/m)^2 averaged = e^2 / 2.
TEST(PerturbationEnergy, ExactForKnownFields) {
  LayerRunRecord r;
  r.nx = 8;
  r.nz = 5;
  const double h0 = 1.0;
  r.z = {0.1, 0.3, 0.5, 0.7, 0.9};  // the last row lies above 0.8 h0 and is left out
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> field(std::size_t(r.nx) * r.nz);
  const double e[] = {0.1, 0.2, 0.0, 0.3, 5.0};
  for (int k = 0; k < r.nz; ++k)
    for (int i = 0; i < r.nx; ++i)
      field[k * r.nx + i] = 2.0 * (1.0 + e[k] * std::cos(2.0 * std::numbers::pi * i / r.nx));
  field[3 * r.nx + 5] = nan;  // row 3 has a cell without grains: left out
  r.I_field = {field};
  r.t = {0.0};
  const auto E = perturbation_energy(r, h0);
  ASSERT_EQ(E.size(), 1u);
  EXPECT_NEAR(E[0], (0.01 + 0.04 + 0.0) / 2.0 / 3.0, 1e-15);
}

// The growth rate of an exact exponential between the two levels, its window, and the two ways
// of having none: never out of the noise, or too few samples in the exponential phase.
TEST(PerturbationEnergy, GrowthRateOfTheExponentialPhase) {
  std::vector<double> t, E;
  for (int n = 0; n <= 100; ++n) {
    t.push_back(0.01 * n);
    // noise level 1e-10 until 0.2 s, then e^{50 (t - 0.2)} 1e-10, saturating at 0.1
    E.push_back(std::min(0.1, 1e-10 * std::exp(50.0 * std::max(t.back() - 0.2, 0.0))));
  }
  const EnergyGrowth g = energy_growth(t, E, 1e-8, 1e-3);
  ASSERT_TRUE(g.rate.has_value()) << g.reason;
  EXPECT_NEAR(*g.rate, 50.0, 1e-9);
  EXPECT_NEAR(g.t_from, 0.30, 1e-12);  // the first sample at or above 1e-8: e^{50 t'} >= 100
  EXPECT_NEAR(g.t_to, 0.52, 1e-12);    // the last at or below 1e-3: e^{50 t'} <= 1e7
  EXPECT_EQ(g.samples, 23);

  std::vector<double> quiet(t.size(), 1e-11);
  const EnergyGrowth none = energy_growth(t, quiet, 1e-8, 1e-3);
  EXPECT_FALSE(none.rate.has_value());
  EXPECT_NE(none.reason.find("never reaches"), std::string::npos) << none.reason;

  std::vector<double> jump(t.size(), 1e-11);
  for (std::size_t n = 50; n < t.size(); ++n) jump[n] = n < 52 ? 1e-6 : 1.0;
  const EnergyGrowth short_phase = energy_growth(t, jump, 1e-8, 1e-3);
  EXPECT_FALSE(short_phase.rate.has_value());
  EXPECT_NE(short_phase.reason.find("only 2 samples"), std::string::npos) << short_phase.reason;
}

}  // namespace
}  // namespace granbench::cases

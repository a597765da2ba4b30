// granbench sweep: growth rate and phase speed of the linear waves over a range of domain lengths,
// measured by the model(s) beside the exact theory — the paper's figure 13.
//
//   granbench sweep --model depthavg --Lx 0.03:0.4:12 --jobs 2 --json
//   granbench sweep --model depthavg --Lx 0.02:0.6:24 --chi bagnold --plot fig13.png
//   granbench sweep --model both --Lx 0.01:0.08:8 --out sweep.h5 --plot fig13.png
//   mpirun -np 4 granbench sweep --model depthavg --Lx 0.02:0.4:32 --jobs 1 --out sweep.h5
//
// With --model depthavg each point is a clean linear measurement
// (analysis/comparison/depthavg_linear_run.hpp): the normal mode (7.10) seeded at amplitude 1e-4
// h0, unlimited central reconstruction, tight tolerances, the growth rate and phase speed fitted
// spectrally over an automatically found window, against (7.11). With --model twod|both each point
// is a run seeded with the eigenmode of the model's own theory, measured like `compare`. All go
// through the resumable engine (analysis/comparison/sweep.hpp) on --jobs threads, shared among the
// ranks under mpirun (sweep_models.hpp): finished points are kept in --out and a re-run skips them.
// The options and the spec they make: sweep_plan.hpp.
#include "analysis/cli/commands.hpp"
#include "analysis/cli/help_footer.hpp"
#include "analysis/cli/sweep_models.hpp"
#include "analysis/cli/sweep_plan.hpp"

namespace granbench::cli {

void add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* sub = app.add_subcommand(
      "sweep", "measured linear growth rate and phase speed over domain lengths vs (7.11)");
  sub->footer(help_footer({"granbench sweep --model depthavg --Lx 0.03:0.4:12 --jobs 2 --json",
                           "granbench sweep --model both --Lx 0.01:0.08:8 --out sweep.h5",
                           "mpirun -np 4 granbench sweep --Lx 0.02:0.4:32 --jobs 1 --out sweep.h5"},
                          {0, 2, 3, 130}));
  add_sweep_options(*sub, *o);
  add_threads_option(*sub);
  sub->callback([o, sub] {
    SweepPlan plan = plan_sweep(*o, *sub);
    add_growth_accuracy_warnings(*o, plan);
    run_sweep_command(std::move(plan.spec), o->output, plan.settings, plan.title, plan.warnings);
  });
}

}  // namespace granbench::cli

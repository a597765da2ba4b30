// What a parallel loop of the 2D solver costs on two threads, apart from the solver (not a test):
// the hand-off of a loop to the thread team and the moving of data between the cores, measured
// on loops of the size of a 256 x 64 step's (docs/performance.md, forty-sixth session).
//
// Three row-major fields of nx x nz doubles (256 x 64: 128 kB each, as the solver's) go through
// y = y + s x, loop after loop, on the solver's own team (twod/parallel.hpp), dealt in one of
// four ways:
//   rows         every loop split by rows (each thread its contiguous block of rows);
//   every_other  each thread every other row, the same rows in every loop (like the rows dealt
//                out by the golden ratio that the solver had for rows of uneven cost until the
//                forty-sixth session);
//   columns      every loop split by columns (each thread its part of every row);
//   alternate    rows, then columns, then rows...: half of each thread's data was last written by
//                the other core, as when a row loop of the solver is followed by a column loop
//                (the fields are row-major, the multigrid's and the viscous lines' vectors
//                column-major);
// and an empty loop (the hand-off alone). Each is timed per loop on one thread and on two, with
// the cores' round trip (bench/core_placement.hpp) before and after. If the two threads gain in
// `rows` and lose it in the others, what costs is the data that both cores write near each other,
// not the hand-off.
//
//   bench_thread_handoff            256 x 64, 20 000 loops per measurement
//   bench_thread_handoff NX NZ N    other field sizes and loop counts
#include <algorithm>
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "bench/core_placement.hpp"
#include "twod/parallel.hpp"

using namespace granbench::twod;
using granbench::bench::available_cpus;
using granbench::bench::core_round_trip_ns;

namespace {

enum class Deal { Rows, EveryOther, Columns, Alternate, Empty };

struct Fields {
  int nx, nz;
  std::vector<double> x, y, z;
};

// y += s x over the rows [k0, k1) and columns [i0, i1), and z = y there (three arrays touched, as
// a typical loop of the solver).
void axpy_block(Fields& f, int k0, int k1, int i0, int i1, double s) {
  for (int k = k0; k < k1; ++k) {
    double* y = &f.y[std::size_t(k) * f.nx];
    double* z = &f.z[std::size_t(k) * f.nx];
    const double* x = &f.x[std::size_t(k) * f.nx];
    for (int i = i0; i < i1; ++i) {
      y[i] += s * x[i];
      z[i] = y[i];
    }
  }
}

// Seconds per loop of `loops` loops dealt as `deal`.
double seconds_per_loop(Fields& f, Deal deal, int loops) {
  const double s = 1e-9;
  const auto t0 = std::chrono::steady_clock::now();
  for (int n = 0; n < loops; ++n) {
    const bool by_rows = deal == Deal::Rows || (deal == Deal::Alternate && n % 2 == 0);
    if (deal == Deal::Empty)
      parallel_for_ranges(f.nz, [&](int, int) {});
    else if (deal == Deal::EveryOther) {
      const int members = thread_count();
      parallel_for(members, true, [&](int m) {
        for (int k = m; k < f.nz; k += members) axpy_block(f, k, k + 1, 0, f.nx, s);
      });
    } else if (by_rows)
      parallel_for_ranges(f.nz, [&](int k0, int k1) { axpy_block(f, k0, k1, 0, f.nx, s); });
    else
      parallel_for_ranges(f.nx, [&](int i0, int i1) { axpy_block(f, 0, f.nz, i0, i1, s); });
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / loops;
}

}  // namespace

int main(int argc, char** argv) {
  const int nx = argc > 1 ? std::stoi(argv[1]) : 256;
  const int nz = argc > 2 ? std::stoi(argv[2]) : 64;
  const int loops = argc > 3 ? std::stoi(argv[3]) : 20000;
  if (nx < 2 || nz < 2 || loops < 1) {
    std::cerr << "usage: bench_thread_handoff [NX >= 2] [NZ >= 2] [LOOPS >= 1]\n";
    return 2;
  }
  const std::size_t cells = std::size_t(nx) * nz;
  Fields f{nx, nz, std::vector<double>(cells, 1.0), std::vector<double>(cells, 0.0),
           std::vector<double>(cells, 0.0)};
  nlohmann::json out = {{"nx", nx}, {"nz", nz}, {"loops", loops}, {"bytes_per_field", 8 * cells}};
  const bool two_cores = available_cpus() >= 2;
  if (two_cores) out["core_round_trip_ns"]["before"] = core_round_trip_ns();
  const std::pair<Deal, const char*> deals[] = {{Deal::Empty, "empty"},
                                                {Deal::Rows, "rows"},
                                                {Deal::EveryOther, "every_other"},
                                                {Deal::Columns, "columns"},
                                                {Deal::Alternate, "alternate"}};
  for (int threads : {1, 2}) {
    if (threads > 1 && !two_cores) break;
    set_thread_count(threads);
    for (const auto& [deal, name] : deals) {
      seconds_per_loop(f, deal, loops / 10);  // (the team started, the shares balanced)
      // the median of five measurements: the host takes a core now and then
      std::vector<double> times;
      for (int rep = 0; rep < 5; ++rep) times.push_back(seconds_per_loop(f, deal, loops));
      std::nth_element(times.begin(), times.begin() + 2, times.end());
      out["microseconds_per_loop"][name][std::to_string(threads)] = 1e6 * times[2];
    }
  }
  if (two_cores) {
    out["core_round_trip_ns"]["after"] = core_round_trip_ns();
    for (const auto& [deal, name] : deals) {
      if (deal == Deal::Empty) continue;
      const auto& t = out["microseconds_per_loop"][name];
      out["two_thread_speedup"][name] = t["1"].get<double>() / t["2"].get<double>();
    }
  }
  std::cout << out.dump(2) << "\n";
  return 0;
}

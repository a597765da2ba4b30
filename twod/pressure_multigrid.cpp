// Geometric multigrid V-cycle for  -div(beta grad p) = b  on the cell-centred MAC grid, the
// preconditioner of the projection's conjugate gradients (projection.cpp).
//
//   smoother     zebra z-line Gauss-Seidel: each column i is solved exactly (Thomas algorithm)
//                with its x-neighbours at their latest values, even columns then odd ones
//                before the coarse correction and the reverse after it, so the cycle is
//                symmetric (valid for CG).
//                Whole columns are solved at once because the grid is finer in z than in x
//                (coefficient ratio (dx/dz)^2) and the density jump of the free surface
//                (beta jumps by rho_g/rho_l = 1500/0.0015 = 1e6 with the default light fluid)
//                runs across the columns.
//                The columns of one colour are solved eight side by side, one per vector lane
//                (kLineLanes; solve_column_group), the rest four at a time: the recurrences in
//                z are chains of dependent operations, whose latency bounded the solve of one or
//                four columns (the smoother went from 15 % to 8 % of a 256 x 64 step,
//                docs/performance.md, thirty-first session). Every grouping does the same
//                arithmetic on a column, so the results are the same to the last bit.
//   coarsening   both directions where the cells are at least twice as wide as tall; x alone
//                (semi-coarsening) below that. The z-line smoother damps every error that
//                varies fast in z, and the zebra order the error that varies fast in x; on
//                nearly square cells the full coarsening's coarse operators then average the
//                surface's density jump over two rows, and the cycle converges about half as
//                fast (160 x 16 cells, dx / dz = 0.94: 16.4 projection iterations per step with
//                full coarsening, 7.3 with x alone first; docs/performance.md, thirtieth session).
//   transfer     piecewise-constant prolongation P, restriction R = P^T (sum of the 2 x 2 cells,
//                or of the 2 x 1 cells after coarsening in x alone).
//   coarse op.   face coefficients of the rediscretisation for constant beta: a coarse face
//                made of two fine faces takes their mean (full coarsening) or their sum (a
//                z-face after x alone), one made of one fine face half of it (an x-face after x
//                alone: twice the distance); the jump stays in place.
//   coarsest     dense LDLT once the grid cannot be halved (or is tiny); 20 symmetric line
//                sweeps instead when an odd size stops the coarsening above 2048 cells
//                (kDirectCoarsestCells): several times the cost of a step, which is why compare
//                and sweep keep their cell counts multiples of 16.
// Threads (parallel.hpp): the columns of one colour are independent, so each colour's columns are
// solved in parallel; the operator, factors and grid transfers are parallel over columns. Every
// value is computed by the same arithmetic for any thread count. Levels below kParallelCells
// cells stay on one thread (too little work to share).
#include "twod/pressure_multigrid.hpp"

#include <type_traits>

#include "twod/parallel.hpp"

namespace granbench::twod {

namespace {
constexpr int kParallelCells = 2048;
}  // namespace

void PoissonLevel::apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  y.resize(nx * nz);
  parallel_for(nx, nx * nz >= kParallelCells, [&](int i) {
    const int il = i == 0 ? nx - 1 : i - 1, ir = i == nx - 1 ? 0 : i + 1;
    const double* cl = &cx[cell(i, 0)];
    const double* cr = &cx[cell(ir, 0)];
    const double* czi = &cz[zface(i, 0)];
    const double* xi = &x[cell(i, 0)];
    const double* xl = &x[cell(il, 0)];
    const double* xr = &x[cell(ir, 0)];
    double* yi = &y[cell(i, 0)];
    // One pass over the column, the bed and top rows apart (no face below, none above to a
    // cell); each row's operations in the same order as ever: the diagonal part, then the face
    // below, then the face above, so the result is the same to the last bit. (Three passes over
    // the column, one per term, each with a run-time overlap check, took 6.0 % of a one-thread
    // 160 x 16 step; one pass 4.4 %.)
    auto centre = [&](int k) {
      return cl[k] * (xi[k] - xl[k]) + cr[k] * (xi[k] - xr[k]) + (czi[k] + czi[k + 1]) * xi[k];
    };
    yi[0] = nz > 1 ? centre(0) - czi[1] * xi[1] : centre(0);  // the bed face has czi[0] = 0
#pragma omp simd  // (y is never x: no check for overlap needed)
    for (int k = 1; k < nz - 1; ++k)
      yi[k] = centre(k) - czi[k] * xi[k - 1] - czi[k + 1] * xi[k + 1];
    if (nz > 1) yi[nz - 1] = centre(nz - 1) - czi[nz - 1] * xi[nz - 2];
  });
}

namespace {
// kLineLanes values, one per column of a group (PoissonLevel's line_* arrays)
using LineVector = double __attribute__((vector_size(kLineLanes * sizeof(double))));
}  // namespace

void PoissonLevel::factorise() {
  // The Thomas factors of every column: for the columns of the smoother's groups (the header)
  // in their lanes, kLineLanes columns at once, with their coefficients; for the others (the
  // remainder of each colour, or every column of an odd nx) column by column in cp and inv_m,
  // which the grouped columns do not use. Either way each column's factors come from the same
  // arithmetic (solve_column_group below).
  line_groups = nx % 2 == 0 ? nx / 2 / kLineLanes : 0;
  const std::size_t entries = std::size_t(2 * line_groups) * nz * kLineLanes;
  for (auto* v : {&line_cl, &line_cr, &line_cz, &line_inv_m, &line_cp}) v->resize(entries);
  line_work.resize(entries);
  cp.resize(nx * nz);
  inv_m.resize(nx * nz);
  const bool parallel = nx * nz >= kParallelCells;
  parallel_for(2 * line_groups, parallel, [&](int cg) {
    const int colour = cg / line_groups, g = cg % line_groups;
    int i[kLineLanes], ir[kLineLanes];
    for (int j = 0; j < kLineLanes; ++j) {
      i[j] = colour + 2 * (kLineLanes * g + j);
      ir[j] = i[j] == nx - 1 ? 0 : i[j] + 1;
    }
    LineVector cp_below = {};
    for (int k = 0; k < nz; ++k) {
      LineVector left, right, face, face_above;
      for (int j = 0; j < kLineLanes; ++j) {
        left[j] = cx[cell(i[j], k)];
        right[j] = cx[cell(ir[j], k)];
        face[j] = cz[zface(i[j], k)];
        face_above[j] = cz[zface(i[j], k + 1)];
      }
      const LineVector zero = {};
      const LineVector diag = left + right + face + face_above;
      const LineVector lower = k > 0 ? -face : zero, upper = k < nz - 1 ? -face_above : zero;
      const LineVector inv = 1.0 / (diag - (k > 0 ? lower * cp_below : zero));
      cp_below = upper * inv;
      const std::size_t e = (std::size_t(cg) * nz + k) * kLineLanes;
      __builtin_memcpy(&line_cl[e], &left, sizeof left);
      __builtin_memcpy(&line_cr[e], &right, sizeof right);
      __builtin_memcpy(&line_cz[e], &face, sizeof face);
      __builtin_memcpy(&line_inv_m[e], &inv, sizeof inv);
      __builtin_memcpy(&line_cp[e], &cp_below, sizeof cp_below);
    }
  });
  const int grouped = kLineLanes * line_groups;
  const int rest = nx % 2 == 0 ? nx / 2 - grouped : 0;  // ungrouped columns of each colour
  auto column = [&](int i) {
    const int ir = i == nx - 1 ? 0 : i + 1;
    for (int k = 0; k < nz; ++k) {
      const int c = cell(i, k);
      const double diag = cx[c] + cx[cell(ir, k)] + cz[zface(i, k)] + cz[zface(i, k + 1)];
      const double lower = k > 0 ? -cz[zface(i, k)] : 0.0,
                   upper = k < nz - 1 ? -cz[zface(i, k + 1)] : 0.0;
      inv_m[c] = 1.0 / (diag - (k > 0 ? lower * cp[c - 1] : 0.0));
      cp[c] = upper * inv_m[c];
    }
  };
  if (nx % 2 == 1)
    parallel_for(nx, parallel, column);
  else
    parallel_for(2 * rest, parallel, [&](int r) {
      column(r % 2 + 2 * (grouped + r / 2));  // colour r % 2, its column grouped + r / 2
    });
}

namespace {

bool can_halve(int nx, int nz) {
  return nx % 2 == 0 && nz % 2 == 0 && nz >= 4 && nx >= 4 && nx * nz > 64;
}

bool can_halve_x(int nx, int nz) {
  return nx % 2 == 0 && nx >= 4 && nx * nz > 64;
}

enum class Halving { None, XAlone, Both };

// The next coarser level's counts and aspect, and how they were halved (None at the coarsest).
Halving coarsen(int& nx, int& nz, double& aspect) {
  if (aspect < kCoarsenXAloneBelowAspect) {
    if (!can_halve_x(nx, nz)) return Halving::None;
    nx /= 2;
    aspect *= 2.0;
    return Halving::XAlone;
  }
  if (!can_halve(nx, nz)) return Halving::None;
  nx /= 2;
  nz /= 2;
  return Halving::Both;
}

}  // namespace

std::pair<int, int> coarsest_level(int nx, int nz, double aspect) {
  while (coarsen(nx, nz, aspect) != Halving::None) {
  }
  return {nx, nz};
}

void PressureMultigrid::set_operator(const PoissonLevel& fine, double aspect) {
  PoissonLevel& F = fine_operator(fine.nx, fine.nz, aspect);
  F.cx = fine.cx;
  F.cz = fine.cz;
  rebuild();
}

PoissonLevel& PressureMultigrid::fine_operator(int nx, int nz, double aspect) {
  if (levels_.empty() || levels_.front().nx != nx || levels_.front().nz != nz ||
      aspect != aspect_) {
    aspect_ = aspect;
    PoissonLevel fine;
    fine.nx = nx;
    fine.nz = nz;
    fine.cx.assign(std::size_t(nx) * nz, 0.0);
    fine.cz.assign(std::size_t(nx) * (nz + 1), 0.0);
    levels_.assign(1, fine);
    for (int cx = nx, cz = nz;;) {
      const Halving halving = coarsen(cx, cz, aspect);
      if (halving == Halving::None) break;
      PoissonLevel C;
      C.nx = cx;
      C.nz = cz;
      C.halved_x_alone = halving == Halving::XAlone;
      C.cx.assign(C.nx * C.nz, 0.0);
      C.cz.assign(C.nx * (C.nz + 1), 0.0);
      levels_.push_back(C);
    }
    rhs_c_.resize(levels_.size());
    x_c_.resize(levels_.size());
  }
  return levels_.front();
}

void PressureMultigrid::rebuild() {
  for (std::size_t l = 1; l < levels_.size(); ++l) {
    const PoissonLevel& F = levels_[l - 1];
    PoissonLevel& C = levels_[l];
    const bool x_alone = C.halved_x_alone;
    parallel_for(C.nx, F.nx * F.nz >= kParallelCells, [&](int i) {
      if (x_alone) {
        for (int k = 0; k < C.nz; ++k) C.cx[C.cell(i, k)] = 0.5 * F.cx[F.cell(2 * i, k)];
        for (int k = 0; k <= C.nz; ++k)
          C.cz[C.zface(i, k)] = F.cz[F.zface(2 * i, k)] + F.cz[F.zface(2 * i + 1, k)];
        return;
      }
      for (int k = 0; k < C.nz; ++k)
        C.cx[C.cell(i, k)] = 0.5 * (F.cx[F.cell(2 * i, 2 * k)] + F.cx[F.cell(2 * i, 2 * k + 1)]);
      for (int k = 0; k <= C.nz; ++k)
        C.cz[C.zface(i, k)] = 0.5 * (F.cz[F.zface(2 * i, 2 * k)] + F.cz[F.zface(2 * i + 1, 2 * k)]);
    });
  }
  for (PoissonLevel& L : levels_) L.factorise();  // (parallel inside)
  const PoissonLevel& B = levels_.back();
  const int n = B.nx * B.nz;
  direct_coarsest_ = n <= kDirectCoarsestCells;
  if (!direct_coarsest_) return;  // grids that cannot be halved far: iterate on the coarsest
  Eigen::MatrixXd dense(n, n);
  Eigen::VectorXd e = Eigen::VectorXd::Zero(n), col;
  for (int j = 0; j < n; ++j) {
    e[j] = 1.0;
    B.apply(e, col);
    dense.col(j) = col;
    e[j] = 0.0;
  }
  coarsest_.compute(dense);
}

namespace {

// Thomas algorithm on the columns i[0..n) of level L at once (n <= 4, columns not neighbours):
// -cz_k x_{k-1} + diag_k x_k - cz_{k+1} x_{k+1} = b_k + cx_left x_left + cx_right x_right,
// with the factors of PoissonLevel::factorise(). Independent recurrences in one loop keep the
// floating-point pipeline busy; each column's arithmetic is the same as when solved alone.
// With zero_neighbours the x-neighbours are taken as 0 without being read (the first colour of
// the first sweep from x = 0).
template <int n, bool zero_neighbours = false>
void solve_columns(const PoissonLevel& L, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   const int (&cols)[n]) {
  const int nx = L.nx, nz = L.nz;
  const double *cl[n], *cr[n], *cz[n], *cp[n], *inv_m[n], *xl[n], *xr[n], *bi[n];
  double* xi[n];
  for (int j = 0; j < n; ++j) {
    const int i = cols[j];
    const int il = i == 0 ? nx - 1 : i - 1, ir = i == nx - 1 ? 0 : i + 1;
    const int c0 = L.cell(i, 0);
    cl[j] = &L.cx[c0];
    cr[j] = &L.cx[L.cell(ir, 0)];
    cz[j] = &L.cz[L.zface(i, 0)];
    cp[j] = &L.cp[c0];
    inv_m[j] = &L.inv_m[c0];
    xl[j] = &x[L.cell(il, 0)];
    xr[j] = &x[L.cell(ir, 0)];
    bi[j] = &b[c0];
    xi[j] = &x[c0];
  }
  double d[n] = {};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n; ++j) {
      const double rhs =
          zero_neighbours ? bi[j][k] : bi[j][k] + cl[j][k] * xl[j][k] + cr[j][k] * xr[j][k];
      d[j] = (rhs + cz[j][k] * d[j]) * inv_m[j][k];  // lower = -cz[k]; d = 0 for k = 0
      xi[j][k] = d[j];
    }
  for (int k = nz - 2; k >= 0; --k)
    for (int j = 0; j < n; ++j) xi[j][k] -= cp[j][k] * xi[j][k + 1];
}

// The Thomas algorithm of solve_columns on the kLineLanes columns of group g of one colour at
// once, lane j in element j of a vector: each column's arithmetic is exactly the scalar one (the
// same operations in the same order; no contraction, CMakeLists.txt), so the result does not
// depend on whether a column is solved here or alone. The latency of the recurrences in k, which
// bound the scalar solve, is paid once for all the group's columns.
// (Its lambdas return 512-bit vectors, whose calling convention differs with and without
// AVX-512; GCC warns of that on builds without it. They are inlined here and never called across
// a translation unit, so the warning does not apply. Filling the vectors through references
// instead made the 256 x 64 step 3-5 % slower.)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
template <bool zero_neighbours>
void solve_column_group(const PoissonLevel& L, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                        int colour, int g) {
  const int nx = L.nx, nz = L.nz;
  std::size_t at[kLineLanes], left[kLineLanes], right[kLineLanes];  // column starts
  for (int j = 0; j < kLineLanes; ++j) {
    const int i = colour + 2 * (kLineLanes * g + j);
    at[j] = std::size_t(L.cell(i, 0));
    left[j] = std::size_t(L.cell(i == 0 ? nx - 1 : i - 1, 0));
    right[j] = std::size_t(L.cell(i == nx - 1 ? 0 : i + 1, 0));
  }
  const std::size_t base = std::size_t(colour * L.line_groups + g) * nz * kLineLanes;
  // Raw pointers, taken once: through the vectors the loops reloaded each array's address on
  // every row (a store through memcpy may alias anything, so GCC could not keep them).
  const double *line_cl = &L.line_cl[base], *line_cr = &L.line_cr[base],
               *line_cz = &L.line_cz[base], *line_inv_m = &L.line_inv_m[base],
               *line_cp = &L.line_cp[base];
  double* work = &L.line_work[base];
  const double* bv = b.data();
  double* xv = x.data();
  auto coefficient = [](const double* v, int k) {
    LineVector r;
    __builtin_memcpy(&r, v + std::size_t(k) * kLineLanes, sizeof r);
    return r;
  };
  auto gather = [](const double* v, const std::size_t(&start)[kLineLanes], int k) {
    LineVector r;
    for (int j = 0; j < kLineLanes; ++j) r[j] = v[start[j] + k];
    return r;
  };
  LineVector d = {};
  for (int k = 0; k < nz; ++k) {
    const LineVector rhs = zero_neighbours
                               ? gather(bv, at, k)
                               : gather(bv, at, k) + coefficient(line_cl, k) * gather(xv, left, k) +
                                     coefficient(line_cr, k) * gather(xv, right, k);
    d = (rhs + coefficient(line_cz, k) * d) * coefficient(line_inv_m, k);
    __builtin_memcpy(work + std::size_t(k) * kLineLanes, &d, sizeof d);
  }
  LineVector next = d;  // row nz - 1: the forward value is final
  for (int j = 0; j < kLineLanes; ++j) xv[at[j] + nz - 1] = next[j];
  for (int k = nz - 2; k >= 0; --k) {
    LineVector xk;
    __builtin_memcpy(&xk, work + std::size_t(k) * kLineLanes, sizeof xk);
    xk -= coefficient(line_cp, k) * next;
    next = xk;
    for (int j = 0; j < kLineLanes; ++j) xv[at[j] + k] = xk[j];
  }
}
#pragma GCC diagnostic pop

}  // namespace

void PressureMultigrid::line_sweep(const PoissonLevel& L, const Eigen::VectorXd& b,
                                   Eigen::VectorXd& x, bool forward, bool from_zero) const {
  // Zebra order: even columns, then odd ones (forward); the exact reverse backward. Columns of
  // one colour are not neighbours, except the first and the last when nx is odd (periodic): the
  // last column of an odd nx is then solved alone, after the others of its colour (forward) or
  // before them (backward). The others are independent, so they are solved in parallel, four at
  // a time (groups fixed by their index; each column's arithmetic is the same as alone; four
  // interleaved recurrences hide the latency of each step better than two: the 256 x 64 rollwave
  // on one thread ran 2-3 % faster than with pairs).
  const int nx = L.nx;
  const bool parallel = nx * L.nz >= kParallelCells;
  auto sweep_colour = [&](int first, bool ascending, auto zero_neighbours) {
    constexpr bool zero = decltype(zero_neighbours)::value;
    const int count = first < nx ? (nx - 1 - first) / 2 + 1 : 0;
    const bool last_alone = nx % 2 == 1 && first == 0 && count > 1;  // column nx - 1
    const int free = last_alone ? count - 1 : count;                 // columns first + 2m, m < free
    // Groups of kLineLanes columns side by side (even nx, PoissonLevel::factorise), then the
    // rest four and one at a time.
    const int groups = L.line_groups;
    const int grouped = kLineLanes * groups;
    const int quads = (free - grouped) / 4;
    if (last_alone && !ascending) solve_columns<1>(L, b, x, {nx - 1});
    parallel_for(groups, parallel, [&](int g) { solve_column_group<zero>(L, b, x, first, g); });
    parallel_for(quads, parallel, [&](int m) {
      const int c = first + 2 * grouped + 8 * m;
      solve_columns<4, zero>(L, b, x, {c, c + 2, c + 4, c + 6});
    });
    for (int m = grouped + 4 * quads; m < free; ++m)
      solve_columns<1, zero>(L, b, x, {first + 2 * m});
    if (last_alone && ascending) solve_columns<1>(L, b, x, {nx - 1});
  };
  if (forward && from_zero) {  // x = 0 on entry: the even columns see zero neighbours
    sweep_colour(0, true, std::true_type{});
    sweep_colour(1, true, std::false_type{});
  } else if (forward) {
    sweep_colour(0, true, std::false_type{});
    sweep_colour(1, true, std::false_type{});
  } else {
    sweep_colour(1, false, std::false_type{});
    sweep_colour(0, false, std::false_type{});
  }
}

void PressureMultigrid::vcycle(std::size_t l, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  const PoissonLevel& L = levels_[l];
  if (l + 1 == levels_.size()) {
    if (direct_coarsest_) {
      x = coarsest_.solve(b);
    } else {
      x.setZero(L.nx * L.nz);
      for (int sweep = 0; sweep < 20; ++sweep) {
        line_sweep(L, b, x, true, false);
        line_sweep(L, b, x, false, false);
      }
    }
    return;
  }
  const bool parallel = L.nx * L.nz >= kParallelCells;
  const PoissonLevel& C = levels_[l + 1];
  Eigen::VectorXd& rc = rhs_c_[l + 1];
  rc.resize(C.nx * C.nz);
  // Pre-smoothing from x = 0 (no need to zero x: every column is solved). A level that has a
  // coarser one has an even nx (set_operator), so the columns alternate in colour all round.
  // After the sweep the odd columns' residual is zero (each was just solved exactly with its
  // neighbours' final values) and an even column's is what its neighbours added after it was
  // solved with them at zero:
  //   r_i = b_i - (A x)_i = cx_left x_{i-1} + cx_right x_{i+1}   (i even).
  // R = P^T sums the 2 x 2 (or, x alone, 2 x 1) fine residuals of a coarse cell, of which only
  // the even column's are non-zero; this replaces the residual's full product and its second pass.
  x.resize(L.nx * L.nz);
  line_sweep(L, b, x, true, true);
  const bool x_alone = C.halved_x_alone;
  parallel_for(C.nx, parallel, [&](int ic) {
    const int i = 2 * ic, il = i == 0 ? L.nx - 1 : i - 1, ir = i + 1;
    const double* cl = &L.cx[L.cell(i, 0)];
    const double* cr = &L.cx[L.cell(ir, 0)];
    const double* xl = &x[L.cell(il, 0)];
    const double* xr = &x[L.cell(ir, 0)];
    double* rci = &rc[C.cell(ic, 0)];
    // (omp simd: rc is never x, so GCC need not check the columns for overlap at run time;
    // with the prolongation's loop the transfers went from 3.5 % to 3.2 % of a one-thread
    // 160 x 16 step, near the profiles' scatter)
    if (x_alone) {
#pragma omp simd
      for (int k = 0; k < C.nz; ++k) rci[k] = cl[k] * xl[k] + cr[k] * xr[k];
      return;
    }
#pragma omp simd
    for (int kc = 0; kc < C.nz; ++kc) {
      const int k = 2 * kc;
      rci[kc] = (cl[k] * xl[k] + cr[k] * xr[k]) + (cl[k + 1] * xl[k + 1] + cr[k + 1] * xr[k + 1]);
    }
  });
  Eigen::VectorXd& xc = x_c_[l + 1];
  vcycle(l + 1, rc, xc);
  parallel_for(L.nx, parallel, [&](int i) {  // P: piecewise constant
    double* xi = &x[L.cell(i, 0)];
    const double* xci = &xc[C.cell(i / 2, 0)];
    if (x_alone) {
#pragma omp simd  // (xc is never x)
      for (int k = 0; k < L.nz; ++k) xi[k] += xci[k];
    } else
      for (int k = 0; k < L.nz; ++k) xi[k] += xci[k / 2];
  });
  line_sweep(L, b, x, false, false);
}

void PressureMultigrid::precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) {
  vcycle(0, r, z);
}

}  // namespace granbench::twod

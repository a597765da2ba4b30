// Rows of the viscous matrix of viscous_step.cpp, written out per unknown. The matrix is the
// sum of the mass terms rho V/dt and of K a a^T over the stress terms (a: difference stencil):
//
//   cell (i, k)     K = 2 eta_c V:  D_xx = (u_{i+1,k} - u_{i,k})/dx,  D_zz = (w_{i,k+1} -
//   w_{i,k})/dz corner (i, k)   K = eta_n V:    gamma = (u_{i,k} - u_{i,k-1})/dz + (w_{i,k} -
//   w_{i-1,k})/dx bed corner      K = eta_n V/2:  gamma = 2 u_{i,0}/dz (no slip, ghost u = -u)
//
// with w = 0 at the bed and the top w and top corners lagged (right-hand side). Row by row:
//
//   u(i,k): mu + (Kc_{i,k} + Kc_{i-1,k})/dx^2 + (Kn_{i,k} [2 Kn_{i,0} at the bed] +
//   Kn_{i,k+1})/dz^2
//           on the diagonal; -Kc/dx^2 to u(i+-1,k); -Kn/dz^2 to u(i,k-+1) (the line);
//           +-Kn/(dx dz) to the four w's around it (corners k and k+1, interior only)
//   w(i,k): mw + (Kc_{i,k} + Kc_{i,k-1})/dz^2 + (Kn_{i,k} + Kn_{i+1,k})/dx^2 on the diagonal;
//           -Kc/dz^2 to w(i,k-+1) (the line); -Kn/dx^2 to w(i+-1,k); +-Kn/(dx dz) to the
//           four u's around it
//
// One visitor per row type defines the rows and serves the assembly and the boundary rows. For
// speed the product's interior rows and the preconditioner's line coefficients are written out
// from the visitor's expressions in loops that vectorise; tests/twod/test_viscous_operator.cpp
// checks the product against the assembled matrix (and its symmetry) and the preconditioner
// against the line sweep of the assembled matrix, so the copies cannot drift apart unnoticed.
//
// Threads (parallel.hpp): rows are independent in the product and lines in the factors, so both
// are parallel over columns. The preconditioner sweeps its lines in blocks of kChunk columns,
// the even blocks, then the odd ones, and within a block in column order: blocks of one colour
// do not couple, so they are swept in parallel, and the order is fixed by the grid alone, so the
// result does not depend on the thread count. (A sweep over all columns in order was serial:
// with two threads the second one waited through it, and it grows with the iterations late in a
// rollwave run. Zebra order, even columns then odd, is parallel too but converges slower: 1.98
// iterations per step against 1.57 at 256 x 64 over the first 0.2 s of the rollwave.)
#include "twod/viscous_operator.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "twod/parallel.hpp"

namespace granbench::twod {

namespace {
// Lines whose Thomas factors are computed side by side in set(): independent recurrences that
// hide each other's division latency (set's share of a one-thread 256 x 64 step: 6.9 % one line
// at a time, 3.3 % four at a time, 2.8 % eight at a time).
constexpr int kFactorLanes = 8;
}  // namespace

ViscousOperator::ViscousOperator(const Grid& g)
    : g_(g),
      nu_(g.nx * g.nz),
      ixx_(1.0 / (g.dx * g.dx)),
      izz_(1.0 / (g.dz * g.dz)),
      ixz_(1.0 / (g.dx * g.dz)),
      mass_u_(g.cells()),
      mass_w_(g.cells()),
      kc_(g.cells()),
      kn_(g.corners()) {
  if (g.nx < 3 || g.nz < 2)
    throw std::invalid_argument("ViscousOperator: grid needs nx >= 3, nz >= 2");
  lower_.resize(size());
  inv_m_.resize(size());
  cp_.resize(size());
}

template <class Visit>
void ViscousOperator::visit_u_row(int i, int k, Visit&& visit) const {
  // Periodic neighbours once; coefficients are stored column by column (see set()).
  const int nx = g_.nx, nz = g_.nz, nzw = nz - 1;
  const int il = i == 0 ? nx - 1 : i - 1, ir = i == nx - 1 ? 0 : i + 1;
  const int row = i * nz + k, row_left = il * nz + k, corner = i * (nz + 1) + k;
  const double kc = kc_[row], kc_left = kc_[row_left];
  const double kn_below = kn_[corner];
  const bool interior_above = k + 1 < nz;  // the top corner is explicit
  const double kn_above = interior_above ? kn_[corner + 1] : 0.0;
  const double below_weight = k == 0 ? 2.0 * kn_below : kn_below;
  visit(row, mass_u_[row] + (kc + kc_left) * ixx_ + (below_weight + kn_above) * izz_, Entry::Diag);
  if (k > 0) visit(row - 1, -kn_below * izz_, Entry::Lower);
  if (interior_above) visit(row + 1, -kn_above * izz_, Entry::Upper);
  visit(ir * nz + k, -kc * ixx_, Entry::Off);
  visit(row_left, -kc_left * ixx_, Entry::Off);
  const int w_here = nu_ + i * nzw - 1, w_left = nu_ + il * nzw - 1;  // + k: w(., k)
  if (k > 0) {
    visit(w_here + k, kn_below * ixz_, Entry::Off);
    visit(w_left + k, -kn_below * ixz_, Entry::Off);
  }
  if (interior_above) {
    visit(w_here + k + 1, -kn_above * ixz_, Entry::Off);
    visit(w_left + k + 1, kn_above * ixz_, Entry::Off);
  }
}

template <class Visit>
void ViscousOperator::visit_w_row(int i, int k, Visit&& visit) const {
  const int nx = g_.nx, nz = g_.nz, nzw = nz - 1;
  const int il = i == 0 ? nx - 1 : i - 1, ir = i == nx - 1 ? 0 : i + 1;
  const int cell = i * nz + k, corner = i * (nz + 1) + k;
  const double kc = kc_[cell], kc_below = kc_[cell - 1];
  const double kn = kn_[corner], kn_right = kn_[ir * (nz + 1) + k];
  const int row = nu_ + i * nzw + k - 1;
  visit(row, mass_w_[row - nu_] + (kc + kc_below) * izz_ + (kn + kn_right) * ixx_, Entry::Diag);
  if (k > 1) visit(row - 1, -kc_below * izz_, Entry::Lower);
  if (k + 1 < nz) visit(row + 1, -kc * izz_, Entry::Upper);
  visit(nu_ + il * nzw + k - 1, -kn * ixx_, Entry::Off);
  visit(nu_ + ir * nzw + k - 1, -kn_right * ixx_, Entry::Off);
  visit(cell, kn * ixz_, Entry::Off);
  visit(cell - 1, -kn * ixz_, Entry::Off);
  visit(ir * nz + k, -kn_right * ixz_, Entry::Off);
  visit(ir * nz + k - 1, kn_right * ixz_, Entry::Off);
}

template <class Each>
void ViscousOperator::for_each_row(Each&& each) const {
  const int nx = g_.nx, nz = g_.nz;
  for (int i = 0; i < nx; ++i)
    for (int k = 0; k < nz; ++k)
      each(u_index(i, k), [&](auto&& visit) { visit_u_row(i, k, visit); });
  for (int i = 0; i < nx; ++i)
    for (int k = 1; k < nz; ++k)
      each(w_index(i, k), [&](auto&& visit) { visit_w_row(i, k, visit); });
}

void ViscousOperator::set(const Properties& props, double dt) {
  set(props, props.eta_c, props.eta_n, dt);
}

void ViscousOperator::set_stress(const std::vector<double>& eta_c,
                                 const std::vector<double>& eta_n) {
  set_stress_weights(eta_c, eta_n);
  std::fill(mass_u_.begin(), mass_u_.end(), 0.0);
  std::fill(mass_w_.begin(), mass_w_.end(), 0.0);
}

namespace {
// The columns of a block in the row-major to column-major copies: a cache line of doubles.
constexpr int kTransposeColumns = 8;
}  // namespace

void ViscousOperator::set_stress_weights(const std::vector<double>& eta_c,
                                         const std::vector<double>& eta_n) {
  // Into column order (i nz + k for cells and u, i (nz + 1) + k for corners), so that the loops
  // along a line read contiguous memory; in blocks of kTransposeColumns columns with the rows
  // outermost, so that each row's read of a block is one cache line and the block's columns are
  // written side by side.
  const double V = g_.cell_volume();
  const int nx = g_.nx, nz = g_.nz;
  parallel_for((nx + kTransposeColumns - 1) / kTransposeColumns, true, [&](int block) {
    const int i0 = block * kTransposeColumns, i1 = std::min(i0 + kTransposeColumns, nx);
    for (int k = 0; k <= nz; ++k)
      for (int i = i0; i < i1; ++i) {
        const std::size_t c = std::size_t(k) * nx + i;
        if (k < nz) kc_[i * nz + k] = 2.0 * eta_c[c] * V;
        kn_[i * (nz + 1) + k] = eta_n[c] * V;
      }
  });
}

void ViscousOperator::set(const Properties& props, const std::vector<double>& eta_c,
                          const std::vector<double>& eta_n, double dt) {
  set_stress_weights(eta_c, eta_n);
  const double V_dt = g_.cell_volume() / dt;
  const int nx = g_.nx, nz = g_.nz;
  // (every entry that a row reads is written here: no zeroing first)
  parallel_for((nx + kTransposeColumns - 1) / kTransposeColumns, true, [&](int block) {
    const int i0 = block * kTransposeColumns, i1 = std::min(i0 + kTransposeColumns, nx);
    for (int k = 0; k < nz; ++k)  // (blocks as in set_stress_weights)
      for (int i = i0; i < i1; ++i) {
        const std::size_t c = std::size_t(k) * nx + i;
        mass_u_[i * nz + k] = props.rho_u[c] * V_dt;
        if (k > 0) mass_w_[i * (nz - 1) + k - 1] = props.rho_w[c] * V_dt;
      }
  });
  // The lines' coefficients, then their Thomas factors m_k = d_k - a_k c'_{k-1},
  // c'_k = c_k / m_k. The coefficients are the visitor's diagonal, lower and upper entries
  // (visit_u_row, visit_w_row: the same expressions), written out in loops over k that vectorise;
  // they are held in inv_m_ (d) and cp_ (c) until the factors replace them. The factors are a
  // recurrence along each line whose pace is set by its division's latency, so kFactorLanes lines
  // are factored side by side; each line's arithmetic is the same as alone.
  const double ixx = ixx_, izz = izz_;
  auto u_coefficients = [&](int i) {
    const int il = i == 0 ? nx - 1 : i - 1;
    const double* kc = &kc_[i * nz];
    const double* kc_left = &kc_[il * nz];
    const double* kn = &kn_[i * (nz + 1)];
    const double* mass = &mass_u_[i * nz];
    double* diag = &inv_m_[i * nz];
    double* lower = &lower_[i * nz];
    double* upper = &cp_[i * nz];
#pragma omp simd
    for (int k = 0; k < nz; ++k) {
      const double kn_below = kn[k];
      const bool interior_above = k + 1 < nz;  // the top corner is explicit
      const double kn_above = interior_above ? kn[k + 1] : 0.0;
      const double below_weight = k == 0 ? 2.0 * kn_below : kn_below;
      diag[k] = mass[k] + (kc[k] + kc_left[k]) * ixx + (below_weight + kn_above) * izz;
      lower[k] = k > 0 ? -kn_below * izz : 0.0;
      upper[k] = interior_above ? -kn_above * izz : 0.0;
    }
  };
  auto w_coefficients = [&](int i) {
    const int nzw = nz - 1, ir = i == nx - 1 ? 0 : i + 1;
    const double* kc = &kc_[i * nz];
    const double* kn = &kn_[i * (nz + 1)];
    const double* kn_right = &kn_[ir * (nz + 1)];
    const double* mass = &mass_w_[i * nzw];     // [k - 1]: w(i, k)
    double* diag = &inv_m_[nu_ + i * nzw - 1];  // [k]: w(i, k)
    double* lower = &lower_[nu_ + i * nzw - 1];
    double* upper = &cp_[nu_ + i * nzw - 1];
#pragma omp simd
    for (int k = 1; k < nz; ++k) {
      diag[k] = mass[k - 1] + (kc[k] + kc[k - 1]) * izz + (kn[k] + kn_right[k]) * ixx;
      lower[k] = k > 1 ? -kc[k - 1] * izz : 0.0;
      upper[k] = k + 1 < nz ? -kc[k] * izz : 0.0;
    }
  };
  // Lines starting at rows first[0..Lanes), n rows each.
  auto factor_lines = [&]<int Lanes>(const std::array<int, Lanes>& first, int n) {
    for (int k = 0; k < n; ++k)
      for (int l = 0; l < Lanes; ++l) {
        const int row = first[l] + k;
        const double m = inv_m_[row] - (k > 0 ? lower_[row] * cp_[row - 1] : 0.0);
        inv_m_[row] = 1.0 / m;
        cp_[row] *= inv_m_[row];
      }
  };
  auto factor_columns = [&](int first_column, int count) {
    for (int i = first_column; i < first_column + count; ++i) {
      u_coefficients(i);
      w_coefficients(i);
    }
    auto u_first = [&](int i) { return u_index(i, 0); };
    auto w_first = [&](int i) { return w_index(i, 1); };
    if (count == kFactorLanes) {
      std::array<int, kFactorLanes> u{}, w{};
      for (int l = 0; l < kFactorLanes; ++l) {
        u[l] = u_first(first_column + l);
        w[l] = w_first(first_column + l);
      }
      factor_lines.template operator()<kFactorLanes>(u, nz);
      factor_lines.template operator()<kFactorLanes>(w, nz - 1);
      return;
    }
    for (int i = first_column; i < first_column + count; ++i) {
      factor_lines.template operator()<1>({u_first(i)}, nz);
      factor_lines.template operator()<1>({w_first(i)}, nz - 1);
    }
  };
  const int groups = (nx + kFactorLanes - 1) / kFactorLanes;
  parallel_for(groups, true, [&](int m) {
    const int first = m * kFactorLanes;
    factor_columns(first, std::min(kFactorLanes, nx - first));
  });
}

void ViscousOperator::apply_u_column(int i, const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  const int nx = g_.nx, nz = g_.nz, nzw = nz - 1;
  auto row_product = [&](int k) {
    double sum = 0.0;
    visit_u_row(i, k, [&](int col, double value, Entry) { sum += value * x[col]; });
    y[u_index(i, k)] = sum;
  };
  row_product(0);  // the bed row and the top row through the visitor
  if (nz > 1) row_product(nz - 1);
  // The interior rows written out: the visitor's entries in its order, so the sum is the same
  // to the last bit, in a loop over k that the compiler vectorises (the visitor's per-row
  // branches kept this product at 11 % of a one-thread step).
  const int il = i == 0 ? nx - 1 : i - 1, ir = i == nx - 1 ? 0 : i + 1;
  const double* kc = &kc_[i * nz];
  const double* kc_left = &kc_[il * nz];
  const double* kn = &kn_[i * (nz + 1)];
  const double* mass = &mass_u_[i * nz];
  const double* xu = &x[i * nz];
  const double* xu_left = &x[il * nz];
  const double* xu_right = &x[ir * nz];
  const double* xw = &x[nu_ + i * nzw - 1];  // [k]: w(i, k)
  const double* xw_left = &x[nu_ + il * nzw - 1];
  double* yu = &y[i * nz];
  const double ixx = ixx_, izz = izz_, ixz = ixz_;
#pragma omp simd  // (y is never x: no run-time overlap checks)
  for (int k = 1; k < nz - 1; ++k) {
    const double below = kn[k], above = kn[k + 1];
    double sum = (mass[k] + (kc[k] + kc_left[k]) * ixx + (below + above) * izz) * xu[k];
    sum += -below * izz * xu[k - 1];
    sum += -above * izz * xu[k + 1];
    sum += -kc[k] * ixx * xu_right[k];
    sum += -kc_left[k] * ixx * xu_left[k];
    sum += below * ixz * xw[k];
    sum += -below * ixz * xw_left[k];
    sum += -above * ixz * xw[k + 1];
    sum += above * ixz * xw_left[k + 1];
    yu[k] = sum;
  }
}

void ViscousOperator::apply_w_column(int i, const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  const int nx = g_.nx, nz = g_.nz, nzw = nz - 1;
  auto row_product = [&](int k) {
    double sum = 0.0;
    visit_w_row(i, k, [&](int col, double value, Entry) { sum += value * x[col]; });
    y[w_index(i, k)] = sum;
  };
  row_product(1);  // the lowest and highest rows through the visitor
  if (nz > 2) row_product(nz - 1);
  const int il = i == 0 ? nx - 1 : i - 1, ir = i == nx - 1 ? 0 : i + 1;
  const double* kc = &kc_[i * nz];
  const double* kn = &kn_[i * (nz + 1)];
  const double* kn_right = &kn_[ir * (nz + 1)];
  const double* mass = &mass_w_[i * nzw];  // [k - 1]: w(i, k)
  const double* xw = &x[nu_ + i * nzw - 1];
  const double* xw_left = &x[nu_ + il * nzw - 1];
  const double* xw_right = &x[nu_ + ir * nzw - 1];
  const double* xu = &x[i * nz];
  const double* xu_right = &x[ir * nz];
  double* yw = &y[nu_ + i * nzw - 1];
  const double ixx = ixx_, izz = izz_, ixz = ixz_;
#pragma omp simd  // (y is never x)
  for (int k = 2; k < nz - 1; ++k) {
    const double here = kn[k], right = kn_right[k];
    double sum = (mass[k - 1] + (kc[k] + kc[k - 1]) * izz + (here + right) * ixx) * xw[k];
    sum += -kc[k - 1] * izz * xw[k - 1];
    sum += -kc[k] * izz * xw[k + 1];
    sum += -here * ixx * xw_left[k];
    sum += -right * ixx * xw_right[k];
    sum += here * ixz * xu[k];
    sum += -here * ixz * xu[k - 1];
    sum += -right * ixz * xu_right[k];
    sum += right * ixz * xu_right[k - 1];
    yw[k] = sum;
  }
}

void ViscousOperator::apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  y.resize(size());
  parallel_for(g_.nx, true, [&](int i) {
    apply_u_column(i, x, y);
    apply_w_column(i, x, y);
  });
}

template <int n>
void ViscousOperator::solve_lines(const int (&first)[n], int length, Eigen::VectorXd& z) const {
  // Thomas algorithm with the factors of set(), on the right-hand sides that z holds, for n
  // lines at once: independent recurrences in one loop keep the floating-point pipeline busy,
  // and each line's arithmetic is the same as alone.
  double y[n] = {};
  for (int m = 0; m < length; ++m)
    for (int j = 0; j < n; ++j) {
      const int row = first[j] + m;
      y[j] = (z[row] - lower_[row] * y[j]) * inv_m_[row];
      z[row] = y[j];
    }
  for (int m = length - 2; m >= 0; --m)
    for (int j = 0; j < n; ++j) {
      const int row = first[j] + m;
      z[row] -= cp_[row] * z[row + 1];
    }
}

// The lines' right-hand sides r - (the couplings outside the line) z, with the latest z of the
// other lines, written into the line's own z (which no coupling outside it reads). The first and
// last rows go through the visitor; the interior ones are written out, the visitor's entries in
// its order (the same sums to the last bit), in loops the compiler vectorises: the recurrence of
// the solve then only reads them (the visitor inside the recurrence kept the line solves at 11 %
// of a one-thread step).
void ViscousOperator::u_line_rhs(int i, const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  const int nx = g_.nx, nz = g_.nz, nzw = nz - 1;
  auto row_rhs = [&](int k) {
    double rhs = r[u_index(i, k)];
    visit_u_row(i, k, [&](int col, double value, Entry e) {
      if (e == Entry::Off) rhs -= value * z[col];
    });
    z[u_index(i, k)] = rhs;
  };
  row_rhs(0);
  if (nz > 1) row_rhs(nz - 1);
  const int il = i == 0 ? nx - 1 : i - 1, ir = i == nx - 1 ? 0 : i + 1;
  const double* kc = &kc_[i * nz];
  const double* kc_left = &kc_[il * nz];
  const double* kn = &kn_[i * (nz + 1)];
  const double* ri = &r[i * nz];
  const double* zu_left = &z[il * nz];
  const double* zu_right = &z[ir * nz];
  const double* zw = &z[nu_ + i * nzw - 1];  // [k]: w(i, k)
  const double* zw_left = &z[nu_ + il * nzw - 1];
  double* zu = &z[i * nz];
  const double ixx = ixx_, ixz = ixz_;
#pragma omp simd  // (writes this column's u entries of z; reads only other entries)
  for (int k = 1; k < nz - 1; ++k) {
    const double below = kn[k], above = kn[k + 1];
    double rhs = ri[k];
    rhs -= -kc[k] * ixx * zu_right[k];
    rhs -= -kc_left[k] * ixx * zu_left[k];
    rhs -= below * ixz * zw[k];
    rhs -= -below * ixz * zw_left[k];
    rhs -= -above * ixz * zw[k + 1];
    rhs -= above * ixz * zw_left[k + 1];
    zu[k] = rhs;
  }
}

void ViscousOperator::w_line_rhs(int i, const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  const int nx = g_.nx, nz = g_.nz, nzw = nz - 1;
  auto row_rhs = [&](int k) {
    double rhs = r[w_index(i, k)];
    visit_w_row(i, k, [&](int col, double value, Entry e) {
      if (e == Entry::Off) rhs -= value * z[col];
    });
    z[w_index(i, k)] = rhs;
  };
  row_rhs(1);
  if (nz > 2) row_rhs(nz - 1);
  const int il = i == 0 ? nx - 1 : i - 1, ir = i == nx - 1 ? 0 : i + 1;
  const double* kn = &kn_[i * (nz + 1)];
  const double* kn_right = &kn_[ir * (nz + 1)];
  const double* rw = &r[nu_ + i * nzw - 1];  // [k]: w(i, k)
  const double* zw_left = &z[nu_ + il * nzw - 1];
  const double* zw_right = &z[nu_ + ir * nzw - 1];
  const double* zu = &z[i * nz];
  const double* zu_right = &z[ir * nz];
  double* zw = &z[nu_ + i * nzw - 1];
  const double ixx = ixx_, ixz = ixz_;
#pragma omp simd  // (writes this column's w entries of z; reads only other entries)
  for (int k = 2; k < nz - 1; ++k) {
    const double here = kn[k], right = kn_right[k];
    double rhs = rw[k];
    rhs -= -here * ixx * zw_left[k];
    rhs -= -right * ixx * zw_right[k];
    rhs -= here * ixz * zu[k];
    rhs -= -here * ixz * zu[k - 1];
    rhs -= -right * ixz * zu_right[k];
    rhs -= right * ixz * zu_right[k - 1];
    zw[k] = rhs;
  }
}

void ViscousOperator::solve_column_lines(bool u_lines, const int* columns, int n,
                                         const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  for (int j = 0; j < n; ++j) u_lines ? u_line_rhs(columns[j], r, z) : w_line_rhs(columns[j], r, z);
  const int length = u_lines ? g_.nz : g_.nz - 1;
  auto first = [&](int j) { return u_lines ? u_index(columns[j], 0) : w_index(columns[j], 1); };
  switch (n) {
    case 1:
      solve_lines<1>({first(0)}, length, z);
      break;
    case 2:
      solve_lines<2>({first(0), first(1)}, length, z);
      break;
    case 3:
      solve_lines<3>({first(0), first(1), first(2)}, length, z);
      break;
    default:
      solve_lines<4>({first(0), first(1), first(2), first(3)}, length, z);
      break;
  }
}

namespace {

// Columns per block of the preconditioner's sweep: 20 blocks at nx = 160 and 32 at 256, an even
// count per colour for two threads (with 16 columns, 160 gave 5 per colour, 3 against 2), while
// most couplings stay inside a block, as in a serial sweep (viscous iterations: 1 809 against
// 1 807 with 16 columns, compare's 2D run to 0.3 s).
constexpr int kChunk = 8;

}  // namespace

void ViscousOperator::sweep_colour(int colour, bool forward, bool u_lines, const Eigen::VectorXd& r,
                                   Eigen::VectorXd& z) const {
  // The blocks of one colour (blocks colour, colour + 2, ...), each swept in column order
  // (backward: reversed). Blocks of one colour are not neighbours and are swept in parallel,
  // except that with an odd number of blocks the last one neighbours block 0 across the periodic
  // boundary: it is swept alone, after the others (forward) or before them (backward), so that
  // the backward sweep is the exact reverse of the forward one.
  const int nx = g_.nx;
  const int blocks = (nx + kChunk - 1) / kChunk;
  const bool last_alone = blocks % 2 == 1 && colour == 0;
  const int end = last_alone ? blocks - 1 : blocks;
  const int count = (end - colour + 1) / 2;  // the colour's blocks m = 0 .. count - 1 below end
  // Blocks m in [m_lo, m_hi), up to four at a time and column by column, so that four line
  // recurrences run interleaved (the lines of blocks of one colour are independent).
  auto sweep_blocks = [&](int m_lo, int m_hi) {
    for (int m0 = m_lo; m0 < m_hi; m0 += 4) {
      const int n = std::min(4, m_hi - m0);
      int lo[4], length[4], longest = 0;
      for (int j = 0; j < n; ++j) {
        lo[j] = (colour + 2 * (m0 + j)) * kChunk;
        length[j] = std::min(nx, lo[j] + kChunk) - lo[j];
        longest = std::max(longest, length[j]);
      }
      for (int step = 0; step < longest; ++step) {
        int columns[4], c = 0;
        for (int j = 0; j < n; ++j)
          if (step < length[j])
            columns[c++] = forward ? lo[j] + step : lo[j] + length[j] - 1 - step;
        solve_column_lines(u_lines, columns, c, r, z);
      }
    }
  };
  if (last_alone && !forward) sweep_blocks(count, count + 1);
  // each thread a contiguous share of the blocks (which thread sweeps a line does not change it)
  parallel_for_ranges(count, [&](int begin, int end) { sweep_blocks(begin, end); });
  if (last_alone && forward) sweep_blocks(count, count + 1);
}

void ViscousOperator::precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  parallel_zero(size(), z);
  // forward: u-lines (even blocks, odd blocks), w-lines (even, odd); backward: the exact
  // reverse, so that M is symmetric
  sweep_colour(0, true, true, r, z);
  sweep_colour(1, true, true, r, z);
  sweep_colour(0, true, false, r, z);
  sweep_colour(1, true, false, r, z);
  sweep_colour(1, false, false, r, z);
  sweep_colour(0, false, false, r, z);
  sweep_colour(1, false, true, r, z);
  sweep_colour(0, false, true, r, z);
}

void ViscousOperator::assemble(PatternedMatrix& A) const {
  A.begin(size());
  for_each_row([&](int row, auto&& entries) {
    entries([&](int col, double value, Entry) { A.add(row, col, value); });
  });
  A.end();
}

}  // namespace granbench::twod

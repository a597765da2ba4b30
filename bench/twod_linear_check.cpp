// Measurement driver (not a test): the 2D solver seeded with the exact 2D linear surface mode of
// its base state, against that mode's growth rate and phase speed (docs/twod-validation.md).
//
// Base states: the mu(I) Bagnold layer (5.4)-(5.5) (rheology=mui, default), or a Newtonian film
// of kinematic viscosity nu (rheology=newton nu=..., Nusselt profile u = (g sin zeta/nu)(h z -
// z^2/2)), whose linear theory is the classical falling-film (Orr-Sommerfeld) problem; both are
// solved by analysis/linear2d_* with the same stress-free surface conditions.
//
// Measurement: the complex Fourier coefficient h_m(t) of the column heights (m = mode, default 1)
// is sampled every dt_out; reported are (a) the least-squares slopes of ln|h_m| and of its
// unwrapped phase over [t_fit0, t_end] (growth and speed of whatever the signal is), and (b) a
// matrix-pencil fit of h_m(t) = sum_j c_j exp(lambda_j t) with `modes` terms (default 2), which
// separates a second wave from the seeded one when they beat.
//
//   bench_twod_linear_check key=value ...
//     rheology=mui|newton nu=<m^2/s> zeta=28.5 h0=0.004 Lx=0.08 Lz=2 (in h0) nx=160 nz=32
//     a0=2e-4 t_end=1 dt_out=<s> t_fit0=0 modes=2 seed=eigen|sine N=32
//     eta_max=2 eta_min=1e-3 D_min=1e-6 rho_light= eta_light= mixing=arithmetic|harmonic
//     frame=0 (grid speed / base surface speed) vtol=1e-4 ptol=1e-10 (viscous: relative to the
//     step's change; projection) cfl=0.4 dt_max=1e-3 passes=1 ab2=1 tangent=1 hydro_p=1 row_p=1
//     extrap_p=1 (eta's dynamic pressure extrapolated) mid_vof=1 (mid-step interface velocity)
//     row_shear=1 row_tau=1 (surface_row_shear) interface_p=cell|extrapolated
//     ambient=1 (ambient_pressure_gradient) effective_p=1 (Rheology::effective_pressure)
//     (defaults: the solver's, twod/parameters.hpp)
//     series=<file>   (t, |h_m|, arg h_m, mean flux per sample)   profile=1 (column means at end)
//     drag=<Pa s/m>   theory with a surface drag tau_xz(h) = mu h - beta u(h)
//     layer=<m> fn= fs= fq=   theory with eta_n, eta_s, q scaled in a surface layer
// Prints one JSON object.
#include <Eigen/Dense>
#include <chrono>
#include <cmath>
#include <complex>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <stdexcept>
#include <string>

#include "analysis/linear2d/base_state.hpp"
#include "analysis/linear2d/chebyshev.hpp"
#include "analysis/linear2d/linear_stability_2d.hpp"
#include "analysis/linear2d/operator.hpp"
#include "analysis/linear2d/spectrum.hpp"
#include "common/steady_state.hpp"
#include "twod/diagnostics.hpp"
#include "twod/initial_state.hpp"
#include "twod/run.hpp"
#include "twod/solver.hpp"
#include "twod/viscosity_mixing.hpp"

using namespace granbench;
using cd = std::complex<double>;

namespace {

struct Args {
  std::map<std::string, std::string> kv;
  double num(const std::string& k, double def) const {
    auto it = kv.find(k);
    return it == kv.end() ? def : std::stod(it->second);
  }
  std::string str(const std::string& k, const std::string& def) const {
    auto it = kv.find(k);
    return it == kv.end() ? def : it->second;
  }
};

// Least-squares slope of y(t).
double slope(const std::vector<double>& t, const std::vector<double>& y) {
  const double n = double(t.size());
  double st = 0, sy = 0, stt = 0, sty = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    st += t[i];
    sy += y[i];
    stt += t[i] * t[i];
    sty += t[i] * y[i];
  }
  return (n * sty - st * sy) / (n * stt - st * st);
}

// Matrix pencil: y_n = sum_j c_j z_j^n, returns lambda_j = ln z_j / dt and |c_j|.
std::vector<std::pair<cd, double>> matrix_pencil(const std::vector<cd>& y, double dt, int M) {
  const int N = int(y.size());
  const int L = N / 3;
  if (L < M + 1) return {};
  Eigen::MatrixXcd Y(N - L, L + 1);
  for (int r = 0; r < N - L; ++r)
    for (int c = 0; c <= L; ++c) Y(r, c) = y[r + c];
  Eigen::JacobiSVD<Eigen::MatrixXcd> svd(Y, Eigen::ComputeThinV);
  const Eigen::MatrixXcd V = svd.matrixV().leftCols(M).conjugate();
  const Eigen::MatrixXcd V1 = V.topRows(L), V2 = V.bottomRows(L);
  const Eigen::MatrixXcd A = V1.completeOrthogonalDecomposition().pseudoInverse() * V2;
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(A);
  std::vector<cd> z(M);
  for (int j = 0; j < M; ++j) z[j] = es.eigenvalues()(j);
  // amplitudes by least squares
  Eigen::MatrixXcd Z(N, M);
  Eigen::VectorXcd yy(N);
  for (int n = 0; n < N; ++n) {
    yy(n) = y[n];
    for (int j = 0; j < M; ++j) Z(n, j) = std::pow(z[j], n);
  }
  const Eigen::VectorXcd c = Z.completeOrthogonalDecomposition().solve(yy);
  std::vector<std::pair<cd, double>> out;
  for (int j = 0; j < M; ++j) out.push_back({std::log(z[j]) / dt, std::abs(c(j))});
  std::sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.second > b.second; });
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    std::string s = argv[i];
    auto eq = s.find('=');
    if (eq == std::string::npos) {
      std::cerr << "argument " << s << " is not key=value\n";
      return 2;
    }
    a.kv[s.substr(0, eq)] = s.substr(eq + 1);
  }
  const bool newton = a.str("rheology", "mui") == "newton";
  const double zeta = degrees_to_radians(a.num("zeta", 28.5));
  const double h0 = a.num("h0", 4e-3), Lx = a.num("Lx", 0.08), Lz = a.num("Lz", 2.0) * h0;
  const int nx = int(a.num("nx", 160)), nz = int(a.num("nz", 32)), mode = int(a.num("mode", 1));
  const double a0 = a.num("a0", 2e-4), t_end = a.num("t_end", 1.0);
  const int N = int(a.num("N", 32));

  twod::SolverParams params;
  params.zeta = zeta;
  auto& rh = params.rheology;
  rh.h0_for_curve = h0;
  rh.eta_max = a.num("eta_max", rh.eta_max);
  rh.eta_min = a.num("eta_min", rh.eta_min);
  rh.D_min = a.num("D_min", rh.D_min);
  rh.rho_light = a.num("rho_light", rh.rho_light);
  rh.eta_light = a.num("eta_light", rh.eta_light);
  if (const auto rule = twod::viscosity_mixing_from_name(a.str("mixing", "arithmetic")))
    rh.mixing = *rule;
  else
    throw std::invalid_argument("mixing: valid values arithmetic, harmonic");
  if (a.kv.count("interface_p"))
    rh.interface_pressure = a.str("interface_p", "") == "extrapolated"
                                ? twod::InterfacePressure::Extrapolated
                                : twod::InterfacePressure::CellAverage;
  params.cfl = a.num("cfl", params.cfl);
  rh.surface_row_shear_spacing = a.num("row_shear", rh.surface_row_shear_spacing ? 1 : 0) != 0;
  rh.ambient_pressure_gradient = a.num("ambient", rh.ambient_pressure_gradient ? 1 : 0) != 0;
  rh.effective_pressure = a.num("effective_p", rh.effective_pressure ? 1 : 0) != 0;
  params.dt_max = a.num("dt_max", params.dt_max);
  params.viscous_tolerance = a.num("vtol", params.viscous_tolerance);
  params.solver_tolerance = a.num("ptol", params.solver_tolerance);
  params.advect_momentum = a.num("advect_momentum", 1) != 0;
  params.viscosity_passes = int(a.num("passes", params.viscosity_passes));
  params.stress_bdf2 = a.num("bdf2", params.stress_bdf2 ? 1 : 0) != 0;
  params.interface_midstep_velocity =
      a.num("mid_vof", params.interface_midstep_velocity ? 1 : 0) != 0;
  params.advection_ab2 = a.num("ab2", params.advection_ab2 ? 1 : 0) != 0;
  params.consistent_momentum = a.num("consistent", params.consistent_momentum ? 1 : 0) != 0;
  params.predictor_pressure_acceleration =
      a.num("accel", params.predictor_pressure_acceleration ? 1 : 0) != 0;
  params.predictor_acceleration_limit = a.num("accel_limit", params.predictor_acceleration_limit);
  params.advection_transverse_terms =
      a.num("transverse", params.advection_transverse_terms ? 1 : 0) != 0;
  params.viscosity_tangent = a.num("tangent", params.viscosity_tangent ? 1 : 0) != 0;
  params.hydrostatic_viscosity_pressure =
      a.num("hydro_p", params.hydrostatic_viscosity_pressure ? 1 : 0) != 0;
  params.extrapolate_dynamic_viscosity_pressure =
      a.num("extrap_p", params.extrapolate_dynamic_viscosity_pressure ? 1 : 0) != 0;
  params.surface_row_pressure = a.num("row_p", params.surface_row_pressure ? 1 : 0) != 0;
  params.surface_row_shear = a.num("row_tau", params.surface_row_shear ? 1 : 0) != 0;

  const Material& mat = rh.material;
  const double rho = mat.bulk_density(), g = mat.g;
  const MuCurve curve(CurveKind::Regularised, mat, h0);
  const SteadyState steady = steady_state(curve, zeta, h0);

  // Base state: mean speed, profile, linear coefficients.
  linear2d::LinearBaseState b;
  double u_mean;
  std::function<double(double, double)> base_u;  // (z, local depth h)
  double nu = 0.0;
  if (newton) {
    nu = a.num("nu", 4e-5);
    rh.newtonian_eta = nu * rho;
    u_mean = g * std::sin(zeta) * h0 * h0 / (3.0 * nu);
    const double F = u_mean / std::sqrt(g * h0 * std::cos(zeta));
    b = linear2d::newtonian_film_base_state(F, zeta);
    base_u = [=](double z, double h) {
      const double zc = std::min(z, h);
      return g * std::sin(zeta) / nu * (h * zc - 0.5 * zc * zc);
    };
  } else {
    u_mean = steady.u_mean;
    b = linear2d::mu_i_base_state(steady, curve);
    base_u = [steady](double z, double h) { return steady.velocity_at_depth(std::min(z, h), h); };
  }
  const double k = 2.0 * std::numbers::pi * mode / Lx, k_hat = k * h0;
  const auto map = b.beta > 0.0 ? linear2d::VerticalMap::SquareRoot : linear2d::VerticalMap::Linear;
  const cd lam_hat = linear2d::surface_mode_eigenvalue(b, k_hat, N, map);
  const linear2d::ChebyshevGrid cheb(N);
  const linear2d::Eigenpair pair =
      linear2d::eigenpair(linear2d::assemble_pencil(b, k_hat, cheb, map), lam_hat);
  const cd lambda = lam_hat * u_mean / h0;
  const int n = cheb.nodes();
  const cd H = pair.v(4 * n);
  Eigen::VectorXcd uhat(n);
  for (int j = 0; j < n; ++j) uhat(j) = pair.v(j) / H * (u_mean / h0);  // per metre of h

  twod::InitialCondition ic;
  const bool eigen_seed = a.str("seed", "eigen") == "eigen";
  ic.height = [=](double x) {
    return eigen_seed ? h0 + a0 * std::cos(k * x) : h0 + a0 * std::sin(k * x);
  };
  ic.velocity = [=, &cheb](double x, double z) {
    const double h = ic.height(x);
    if (!eigen_seed) return base_u(z, h);
    const double zc = std::min(z, h);
    const double s = linear2d::map_coordinate(map, std::min(zc, h0) / h0);
    const cd uh = cheb.interpolate(uhat, s);
    return base_u(zc, h0) + (std::polar(a0, k * x) * uh).real();
  };

  twod::Grid grid(nx, nz, Lx, Lz);
  // the grid's speed as a fraction of the base surface speed (twod/frame.hpp); 0: the lab frame
  grid.frame_speed = a.num("frame", 0.0) * base_u(h0, h0);
  twod::Solver solver(grid, params, twod::make_initial_state(grid, ic, params));

  const double period = Lx / mode / std::abs(lambda.imag() / k);
  const double dt_out = a.num("dt_out", std::min(0.004, period / 16.0));
  std::vector<double> ts, lnA, ph, flux;
  std::vector<cd> hm;
  // Each sample of the run (twod/run.hpp): h_m, ln|h_m|, the unwrapped phase and the mean flux.
  auto record = [&](const twod::Solver& sv, const SurfaceSeries& series) {
    const auto h = series.h_at(series.nt() - 1);
    cd c = 0.0;
    for (int i = 0; i < nx; ++i) c += h[i] * std::polar(1.0, -k * grid.xc(i));
    c *= 2.0 / nx;
    ts.push_back(sv.state().t);
    hm.push_back(c);
    lnA.push_back(std::log(std::abs(c)));
    double phase = std::arg(c);
    if (!ph.empty()) {
      while (phase - ph.back() > std::numbers::pi) phase -= 2 * std::numbers::pi;
      while (phase - ph.back() < -std::numbers::pi) phase += 2 * std::numbers::pi;
    }
    ph.push_back(phase);
    flux.push_back(twod::mean_flux(grid, sv.state()));
  };
  twod::RunSchedule schedule;
  schedule.t_end = t_end;
  schedule.dt_out = dt_out;
  twod::RunHooks hooks;
  hooks.sample = record;
  const auto wall_start = std::chrono::steady_clock::now();
  const twod::RunResult run = twod::run(
      solver, SurfaceSeries::uniform_grid(Lx, static_cast<std::size_t>(nx), h0), schedule, hooks);
  const std::string status = run.completed() ? "completed" : run.message;
  const double t_fit0 = a.num("t_fit0", 0.0);
  std::vector<double> tf, lf, pf;
  std::vector<cd> hf;
  for (std::size_t i = 0; i < ts.size(); ++i)
    if (ts[i] >= t_fit0 - 1e-12) {
      tf.push_back(ts[i]);
      lf.push_back(lnA[i]);
      pf.push_back(ph[i]);
      hf.push_back(hm[i]);
    }
  nlohmann::json out;
  out["args"] = a.kv;
  out["status"] = status;
  out["theory"] = {{"growth_rate", lambda.real()},
                   {"phase_speed", -lambda.imag() / k},
                   {"lambda_hat", {lam_hat.real(), lam_hat.imag()}},
                   {"F", b.F},
                   {"u_mean", u_mean},
                   {"eigen_residual", pair.residual}};
  if (newton) out["theory"]["Re"] = u_mean * h0 / nu;
  {  // the least-damped linear modes at this k (growth, speed)
    nlohmann::json sp = nlohmann::json::array();
    const auto ev = linear2d::spectrum(b, k_hat, N, map);
    for (std::size_t j = 0; j < ev.size() && j < 6; ++j) {
      const cd l = ev[j] * u_mean / h0;
      sp.push_back({l.real(), -l.imag() / k});
    }
    out["theory"]["spectrum"] = sp;
  }
  if (a.kv.count("layer")) {  // surface-layer sensitivity: layer=delta(m) fn= fs= fq=
    const linear2d::ChebyshevGrid fine(int(a.num("layer_N", 64)));
    const double delta = a.num("layer", 0.0) / h0;
    auto lam_of = [&](double fn, double fs, double fq) {
      const auto P = linear2d::assemble_pencil(b, k_hat, fine, linear2d::VerticalMap::SquareRoot,
                                               {delta, fn, fs, fq});
      const auto ev = linear2d::finite_eigenvalues(P, lam_hat + cd(0.01, 0.013));
      cd best = ev.front();
      for (const cd& e : ev)
        if (std::abs(e - lam_hat) < std::abs(best - lam_hat)) best = e;
      return best * u_mean / h0;
    };
    const cd l0 = lam_of(1, 1, 1);
    const cd l1 = lam_of(a.num("fn", 1), a.num("fs", 1), a.num("fq", 1));
    out["theory"]["layer"] = {{"unmodified", {l0.real(), -l0.imag() / k}},
                              {"modified", {l1.real(), -l1.imag() / k}}};
  }
  if (a.kv.count("drag")) {  // the surface mode with a surface drag: tau_xz(1) = mu h - beta u(1)
    // beta in Pa s/m (e.g. eta_l / delta of a light-fluid layer), scaled by u_mean/(rho g cos h0)
    const double beta = a.num("drag", 0.0) * u_mean / (rho * g * std::cos(zeta) * h0);
    linear2d::Pencil P = linear2d::assemble_pencil(b, k_hat, cheb, map);
    P.A(P.shear() + N, P.u() + N) += beta;
    const auto ev = linear2d::finite_eigenvalues(P, lam_hat + cd(0.01, 0.013));
    cd best = ev.front();
    for (const cd& e : ev)
      if (std::abs(e - lam_hat) < std::abs(best - lam_hat)) best = e;
    out["theory"]["with_drag"] = {(best * u_mean / h0).real(), -(best * u_mean / h0).imag() / k};
  }
  const auto st = solver.statistics();
  out["wall_seconds"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  out["steps"] = st.steps;
  out["viscous_iterations_per_step"] = double(st.viscous_iterations) / double(st.steps);
  out["projection_iterations_per_step"] = double(st.projection_iterations) / double(st.steps);
  out["mass_error"] = st.mass_error();
  out["flux_initial"] = flux.front();
  out["flux_final"] = flux.back();
  out["t_reached"] = ts.back();
  if (tf.size() > 3) {
    out["fit_growth"] = slope(tf, lf);
    out["fit_speed"] = -slope(tf, pf) / k;
    const int M = int(a.num("modes", 2));
    nlohmann::json mp = nlohmann::json::array();
    for (auto& [l, c] : matrix_pencil(hf, dt_out, M))
      mp.push_back({{"growth", l.real()}, {"speed", -l.imag() / k}, {"amplitude", c}});
    out["pencil"] = mp;
  }
  if (a.num("profile", 0) != 0) {  // column-mean u, f, eta_c, I_c at the end vs (5.5)
    const auto& S = solver.state();
    const auto& P = solver.properties();
    nlohmann::json pr = nlohmann::json::array();
    for (int kk = 0; kk < nz; ++kk) {
      double um = 0, fm = 0, em = 0, im = 0, emin = 1e300, emax = 0, enmax = 0;
      for (int i = 0; i < nx; ++i) enmax = std::max(enmax, P.eta_n[grid.at(i, kk)]);
      for (int i = 0; i < nx; ++i) {
        const std::size_t c = grid.at(i, kk);
        um += (S.u[c] + grid.frame_speed) / nx;  // lab frame
        fm += S.f[c] / nx;
        em += P.eta_c[c] / nx;
        im += P.I_c[c] / nx;
        emin = std::min(emin, P.eta_c[c]);
        emax = std::max(emax, P.eta_c[c]);
      }
      pr.push_back({{"z", grid.zc(kk)},
                    {"u", um},
                    {"u_exact", base_u(grid.zc(kk), h0)},
                    {"f", fm},
                    {"eta", em},
                    {"eta_min", emin},
                    {"eta_max", emax},
                    {"I", im},
                    {"eta_corner_below_max", enmax}});
    }
    out["profile"] = pr;
  }
  // |h_m| at a few times, for the shape of the curve
  nlohmann::json samples = nlohmann::json::array();
  const std::size_t every = std::max<std::size_t>(1, ts.size() / 10);
  for (std::size_t i = 0; i < ts.size(); i += every)
    samples.push_back({ts[i], std::exp(lnA[i]) / a0, flux[i]});
  out["amp_over_a0"] = samples;
  if (auto f = a.str("series", ""); !f.empty()) {
    std::ofstream os(f);
    os.precision(10);
    for (std::size_t i = 0; i < ts.size(); ++i)
      os << ts[i] << ' ' << std::exp(lnA[i]) << ' ' << ph[i] << ' ' << flux[i] << '\n';
  }
  std::cout << out.dump(2) << std::endl;
  return 0;
}

// A sum of damped complex exponentials fitted to one uniformly sampled complex signal by the
// matrix pencil method (Hua & Sarkar 1990, IEEE Trans. Acoust. Speech Signal Process. 38, 814,
// in the SVD-filtered form of Sarkar & Pereira 1995, IEEE Antennas Propag. Mag. 37(1), 48).
// Used on the Fourier coefficient h_k(t) of one wavenumber, where a 2D run carries two or three
// waves at once (the seeded surface mode, a slow internal mode, short-wave difference
// interactions): one exponential fitted to ln|h_k| sees their beating as a wrong rate or a stall.
//
// Model, for samples y_n = y(t_0 + n dt), n = 0 .. N-1:
//
//   y_n = sum_{j=1..M} a_j z_j^n,   z_j = exp(lambda_j dt).                                 (1)
//
// 1. Hankel matrix Y, (N - L) x (L + 1), Y_pq = y_{p+q}, with the pencil parameter L = N/3 (the
//    noise-optimal range is N/3 .. N/2), capped at max_pencil so a fit costs O(N max_pencil^2).
// 2. SVD Y = U S V^H. By (1) the rows of Y are combinations of the rows of the M x (L+1)
//    Vandermonde matrix W_jq = z_j^q, so the M dominant right singular vectors V_M satisfy
//    V_M^H = T W for an invertible T (SVD truncation to M filters the noise). Deleting the last
//    or the first row of V_M gives V1 and V2 with V2^H = T diag(z) T^-1 V1^H, i.e.
//    V2 = V1 X, X = (T diag(z) T^-1)^H: the z_j are the complex conjugates of the eigenvalues of
//    the M x M least-squares solution X = V1^+ V2.                                           (2)
// 3. lambda_j = ln(z_j)/dt, principal branch: a component must turn by less than pi per sample.
// 4. Amplitudes a_j by linear least squares of (1) with the z_j fixed; the relative residual
//    r_M = ||y - sum a_j z_j^n|| / ||y|| measures how well M components describe the data.
//
// Choice of M (fit_exponentials with PencilOptions): every M = 1 .. max_components is fitted
// from the one SVD. An M is admissible only if its components are resolved: every two differ in
// angular frequency by at least 2 pi min_beats / T over the window length T = (N-1) dt (default
// half a beat; the pencil resolves closer frequencies than the Fourier limit 1/T, but two
// components at one frequency cannot be told apart from one component whose amplitude is not
// exponential, e.g. growth that stalls, which is exactly what the fit must not absorb). Among the
// admissible M whose residual meets target_residual (all admissible M when none does), the one
// with the smallest max(r_M, residual_floor) * improvement^(M-1) is kept: the fewest components
// that describe the data, plus each further one that lowers the residual `improvement`-fold (a
// real wave does; a component fitted to noise or round-off gains little).
#pragma once

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

namespace granbench {

struct ExponentialComponent {
  std::complex<double> lambda;     // [1/s]: growth rate Re, angular frequency Im
  std::complex<double> amplitude;  // a_j: the component's value at the first sample
};

struct PencilFit {
  std::vector<ExponentialComponent> components;  // sorted by |amplitude|, largest first
  double relative_residual = 0.0;                // r_M over the fitted samples
  std::vector<double> singular_values;  // of the Hankel matrix over the largest, the first few
};

struct PencilOptions {
  int max_components = 3;
  double target_residual = 1e-3;  // a fit this close describes the data
  double improvement = 10.0;      // residual factor a further component must gain
  double residual_floor = 1e-9;   // residuals below this count as exact (round-off)
  double min_beats = 0.5;         // beat periods two components must show within the window
  std::size_t max_pencil = 64;    // cap on the pencil parameter L
};

// Smallest number of samples the pencil accepts for M components.
std::size_t pencil_min_samples(int M);

// Exactly M components fitted to y (spaced dt > 0). Throws std::invalid_argument when y has fewer
// than pencil_min_samples(M) samples or dt is not positive.
PencilFit fit_exponentials(std::span<const std::complex<double>> y, double dt, int M,
                           std::size_t max_pencil = 64);

// M chosen by the rule above (1 <= M <= opt.max_components).
PencilFit fit_exponentials(std::span<const std::complex<double>> y, double dt,
                           const PencilOptions& opt);

}  // namespace granbench

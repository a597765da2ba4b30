// mu(I) curves: values, analytic derivatives and inverses. See mu_curves.hpp for the equations.
#include "common/mu_curves.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "common/ill_posedness.hpp"
#include "common/neutral_points.hpp"
#include "common/root_finding.hpp"

namespace granbench {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct CurveNameEntry {
  CurveKind kind;
  std::string_view name;
};
constexpr CurveNameEntry kCurveNames[] = {{CurveKind::Jop, "jop"},
                                          {CurveKind::Regularised, "regularised"},
                                          {CurveKind::LowI, "low-i"},
                                          {CurveKind::KamrinKoval, "kamrin-koval"},
                                          {CurveKind::Holyoake, "holyoake"}};

}  // namespace

std::string_view curve_name(CurveKind kind) {
  for (const auto& e : kCurveNames)
    if (e.kind == kind) return e.name;
  return "unknown";
}

CurveKind parse_curve_name(std::string_view name) {
  for (const auto& e : kCurveNames)
    if (e.name == name) return e.kind;
  throw std::invalid_argument("unknown curve '" + std::string(name) + "'");
}

std::vector<std::string> all_curve_names() {
  std::vector<std::string> names;
  for (const auto& e : kCurveNames) names.emplace_back(e.name);
  return names;
}

MuCurve::MuCurve(CurveKind kind, const Material& material, double h0)
    : kind_(kind), material_(material) {
  const Material& m = material_;
  switch (kind_) {
    case CurveKind::Regularised:
      quad_ = m.mu_inf;  // (6.3)
      break;
    case CurveKind::Holyoake:
      quad_ = m.hm_c * std::pow(h0 / m.d, -1.0 / 3.0);  // (6.1): mu_inf = c (h0/d)^(-1/3)
      break;
    default:
      quad_ = 0.0;
  }
  if (kind_ == CurveKind::Regularised || kind_ == CurveKind::LowI) {
    // The low-I branch joins at the lower neutral point of the upper branch (§5.1, §6.1).
    const auto roots = neutral_points([this](double I) { return upper_branch(I); },
                                      [this](double I) { return upper_branch_derivative(I); });
    if (roots.empty())
      throw std::runtime_error(
          "the upper branch of the curve has no neutral point to join the low-I branch at");
    junction_I_ = roots.front();
    const double mu_j = upper_branch(junction_I_);
    A_minus_ = junction_I_ * std::exp(m.alpha / (mu_j * mu_j));  // (5.3), (6.4)
  }
  switch (kind_) {
    case CurveKind::Jop:
      mu_min_ = m.mu_s;
      mu_max_ = m.mu_d;
      break;
    case CurveKind::LowI:
      mu_min_ = 0.0;
      mu_max_ = m.mu_d;
      break;
    case CurveKind::Regularised:
      mu_min_ = 0.0;
      mu_max_ = quad_ > 0.0 ? kInf : m.mu_d;
      break;
    case CurveKind::KamrinKoval:
      mu_min_ = m.kk_mu0;
      mu_max_ = kInf;
      break;
    case CurveKind::Holyoake:
      mu_min_ = m.mu_s;
      mu_max_ = quad_ > 0.0 ? kInf : m.mu_d;
      break;
  }
}

// (2.12) with the optional I^2 term of (6.1)/(6.3): (mu_s I0 + mu_d I + q I^2)/(I0 + I).
double MuCurve::upper_branch(double I) const {
  const Material& m = material_;
  if (kind_ == CurveKind::KamrinKoval)
    return m.mu_s + (m.mu_d - m.mu_s) / m.I0 * I +
           (m.kk_mu0 - m.mu_s) * std::exp(-I / m.kk_cK);  // (5.1)
  return (m.mu_s * m.I0 + m.mu_d * I + quad_ * I * I) / (m.I0 + I);
}

double MuCurve::upper_branch_derivative(double I) const {
  const Material& m = material_;
  if (kind_ == CurveKind::KamrinKoval)
    return (m.mu_d - m.mu_s) / m.I0 - (m.kk_mu0 - m.mu_s) / m.kk_cK * std::exp(-I / m.kk_cK);
  const double num = m.mu_s * m.I0 + m.mu_d * I + quad_ * I * I;
  const double den = m.I0 + I;
  return ((m.mu_d + 2.0 * quad_ * I) * den - num) / (den * den);
}

double MuCurve::mu(double I) const {
  if (I <= 0.0)
    return (kind_ == CurveKind::Regularised || kind_ == CurveKind::LowI) ? 0.0 : upper_branch(0.0);
  if (I <= junction_I_) return std::sqrt(material_.alpha / std::log(A_minus_ / I));  // (5.2), (6.3)
  return upper_branch(I);
}

void MuCurve::mu_many(std::span<const double> I, std::span<double> out) const {
  for (std::size_t i = 0; i < I.size(); ++i) out[i] = mu(I[i]);
}

double MuCurve::dmu_dI(double I) const {
  if (I <= junction_I_ && I > 0.0) {
    const double L = std::log(A_minus_ / I);
    return 0.5 * std::sqrt(material_.alpha) * std::pow(L, -1.5) / I;  // d/dI of (5.2)
  }
  return upper_branch_derivative(I);
}

MuCurve::WithLogSlope MuCurve::mu_with_log_slope(double I) const {
  if (I <= 0.0) return {mu(I), 0.0};
  if (I <= junction_I_) {  // (5.2): mu = sqrt(alpha / L), L = ln(A_- / I), so I mu'/mu = 1 / (2 L)
    const double L = std::log(A_minus_ / I);
    return {std::sqrt(material_.alpha / L), 0.5 / L};
  }
  if (kind_ == CurveKind::KamrinKoval) {
    const double m = upper_branch(I);
    return {m, I * upper_branch_derivative(I) / m};
  }
  // The rational upper branch mu = N / Q, N = mu_s I0 + mu_d I + q I^2, Q = I0 + I:
  // I mu'/mu = I (N' Q - N) / (Q N).
  const Material& m = material_;
  const double num = m.mu_s * m.I0 + m.mu_d * I + quad_ * I * I;
  const double den = m.I0 + I;
  return {num / den, I * ((m.mu_d + 2.0 * quad_ * I) * den - num) / (den * num)};
}

void MuCurve::mu_with_log_slope_many(std::span<const double> I, std::span<double> mu,
                                     std::span<double> log_slope) const {
  const std::size_t n = I.size();
  const double* in = I.data();
  double *mu_out = mu.data(), *slope_out = log_slope.data();
  if (kind_ != CurveKind::KamrinKoval) {
    // mu_with_log_slope's rational branch, the same expressions (one lane per I; GCC vectorises
    // the loop)
    const Material& m = material_;
    const double c0 = m.mu_s * m.I0, mu_d = m.mu_d, I0 = m.I0, q = quad_;
    for (std::size_t j = 0; j < n; ++j) {
      const double x = in[j];
      const double num = c0 + mu_d * x + q * x * x;
      const double den = I0 + x;
      mu_out[j] = num / den;
      slope_out[j] = x * ((mu_d + 2.0 * q * x) * den - num) / (den * num);
    }
  }
  // The I that the rational branch does not serve: I <= 0, and the low-I branch of I <= I1N
  // (rare in a flow: first count them, in a loop that vectorises)
  const double branch_limit = std::max(junction_I_, 0.0);
  int below = 0;
  for (std::size_t j = 0; j < n; ++j) below += in[j] <= branch_limit;
  if (kind_ != CurveKind::KamrinKoval && below == 0) return;
  for (std::size_t j = 0; j < n; ++j) {
    const double x = in[j];
    if (kind_ == CurveKind::KamrinKoval || x <= branch_limit) {
      const auto [m, s] = mu_with_log_slope(x);
      mu_out[j] = m;
      slope_out[j] = s;
    }
  }
}

double MuCurve::inverse(double target) const {
  if (!(target > mu_min_ && target < mu_max_)) {
    std::ostringstream msg;
    msg << "mu = " << target << " is outside the range (" << mu_min_ << ", " << mu_max_
        << ") of the " << curve_name(kind_) << " curve";
    throw CurveRangeError(msg.str());
  }
  if (junction_I_ > 0.0 && target <= mu(junction_I_))
    return A_minus_ * std::exp(-material_.alpha / (target * target));  // (5.2) inverted exactly
  // Upper branch: bracket in ln I, then Brent.
  double s_lo = junction_I_ > 0.0 ? std::log(junction_I_) : -60.0;
  double s_hi = 0.0;
  const std::function<double(double)> residual = [&](double s) {
    return upper_branch(std::exp(s)) - target;  // Brent over ln I: few steps across decades
  };
  while (residual(s_hi) < 0.0) {
    s_hi += 5.0;
    if (s_hi > 200.0) throw CurveRangeError("no I with mu(I) = target found below I = e^200");
  }
  if (residual(s_lo) > 0.0) {
    std::ostringstream msg;
    msg << "mu = " << target << " is below the values the " << curve_name(kind_) << " curve takes";
    throw CurveRangeError(msg.str());
  }
  return std::exp(brent_root(residual, s_lo, s_hi));
}

}  // namespace granbench

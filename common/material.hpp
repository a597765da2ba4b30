// Material and gravity constants for a granular chute flow.
//
// Defaults are the spherical glass ballotini of Barker & Gray (2017), table 1, with the
// regularisation constants of §5.2 (alpha) and §6.1 (mu_inf). Every value can be overridden from
// the command line or a case file; nothing in granbench reads a constant from anywhere else.
#pragma once

#include <array>

namespace granbench {

struct Material {
  double mu_s = 0.342;       // static friction coefficient, tan(zeta_s)          (table 1)
  double mu_d = 0.557;       // dynamic friction coefficient, tan(zeta_d)         (table 1)
  double I0 = 0.069;         // inertial-number scale of the Jop curve (2.12)     (table 1)
  double d = 1.43e-4;        // grain diameter [m]                                (table 1)
  double phi = 0.6;          // solids volume fraction                            (table 1)
  double rho_star = 2500.0;  // intrinsic grain density [kg m^-3] (glass)
  double g = 9.81;           // gravitational acceleration [m s^-2]
  double mu_inf = 0.05;      // high-I coefficient of the regularised curve (6.3)
  double alpha = 1.9;        // low-I regularisation constant of (5.2) and (6.3), alpha < 2
  // Kamrin & Koval (2014) local curve (5.1): friction at I = 0 and decay scale c_K. The paper
  // gives no values; these are illustrative defaults chosen so that mu_0 < mu_s.
  double kk_mu0 = 0.25;
  double kk_cK = 0.01;
  // Holyoake & McElwaine (2012) curve (6.1): mu_inf = c (h0/d)^(-1/3). The default c makes
  // mu_inf = 0.05 at h0 = 4 mm, matching the paper's fit in figure 6.
  double hm_c = 0.151819;

  double bulk_density() const { return rho_star * phi; }  // rho_* phi, the density in (2.10)
};

// Every constant of Material by name: its key in HDF5 attributes, JSON and stored sweep settings,
// and the command-line option that sets it. Outputs, the stored settings and the reproducing
// command lines iterate over this one list, so none of them can miss a constant.
struct MaterialConstant {
  const char* key;
  const char* option;
  double Material::*value;
};
inline constexpr std::array<MaterialConstant, 12> material_constants{{
    {"mu_s", "--mu-s", &Material::mu_s},
    {"mu_d", "--mu-d", &Material::mu_d},
    {"I0", "--I0", &Material::I0},
    {"d", "--d", &Material::d},
    {"phi", "--phi", &Material::phi},
    {"rho_star", "--rho-star", &Material::rho_star},
    {"g", "--g", &Material::g},
    {"mu_inf", "--mu-inf", &Material::mu_inf},
    {"alpha", "--alpha", &Material::alpha},
    {"kk_mu0", "--kk-mu0", &Material::kk_mu0},
    {"kk_cK", "--kk-cK", &Material::kk_cK},
    {"hm_c", "--hm-c", &Material::hm_c},
}};
// A constant added to Material without an entry above fails here.
static_assert(sizeof(Material) == material_constants.size() * sizeof(double),
              "every Material constant needs an entry in material_constants");

}  // namespace granbench

//! @file Monaghan artificial viscosity Pi_ij (spec section 3, docs/method.md), one pair.
#pragma once

namespace hvi::sph {

//! Pi_ij = (-alpha c_ij phi_ij + beta phi_ij^2) / rho_ij for approaching pairs (v_ij . x_ij < 0),
//! 0 otherwise; phi_ij = h_ij v_ij . x_ij / (|x_ij|^2 + varphi^2), varphi = 0.1 h_ij.
//! Pi has the units of P / rho^2 (cm^5 / (g us^2)).
struct MonaghanViscosity {
  double alpha = 1.0;
  double beta = 2.0;

  //! `vdotx` = v_ij . x_ij (cm^2/us), `r2` = |x_ij|^2, `h` = h_ij, `cbar` = (c_i + c_j)/2,
  //! `rhobar` = (rho_i + rho_j)/2. Writes phi_ij (cm/us, <= 0; 0 for receding pairs) to `phi`.
  double operator()(double vdotx, double r2, double h, double cbar, double rhobar,
                    double& phi) const {
    if (vdotx >= 0.0) {
      phi = 0.0;
      return 0.0;
    }
    phi = h * vdotx / (r2 + 0.01 * h * h);
    return (-alpha * cbar * phi + beta * phi * phi) / rhobar;
  }
};

}  // namespace hvi::sph

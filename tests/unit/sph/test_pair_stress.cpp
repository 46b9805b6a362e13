//! @file The strength pair terms (pair_stress.hpp): momentum and total energy balance of a
//! pair, the stress power of a uniform stress, the kernel velocity gradient of a linear field,
//! and Monaghan's artificial stress against its principal-frame definition.
#include <gtest/gtest.h>

#include <cmath>

#include "hvi/sph/kernel.hpp"
#include "hvi/sph/pair_stress.hpp"

namespace hvi::sph {
namespace {

Sym2 over(const Sym2& s, double rho) {
  const double k = 1.0 / (rho * rho);
  return {s.xx * k, s.zz * k, s.xz * k};
}
Sym2 add(const Sym2& a, const Sym2& b) { return {a.xx + b.xx, a.zz + b.zz, a.xz + b.xz}; }

TEST(PairStress, MomentumAndTotalEnergyBalanceOfAPair) {
  // Two particles with different masses, densities, stresses and velocities.
  const double xa = 0.1, za = -0.2, xb = 0.13, zb = -0.185, h = 0.02;
  const double ma = 1.3e-4, mb = 0.9e-4, rhoa = 2.7, rhob = 2.9;
  const double vxa = 0.05, vza = -0.02, vxb = -0.01, vzb = 0.03;
  const Sym2 sa{2e-3, -1e-3, 5e-4}, sb{-4e-4, 1.5e-3, -7e-4};
  const Sym2 t = add(over(sa, rhoa), over(sb, rhob));
  const double dx = xa - xb, dz = za - zb, r2 = dx * dx + dz * dz;
  const double f = GaussianKernel::gradFactor(GaussianKernel::value(r2, h), r2, h);
  const StressPairTerm ab = stressPairTerm(t, mb, vxa - vxb, vza - vzb, f * dx, f * dz);
  const StressPairTerm ba = stressPairTerm(t, ma, vxb - vxa, vzb - vza, -f * dx, -f * dz);
  const double scale = ma * (std::abs(ab.ax) + std::abs(ab.az));
  ASSERT_GT(scale, 0.0);
  EXPECT_NEAR(ma * ab.ax + mb * ba.ax, 0.0, 1e-15 * scale);
  EXPECT_NEAR(ma * ab.az + mb * ba.az, 0.0, 1e-15 * scale);
  // d/dt (kinetic + internal) = 0 for the pair, to round-off of its terms (|v| ~ 0.05).
  const double power =
      ma * (vxa * ab.ax + vza * ab.az) + mb * (vxb * ba.ax + vzb * ba.az) + ma * ab.de + mb * ba.de;
  EXPECT_NEAR(power, 0.0, 1e-15 * scale * 0.05);
}

// A square lattice (spacing dp, h = 1.2 dp, Gaussian) of uniform density: the sums at the
// centre particle, far from any edge.
struct Lattice {
  static constexpr int n = 4;  // 9 x 9 particles hold the support 3h = 3.6 dp
  double dp = 0.01, h = 0.012, rho = 2.7;
  double m() const { return rho * dp * dp; }
};

TEST(PairStress, VelocityGradientOfALinearFieldAtTheLatticeResolution) {
  // v = (a x + b z, c x + d z): the estimate is exact up to the lattice sum of
  // V r (x) grad W, which differs from -I by the kernel's discretisation error: measured here
  // first, then the gradient must match A times that moment to round-off.
  const Lattice L;
  const double a = 0.3, b = -0.7, c = 1.1, d = 0.2;
  VelocityGradientTerm g, mom;
  for (int i = -L.n; i <= L.n; ++i)
    for (int j = -L.n; j <= L.n; ++j) {
      if (i == 0 && j == 0) continue;
      const double x = i * L.dp, z = j * L.dp, r2 = x * x + z * z;
      // gradFactor holds inside the support only (the neighbour list's pairs).
      if (r2 >= 9.0 * L.h * L.h) continue;
      const double f = GaussianKernel::gradFactor(GaussianKernel::value(r2, L.h), r2, L.h);
      const double gx = -f * x, gz = -f * z;  // grad_a W_ab with a at the origin, b at (x, z)
      const auto t = velocityGradientTerm(L.m() / L.rho, a * x + b * z, c * x + d * z, gx, gz);
      g.xx += t.xx, g.xz += t.xz, g.zx += t.zx, g.zz += t.zz;
      const auto mxx = velocityGradientTerm(L.m() / L.rho, x, z, gx, gz);
      mom.xx += mxx.xx, mom.xz += mxx.xz, mom.zx += mxx.zx, mom.zz += mxx.zz;
    }
  // The moment sum_b V_b (x_b - x_a) (x) grad_a W_ab: the identity for a well-resolved kernel
  // (measured 0.99982 at h = 1.2 dp: the lattice sum of the Gaussian's second moment).
  EXPECT_NEAR(mom.xx, 1.0, 1e-3);
  EXPECT_NEAR(mom.zz, 1.0, 1e-3);
  EXPECT_NEAR(mom.xz, 0.0, 1e-14);
  // By linearity the gradient is A . moment: exact to round-off, so within the moment's error
  // (2e-4) of A itself.
  EXPECT_NEAR(g.xx, a * mom.xx, 1e-14);
  EXPECT_NEAR(g.xz, b * mom.zz, 1e-14);
  EXPECT_NEAR(g.zx, c * mom.xx, 1e-14);
  EXPECT_NEAR(g.zz, d * mom.zz, 1e-14);
}

TEST(PairStress, UniformStressGivesNoForceAndItsStressPower) {
  // A uniform stress over the lattice: the symmetric force sums to zero at the centre (the
  // lattice is point-symmetric), and the energy term sums to s : grad v / rho for a linear v.
  const Lattice L;
  const Sym2 s{3e-3, -1e-3, 2e-3};
  const Sym2 t = add(over(s, L.rho), over(s, L.rho));
  const double a = 0.3, b = -0.7, c = 1.1, d = 0.2;
  double ax = 0.0, az = 0.0, de = 0.0;
  VelocityGradientTerm mom;
  for (int i = -L.n; i <= L.n; ++i)
    for (int j = -L.n; j <= L.n; ++j) {
      if (i == 0 && j == 0) continue;
      const double x = i * L.dp, z = j * L.dp, r2 = x * x + z * z;
      // gradFactor holds inside the support only (the neighbour list's pairs).
      if (r2 >= 9.0 * L.h * L.h) continue;
      const double f = GaussianKernel::gradFactor(GaussianKernel::value(r2, L.h), r2, L.h);
      const double gx = -f * x, gz = -f * z;
      // v_a - v_b with v_a = 0 at the origin.
      const auto p = stressPairTerm(t, L.m(), -(a * x + b * z), -(c * x + d * z), gx, gz);
      ax += p.ax, az += p.az, de += p.de;
      const auto m = velocityGradientTerm(L.m() / L.rho, x, z, gx, gz);
      mom.xx += m.xx, mom.zz += m.zz;
    }
  EXPECT_NEAR(ax, 0.0, 1e-15);
  EXPECT_NEAR(az, 0.0, 1e-15);
  // -(1/2) sum m_b (v_a - v_b) . (2 s / rho^2) grad W = (s : grad v) / rho with the gradient's
  // lattice moment (mom.xx = mom.zz on a square lattice).
  const double expect =
      (s.xx * a * mom.xx + s.xz * (b * mom.zz + c * mom.xx) + s.zz * d * mom.zz) / L.rho;
  EXPECT_NEAR(de, expect, 1e-14 * std::abs(expect));
}

TEST(PairStress, ArtificialStressActsOnTensionOnlyInThePrincipalFrame) {
  const double rho = 2.0, eps = 0.3;
  // Uniaxial tension along x: R_xx = -eps sigma / rho^2, nothing else.
  Sym2 r = artificialStress({1.0, 0.0, 0.0}, rho, eps);
  EXPECT_DOUBLE_EQ(r.xx, -0.3 / 4.0);
  EXPECT_DOUBLE_EQ(r.zz, 0.0);
  EXPECT_DOUBLE_EQ(r.xz, 0.0);
  // Compression: none.
  r = artificialStress({-1.0, -2.0, 0.5}, rho, eps);
  EXPECT_EQ(r.xx, 0.0);
  EXPECT_EQ(r.zz, 0.0);
  EXPECT_EQ(r.xz, 0.0);
  // Pure shear [[0, 1], [1, 0]]: +1 along (1, 1)/sqrt2, -1 along (1, -1)/sqrt2, so
  // R = -eps / rho^2 n n^T = -eps / (2 rho^2) [[1, 1], [1, 1]].
  r = artificialStress({0.0, 0.0, 1.0}, rho, eps);
  EXPECT_NEAR(r.xx, -0.3 / 8.0, 1e-16);
  EXPECT_NEAR(r.zz, -0.3 / 8.0, 1e-16);
  EXPECT_NEAR(r.xz, -0.3 / 8.0, 1e-16);
  // Isotropic tension: -eps sigma / rho^2 I.
  r = artificialStress({2.0, 2.0, 0.0}, rho, eps);
  EXPECT_DOUBLE_EQ(r.xx, -0.15);
  EXPECT_DOUBLE_EQ(r.zz, -0.15);
  EXPECT_DOUBLE_EQ(r.xz, 0.0);
}

}  // namespace
}  // namespace hvi::sph

"""Exact solutions the study measures against, in python (numpy only).

- ``ToroRiemann``: the exact Riemann problem for one ideal gas (Toro, *Riemann Solvers and
  Numerical Methods for Fluid Dynamics*, 3rd ed., ch. 4: pressure function, Newton iteration on
  p*, sampling). Used for Sod; checked against the C++ general-EOS solver (`hvi run` with
  solver = "riemann") by ``tools/study.py --selftest``.
- ``noh_density``: the Noh implosion of a cold ideal gas, planar / cylindrical / spherical, in
  closed form (Noh 1987; docs/verification.md).
All quantities in hvi's cm-g-us units (velocity cm/us, pressure Mbar).
"""
import math

import numpy as np


class ToroRiemann:
    """Exact solution of the 1-D Riemann problem for an ideal gas of ratio `gamma`.

    Left and right states are (rho, u, p); `sample(xi)` gives (rho, u, p) at xi = (x - x0)/t.
    Assumes no vacuum is generated (true for the shock tubes here; checked).
    """

    def __init__(self, gamma, left, right):
        self.g = gamma
        self.l = tuple(map(float, left))
        self.r = tuple(map(float, right))
        rl, ul, pl = self.l
        rr, ur, pr = self.r
        self.cl = math.sqrt(gamma * pl / rl)
        self.cr = math.sqrt(gamma * pr / rr)
        if 2.0 / (gamma - 1.0) * (self.cl + self.cr) <= ur - ul:
            raise ValueError("vacuum is generated; not handled")
        self.p_star, self.u_star = self._star()

    def _f(self, p, rho, pk, ck):
        """Toro's f_K(p) and its derivative (eqs. 4.6, 4.7, 4.37)."""
        g = self.g
        if p > pk:  # shock
            a = 2.0 / ((g + 1.0) * rho)
            b = (g - 1.0) / (g + 1.0) * pk
            q = math.sqrt(a / (p + b))
            return (p - pk) * q, q * (1.0 - 0.5 * (p - pk) / (b + p))
        pr = p / pk  # rarefaction
        f = 2.0 * ck / (g - 1.0) * (pr ** ((g - 1.0) / (2.0 * g)) - 1.0)
        return f, 1.0 / (rho * ck) * pr ** (-(g + 1.0) / (2.0 * g))

    def _star(self):
        rl, ul, pl = self.l
        rr, ur, pr = self.r
        du = ur - ul
        # Two-rarefaction guess (Toro 4.46): exact when both waves are rarefactions, close
        # otherwise, and always positive.
        z = (self.g - 1.0) / (2.0 * self.g)
        p = ((self.cl + self.cr - 0.5 * (self.g - 1.0) * du)
             / (self.cl / pl ** z + self.cr / pr ** z)) ** (1.0 / z)
        for _ in range(100):
            fl, dl = self._f(p, rl, pl, self.cl)
            fr, dr = self._f(p, rr, pr, self.cr)
            p_new = max(p - (fl + fr + du) / (dl + dr), 1e-14 * p)
            done = abs(p_new - p) <= 1e-15 * (p_new + p)
            p = p_new
            if done:
                break
        fl, _ = self._f(p, rl, pl, self.cl)
        fr, _ = self._f(p, rr, pr, self.cr)
        return p, 0.5 * (ul + ur) + 0.5 * (fr - fl)

    def star_densities(self):
        return self._side_star(self.l, self.cl), self._side_star(self.r, self.cr)

    def _side_star(self, state, c):
        rho, _, pk = state
        g, ps = self.g, self.p_star
        if ps > pk:
            q = ps / pk
            gm = (g - 1.0) / (g + 1.0)
            return rho * (q + gm) / (gm * q + 1.0)
        return rho * (ps / pk) ** (1.0 / g)

    def shock_speed_right(self):
        rr, ur, pr = self.r
        g = self.g
        return ur + self.cr * math.sqrt((g + 1.0) / (2.0 * g) * self.p_star / pr
                                        + (g - 1.0) / (2.0 * g))

    def sample(self, xi):
        """Density, velocity and pressure at similarity coordinates xi (array)."""
        xi = np.asarray(xi, dtype=float)
        rho = np.empty_like(xi)
        u = np.empty_like(xi)
        p = np.empty_like(xi)
        left = xi <= self.u_star
        for mask, state, c, sign in ((left, self.l, self.cl, -1.0),
                                     (~left, self.r, self.cr, 1.0)):
            r_, u_, p_ = self._sample_side(xi[mask], state, c, sign)
            rho[mask], u[mask], p[mask] = r_, u_, p_
        return rho, u, p

    def _sample_side(self, xi, state, c, sign):
        """One side of the contact; sign = -1 left (waves move to -x), +1 right."""
        g, ps, us = self.g, self.p_star, self.u_star
        rk, uk, pk = state
        rs = self._side_star(state, c)
        rho = np.full_like(xi, rk)
        u = np.full_like(xi, uk)
        p = np.full_like(xi, pk)
        if ps > pk:  # shock at speed s: beyond it the initial state, inside the star state
            s = uk + sign * c * math.sqrt((g + 1.0) / (2.0 * g) * ps / pk + (g - 1.0) / (2.0 * g))
            inside = sign * (xi - s) < 0.0
            rho[inside], u[inside], p[inside] = rs, us, ps
            return rho, u, p
        cs = c * (ps / pk) ** ((g - 1.0) / (2.0 * g))
        head, tail = uk + sign * c, us + sign * cs
        star = sign * (xi - tail) <= 0.0
        fan = (~star) & (sign * (xi - head) < 0.0)
        rho[star], u[star], p[star] = rs, us, ps
        x = xi[fan]
        # Inside the fan (Toro 4.56 left, 4.63 right).
        factor = 2.0 / (g + 1.0) - sign * (g - 1.0) / ((g + 1.0) * c) * (uk - x)
        rho[fan] = rk * factor ** (2.0 / (g - 1.0))
        u[fan] = 2.0 / (g + 1.0) * (-sign * c + 0.5 * (g - 1.0) * uk + x)
        p[fan] = pk * factor ** (2.0 * g / (g - 1.0))
        return rho, u, p


def sod_density(x, t, x0=0.5, gamma=1.4, left=(1.0, 0.0, 1.0), right=(0.125, 0.0, 0.1)):
    """Density of Sod's problem at positions x (cm) and time t (us)."""
    return ToroRiemann(gamma, left, right).sample((np.asarray(x) - x0) / t)[0]


def noh_density(r, t, n, gamma=5.0 / 3.0, rho0=1.0, u0=1.0):
    """Noh implosion: cold gas rho0 flowing to r = 0 at u0; n = 0 planar, 1 cyl., 2 spherical.

    Shock at r_s = u0 (gamma - 1) t / 2; inside rho0 ((g+1)/(g-1))^(n+1), outside
    rho0 (1 + u0 t / r)^n (the converging stream compresses geometrically).
    """
    r = np.asarray(r, dtype=float)
    rs = 0.5 * u0 * (gamma - 1.0) * t
    inside = rho0 * ((gamma + 1.0) / (gamma - 1.0)) ** (n + 1)
    with np.errstate(divide="ignore"):
        outside = rho0 * (1.0 + u0 * t / np.maximum(r, 1e-300)) ** n
    return np.where(r < rs, inside, outside)


def selftest():
    """Published values (docs/verification.md, Toro table 4.2): Sod and Noh."""
    s = ToroRiemann(1.4, (1.0, 0.0, 1.0), (0.125, 0.0, 0.1))
    rl, rr = s.star_densities()
    checks = [("p*", s.p_star, 0.303130), ("u*", s.u_star, 0.927453),
              ("rho*L", rl, 0.426319), ("rho*R", rr, 0.265574),
              ("shock speed", s.shock_speed_right(), 1.752156)]
    # Toro's test 3 (strong left rarefaction/right shock): p* = 460.894, u* = 19.5975.
    t3 = ToroRiemann(1.4, (1.0, 0.0, 1000.0), (1.0, 0.0, 0.01))
    checks += [("Toro 3 p*", t3.p_star, 460.894), ("Toro 3 u*", t3.u_star, 19.5975)]
    checks += [("Noh cyl rho", float(noh_density(0.1, 0.6, 1)), 16.0),
               ("Noh planar rho", float(noh_density(0.1, 0.6, 0)), 4.0)]
    # Tillotson Al at 7 km/s, symmetric (docs/verification.md, from the C++ general-EOS solver).
    tube = SymmetricImpactTube(v=0.7, u_left=0.7, x0=1.0)
    checks += [("Al p*", tube.p_star, 0.988212845), ("Al rho*", tube.rho_star, 4.265087292),
               ("Al Us", tube.us, 1.011995)]
    ok = True
    for name, got, want in checks:
        # The published values carry 6 significant digits: agreement to 5e-6 relative is exact.
        good = abs(got - want) <= 5e-6 * abs(want)
        ok &= good
        print(f"  {name:14s} {got:.7g} (published {want}) {'ok' if good else 'MISMATCH'}")
    # Mass conservation of the fan: integral of rho over the tube equals the initial mass.
    x = np.linspace(0.0, 1.0, 200001)
    rho = sod_density(x, 0.2)
    mass = np.trapz(rho, x)
    good = abs(mass - 0.5625) < 1e-4  # trapezoid on 5e-6 cm cells: jumps cost ~ 1e-5
    ok &= good
    print(f"  Sod mass       {mass:.7f} (initial 0.5625) {'ok' if good else 'MISMATCH'}")
    return ok


# The study's Tillotson aluminium (spec section 2, docs/method.md;
# eos/include/hvi/eos/tillotson.hpp).
TILLOTSON_AL = {"rho0": 2.79, "a": 0.5, "b": 1.63, "A": 0.75, "B": 0.65, "e0": 0.05}


def tillotson_compressed_pressure(rho, e, p=TILLOTSON_AL):
    """Tillotson's compressed-region pressure P_c (rho >= rho0), Mbar."""
    eta = rho / p["rho0"]
    mu = eta - 1.0
    return (p["a"] + p["b"] / (e / (p["e0"] * eta * eta) + 1.0)) * rho * e + p["A"] * mu \
        + p["B"] * mu * mu


class SymmetricImpactTube:
    """Equal slabs of Tillotson aluminium at rest density, e = 0, meeting at x0 with closing
    speed v: two shocks, the material between them at rest in the centre-of-mass frame with
    particle speed up = v/2 relative to each slab and e* = up^2/2. The shock speed Us (relative to
    the unshocked slab) solves P_c(rho0 Us/(Us - up), up^2/2) = rho0 Us up (Rankine-Hugoniot);
    the left-hand side minus the right changes sign once on Us in (up, 100 up), found by bisection.
    """

    def __init__(self, v, u_left, x0, p=TILLOTSON_AL):
        self.up = 0.5 * v
        self.rho0 = p["rho0"]
        self.u_left, self.x0 = u_left, x0
        up, rho0 = self.up, self.rho0
        e = 0.5 * up * up

        def g(us):
            return tillotson_compressed_pressure(rho0 * us / (us - up), e, p) - rho0 * us * up

        lo, hi = up * (1.0 + 1e-9), 100.0 * up
        if g(lo) * g(hi) > 0.0:
            raise ValueError("no Hugoniot root bracketed")
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if (g(lo) > 0.0) == (g(mid) > 0.0):
                lo = mid
            else:
                hi = mid
        self.us = 0.5 * (lo + hi)
        self.rho_star = rho0 * self.us / (self.us - up)
        self.p_star = rho0 * self.us * up
        self.e_star = e

    def density(self, x, t):
        """Lab frame: the left slab moves at u_left, the right one at u_left - v (both along x)."""
        x = np.asarray(x, dtype=float)
        left_shock = self.x0 + (self.u_left - self.us) * t
        right_shock = self.x0 + (self.u_left - 2.0 * self.up + self.us) * t
        return np.where((x > left_shock) & (x < right_shock), self.rho_star, self.rho0)


def al_tube_density(x, t):
    """The Tillotson aluminium impact tube (cases/scenes/al_impact_tube.toml): 7 km/s onto rest."""
    return SymmetricImpactTube(v=0.7, u_left=0.7, x0=1.0).density(x, t)

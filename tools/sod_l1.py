#!/usr/bin/env python3
"""L1 density error of hvi's 2-D Sod run (tools/bench_anchors.sh sod) against the exact solution.

    tools/sod_l1.py <output folder>/checkpoint.bin [t] [x_diaphragm]

Reads the density from the TVD record of a run's checkpoint (tvd/src/checkpoint.cpp, version 4:
header, five budgets, then the conserved arrays) and prints mean |rho - rho_exact| over all cells, the norm
Athena++'s shock_tube problem writes to shock-errors.dat (sum |rho - rho_exact| dV / V). The
exact solution is the ideal-gas Riemann problem of Sod (1978): (rho, u, p) = (1, 0, 1) left,
(0.125, 0, 0.1) right, gamma 1.4, Toro (2009) section 4.2 (Newton iteration for p*).
Standard library only (no numpy)."""
import math
import struct
import sys

G = 1.4
L = (1.0, 0.0, 1.0)
R = (0.125, 0.0, 0.1)


def f_k(p, rho, pk):
    a = math.sqrt(G * pk / rho)
    if p > pk:  # shock
        A, B = 2.0 / ((G + 1) * rho), (G - 1) / (G + 1) * pk
        f = (p - pk) * math.sqrt(A / (p + B))
        df = math.sqrt(A / (B + p)) * (1 - (p - pk) / (2 * (B + p)))
    else:  # rarefaction
        f = 2 * a / (G - 1) * ((p / pk) ** ((G - 1) / (2 * G)) - 1)
        df = 1 / (rho * a) * (p / pk) ** (-(G + 1) / (2 * G))
    return f, df


def star():
    p = 0.5 * (L[2] + R[2])
    for _ in range(100):
        fl, dl = f_k(p, L[0], L[2])
        fr, dr = f_k(p, R[0], R[2])
        dp = (fl + fr + R[1] - L[1]) / (dl + dr)
        p = max(p - dp, 1e-12)
        if abs(dp) < 1e-15 * p:
            break
    u = 0.5 * (L[1] + R[1]) + 0.5 * (f_k(p, R[0], R[2])[0] - f_k(p, L[0], L[2])[0])
    return p, u


def density(s, ps, us):
    """Exact density at x/t = s (Sod: left rarefaction, right shock)."""
    rl, ul, pl = L
    rr, ur, pr = R
    al = math.sqrt(G * pl / rl)
    if s < us:
        head = ul - al
        rls = rl * (ps / pl) ** (1 / G)
        tail = us - al * (ps / pl) ** ((G - 1) / (2 * G))
        if s <= head:
            return rl
        if s >= tail:
            return rls
        return rl * (2 / (G + 1) + (G - 1) / ((G + 1) * al) * (ul - s)) ** (2 / (G - 1))
    ratio = ps / pr
    rrs = rr * (ratio + (G - 1) / (G + 1)) / ((G - 1) / (G + 1) * ratio + 1)
    ar = math.sqrt(G * pr / rr)
    shock = ur + ar * math.sqrt((G + 1) / (2 * G) * ratio + (G - 1) / (2 * G))
    return rrs if s < shock else rr


def main():
    path = sys.argv[1]
    t = float(sys.argv[2]) if len(sys.argv) > 2 else 0.2
    x0 = float(sys.argv[3]) if len(sys.argv) > 3 else 0.5
    with open(path, "rb") as f:
        data = f.read()
    # hvi's run checkpoint wraps the solver's record: find the TVD record by its tag.
    start = data.find(struct.pack("<Q", 0x31304456544956))  # "VITVD01"
    if start < 0:
        sys.exit(f"{path}: no TVD checkpoint record in it")
    (version,) = struct.unpack_from("<I", data, start + 8)
    if version != 4:
        sys.exit(f"{path}: TVD checkpoint version {version}, this reader knows 4")
    nx, nz, rz, markers, cut = struct.unpack_from("<5i", data, start + 12)
    off = start + 12 + 20 + 8 * 4 + 5 * 4 * 8
    (n,) = struct.unpack_from("<Q", data, off)
    if n != nx * nz:
        sys.exit(f"{path}: density array of {n} values for a {nx} x {nz} grid")
    rho = struct.unpack_from(f"<{n}d", data, off + 8)
    ps, us = star()
    h = 1.0 / nx  # the bench's grid: [0, 1] along x
    exact = [density(((i + 0.5) * h - x0) / t, ps, us) for i in range(nx)]
    total = 0.0
    for k in range(nz):
        row = rho[k * nx:(k + 1) * nx]
        total += sum(abs(a - b) for a, b in zip(row, exact))
    print(f"{total / n:.6e}")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""The two inverse methods of issue 59 measured on the radial problem.

    python3 benchmarks/unloaded_shape/compare_methods.py [--elements N]

A thick-walled neo-Hookean cylinder in plane strain (reference radii 1 and
2, E = 1, nu = 0.3), internal follower pressure p = 0.15, outer surface
free, reduced to its radial problem r(R) and discretised with linear
elements. The loaded radii come from a forward solve; from them (a mesh of
the loaded annulus, its nodes fixed) the reference is sought by

  fixed point:  the backward-displacement iteration X <- X + w (x^ - x(X))
                with Aitken relaxation, a whole forward solve (Newton in
                load steps, as the program runs a scene) per iteration: the
                method the program implements (source/inverse/unloaded_shape.cc);
  inverse:      the formulation of Govindjee and Mihalic: Cauchy
                equilibrium on the fixed loaded mesh, the reference radii
                R(r) the unknowns, one Newton solve (its tangent here by
                central differences: a prototype).

Both stop at the same geometric tolerance (1e-8 of the outer radius). The
script prints the iterations, the Newton iterations in all and the time of
each, and the recovered radii against the exact 1 and 2; it writes
compare_methods.csv beside itself.
"""
import argparse
import csv
import os
import time

import numpy

MU = 1.0 / 2.6
LAMBDA = 0.3 / (1.3 * 0.4)
PRESSURE = 0.15
GAUSS = [(0.5 - 0.5 / 3 ** 0.5, 0.5), (0.5 + 0.5 / 3 ** 0.5, 0.5)]


def stresses(lr, lt):
    """P_rR, P_tT and their derivatives of compressible neo-Hookean."""
    lnj = numpy.log(lr * lt)
    prr = MU * (lr - 1 / lr) + LAMBDA * lnj / lr
    ptt = MU * (lt - 1 / lt) + LAMBDA * lnj / lt
    drr = MU * (1 + 1 / lr ** 2) + LAMBDA * (1 - lnj) / lr ** 2
    dtt = MU * (1 + 1 / lt ** 2) + LAMBDA * (1 - lnj) / lt ** 2
    drt = LAMBDA / (lr * lt)
    return prr, ptt, drr, dtt, drt


def forward_system(R, r, load):
    """Residual and tangent of the radial problem on the reference mesh R."""
    n = len(R)
    res = numpy.zeros(n)
    K = numpy.zeros((n, n))
    for e in range(n - 1):
        h = R[e + 1] - R[e]
        for xi, w in GAUSS:
            Rq = R[e] + xi * h
            N = numpy.array([1 - xi, xi])
            dN = numpy.array([-1 / h, 1 / h])
            rq = N @ r[e:e + 2]
            lr, lt = dN @ r[e:e + 2], rq / Rq
            prr, ptt, drr, dtt, drt = stresses(lr, lt)
            g = dN * prr + N / Rq * ptt
            res[e:e + 2] += g * Rq * w * h
            dlr, dlt = dN, N / Rq
            for a in range(2):
                for b in range(2):
                    K[e + a, e + b] += (dN[a] * (drr * dlr[b] + drt * dlt[b]) +
                                        N[a] / Rq * (drt * dlr[b] + dtt * dlt[b])) * Rq * w * h
    # The follower pressure on the inner surface: p r(A) per unit angle.
    res[0] -= load * r[0]
    K[0, 0] -= load
    return res, K


def forward_solve(R, steps=4):
    """r(R) under the full pressure, in load steps; Newton iterations."""
    r = R.copy()
    iterations = 0
    for s in range(1, steps + 1):
        load = PRESSURE * s / steps
        for _ in range(50):
            res, K = forward_system(R, r, load)
            iterations += 1
            if numpy.linalg.norm(res) < 1e-12:
                break
            du = numpy.linalg.solve(K, res)
            r -= du
            if numpy.linalg.norm(du) < 1e-14 * numpy.linalg.norm(r):
                break
    return r, iterations


def inverse_residual(r, R):
    """Cauchy equilibrium on the loaded mesh r with reference radii R."""
    n = len(r)
    res = numpy.zeros(n)
    for e in range(n - 1):
        h = r[e + 1] - r[e]
        for xi, w in GAUSS:
            rq = r[e] + xi * h
            N = numpy.array([1 - xi, xi])
            dN = numpy.array([-1 / h, 1 / h])
            Rq = N @ R[e:e + 2]
            lr, lt = 1 / (dN @ R[e:e + 2]), rq / Rq
            prr, ptt, _, _, _ = stresses(lr, lt)
            srr, stt = prr / lt, ptt / lr
            res[e:e + 2] += (dN * srr + N / rq * stt) * rq * w * h
    res[0] -= PRESSURE * r[0]
    return res


def inverse_solve(r):
    R = r.copy()
    iterations = 0
    for _ in range(50):
        res = inverse_residual(r, R)
        iterations += 1
        if numpy.linalg.norm(res) < 1e-12:
            break
        J = numpy.zeros((len(R), len(R)))
        for j in range(len(R)):
            d = 1e-7 * R[j]
            Rp, Rm = R.copy(), R.copy()
            Rp[j] += d
            Rm[j] -= d
            J[:, j] = (inverse_residual(r, Rp) - inverse_residual(r, Rm)) / (2 * d)
        dR = numpy.linalg.solve(J, res)
        R -= dR
        if numpy.linalg.norm(dR) < 1e-14 * numpy.linalg.norm(R):
            break
    return R, iterations


def fixed_point(x_loaded, tolerance):
    X = x_loaded.copy()
    omega, previous = 1.0, None
    solves = newton = 0
    while solves < 100:
        x, its = forward_solve(X)
        solves += 1
        newton += its
        residual = x_loaded - x
        if numpy.max(numpy.abs(residual)) <= tolerance:
            return X, solves, newton
        if previous is not None:
            change = residual - previous
            omega = -omega * (previous @ change) / (change @ change)
        previous = residual
        X = X + omega * residual
    raise RuntimeError("the fixed point did not converge in 100 solves")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--elements", type=int, default=40)
    args = parser.parse_args()
    R_exact = numpy.linspace(1.0, 2.0, args.elements + 1)
    x_loaded, _ = forward_solve(R_exact)
    tolerance = 1e-8 * 2.0
    rows = []
    start = time.perf_counter()
    X, solves, newton = fixed_point(x_loaded, tolerance)
    rows.append(("fixed point (Aitken)", solves, newton,
                 time.perf_counter() - start, X[0], X[-1]))
    start = time.perf_counter()
    R, its = inverse_solve(x_loaded)
    rows.append(("inverse (Govindjee-Mihalic)", 1, its,
                 time.perf_counter() - start, R[0], R[-1]))
    start = time.perf_counter()
    _, its = forward_solve(R_exact)
    forward = time.perf_counter() - start
    print(f"loaded radii: inner {x_loaded[0]:.10f}, outer {x_loaded[-1]:.10f}"
          f" ({args.elements} elements; one forward solve: {its} Newton "
          f"iterations, {forward:.3f} s)")
    print(f"{'method':30s} {'solves':>6s} {'Newton':>6s} {'time/s':>8s} "
          f"{'R inner - 1':>12s} {'R outer - 2':>12s}")
    for name, s, n, t, inner, outer in rows:
        print(f"{name:30s} {s:6d} {n:6d} {t:8.3f} {inner - 1:12.2e} "
              f"{outer - 2:12.2e}")
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                        "compare_methods.csv")
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["method", "forward_solves", "newton_iterations",
                      "seconds", "inner_error", "outer_error",
                      "forward_solve_newton", "forward_solve_seconds"])
        for name, s, n, t, inner, outer in rows:
            out.writerow([name, s, n, f"{t:.4f}", f"{inner - 1:.3e}",
                          f"{outer - 2:.3e}", its, f"{forward:.4f}"])


if __name__ == "__main__":
    main()

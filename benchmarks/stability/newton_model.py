#!/usr/bin/python3
"""A NumPy model of the crush (stress test 25) for trying Newton variants
in seconds instead of rebuilds (issue 28).

The model is the program's scene re-done in NumPy/SciPy: the same mesh as
deal.II's subdivided_hyper_rectangle_with_simplices (each box cut into 5
tetrahedra, the two mirror patterns alternating with i + j + k), the same
stable neo-Hookean energy (mu' = 4/3 mu, lambda' = lambda + 5/6 mu,
psi = mu'/2 (d - ln(1 + d/4)) + (J - 1)(lambda'/2 (J - 1) - 3/4 mu')),
bottom clamped, top clamped and pushed down by c t. Linear solves are
exact (sparse LU), so iteration counts differ slightly from the program's
(inexact CG + AMG): the reference variant 'line search' needs 48
iterations for the one-step crush here and 45 in the program.

Variants (each a Newton solve per load step, at most --iterations
iterations, the adaptive stepper halving a failed increment and doubling
after an easy step, like Load stepping/Adaptive):
  line search     the program's automatic tangent: dP/dF projected to
                  PSD where J <= 0 until the residual fell by 1e-3, then
                  exact; energy backtracking (Armijo 1e-4); the first
                  iteration imposes the boundary increment with the
                  tangent (the program's predictor)
  exact search    the same directions, step length minimising the energy
                  along them (bounded scalar search on [0, 2])
  trust region    exact tangent, Steihaug-Toint CG in a trust region,
                  preconditioned by the tangent projected everywhere
                  (an ideal SPD preconditioner), radius from the ratio
                  of actual to predicted energy decrease
  laplace         'line search', but the boundary increment is extended
                  into the body by the vector Laplacian instead of the
                  tangent (no cell of the crush inverts in the predictor)

  /usr/bin/python3 benchmarks/stability/newton_model.py          # writes newton_model.csv (~10 min)
  /usr/bin/python3 benchmarks/stability/newton_model.py --quick  # the 6 x 6 x 6 crush only
"""
import argparse
import csv
import os

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from scipy.optimize import minimize_scalar

HERE = os.path.dirname(os.path.abspath(__file__))
EPS = np.zeros((3, 3, 3))
EPS[0, 1, 2] = EPS[1, 2, 0] = EPS[2, 0, 1] = 1.
EPS[0, 2, 1] = EPS[2, 1, 0] = EPS[1, 0, 2] = -1.
# deal.II 9.4's 5-tetrahedron split of a box (local vertices x fastest).
EVEN = [[0, 1, 2, 4], [2, 1, 3, 7], [1, 4, 5, 7], [2, 4, 7, 6], [1, 2, 4, 7]]
ODD = [[0, 1, 3, 5], [0, 3, 2, 6], [0, 4, 5, 6], [3, 5, 7, 6], [0, 3, 6, 5]]


class Crush:
    """The unit cube of n^3 boxes, stable neo-Hookean (E = 1, nu),
    clamped at z = 0 and z = 1, the top pushed down by compression * t."""

    def __init__(self, n, nu, compression):
        mu = 1. / (2. * (1. + nu))
        lam = nu / ((1. + nu) * (1. - 2. * nu))
        self.mu, self.lam = 4. / 3. * mu, lam + 5. / 6. * mu
        self.compression = compression
        xs = np.linspace(0., 1., n + 1)
        self.X = np.array([[x, y, z] for z in xs for y in xs for x in xs])

        def vid(i, j, k):
            return i + (n + 1) * (j + (n + 1) * k)
        cells = []
        for k in range(n):
            for j in range(n):
                for i in range(n):
                    box = [vid(i + a, j + b, k + c) for c in (0, 1)
                           for b in (0, 1) for a in (0, 1)]
                    for tet in (EVEN if (i + j + k) % 2 == 0 else ODD):
                        cells.append([box[v] for v in tet])
        self.T = np.array(cells)
        Dm = np.stack([self.X[self.T[:, a]] - self.X[self.T[:, 0]]
                       for a in (1, 2, 3)], axis=2)
        self.vol = np.linalg.det(Dm) / 6.
        assert (self.vol > 0.).all()
        self.G = np.zeros((len(self.T), 4, 3))
        self.G[:, 1:, :] = np.linalg.inv(Dm)
        self.G[:, 0, :] = -self.G[:, 1:, :].sum(1)
        self.ndof = 3 * len(self.X)
        self.dofs = (3 * self.T[:, :, None] + np.arange(3)).reshape(-1, 12)
        z = self.X[:, 2]
        self.top = np.where(np.isclose(z, 1.))[0]
        bottom = np.where(np.isclose(z, 0.))[0]
        both = np.concatenate([bottom, self.top])
        self.fixed = (3 * both[:, None] + np.arange(3)).ravel()
        self.free = np.setdiff1d(np.arange(self.ndof), self.fixed)
        self.B = np.zeros((len(self.T), 9, 12))  # dF_iJ / du_ai
        for a in range(4):
            for i in range(3):
                self.B[:, 3 * i:3 * i + 3, 3 * a + i] = self.G[:, a, :]
        self.rows = np.repeat(self.dofs, 12, axis=1).ravel()
        self.cols = np.tile(self.dofs, (1, 12)).ravel()
        # The vector Laplacian (grad u : grad v).
        K = np.zeros((len(self.T), 12, 12))
        KL = np.einsum('e,eaJ,ebJ->eab', self.vol, self.G, self.G)
        for i in range(3):
            K[:, i::3, i::3] = KL
        self.laplacian = self.assemble(K)

    def assemble(self, Ke):
        return sp.csr_matrix((Ke.ravel(), (self.rows, self.cols)),
                             shape=(self.ndof, self.ndof))

    def prescribed(self, t):
        v = np.zeros(self.ndof)
        v[3 * self.top + 2] = -self.compression * t
        return v

    def F(self, u):
        x = self.X + u.reshape(-1, 3)
        return np.einsum('eai,eaJ->eiJ', x[self.T], self.G)

    def min_J(self, u):
        return np.linalg.det(self.F(u)).min()

    def energy(self, u):
        F = self.F(u)
        d = np.einsum('eij,eij->e', F, F) - 3.
        J = np.linalg.det(F)
        psi = (0.5 * self.mu * (d - np.log1p(0.25 * d)) +
               (J - 1.) * (0.5 * self.lam * (J - 1.) - 0.75 * self.mu))
        return (self.vol * psi).sum()

    def _parts(self, F):
        IC = np.einsum('eij,eij->e', F, F)
        J = np.linalg.det(F)
        cof = 0.5 * np.einsum('imn,JMN,emM,enN->eiJ', EPS, EPS, F, F)
        shear = self.mu * (1. - 1. / (IC + 1.))
        volume = self.lam * (J - 1.) - 0.75 * self.mu
        return IC, J, cof, shear, volume

    def gradient(self, u):
        F = self.F(u)
        IC, J, cof, shear, volume = self._parts(F)
        P = shear[:, None, None] * F + volume[:, None, None] * cof
        fe = np.einsum('e,eiJ,eaJ->eai', self.vol, P, self.G).reshape(-1, 12)
        g = np.zeros(self.ndof)
        np.add.at(g, self.dofs, fe)
        return g

    def hessian(self, u, project='none'):
        """The tangent; dP/dF projected to PSD at no point ('none'), where
        J <= 0 ('inverted') or everywhere ('all')."""
        F = self.F(u)
        IC, J, cof, shear, volume = self._parts(F)
        I3 = np.eye(3)
        A = shear[:, None, None, None, None] * \
            np.einsum('ik,JL->iJkL', I3, I3)[None]
        A += (2. * self.mu / (IC + 1.) ** 2)[:, None, None, None, None] * \
            np.einsum('eiJ,ekL->eiJkL', F, F)
        A += self.lam * np.einsum('eiJ,ekL->eiJkL', cof, cof)
        A += volume[:, None, None, None, None] * \
            np.einsum('ikm,JLN,emN->eiJkL', EPS, EPS, F)
        A = A.reshape(-1, 9, 9)
        mask = (J <= 0.) if project == 'inverted' else \
            np.full(len(J), project == 'all')
        if mask.any():
            w, V = np.linalg.eigh(A[mask])
            A[mask] = np.einsum('eij,ej,ekj->eik', V, np.maximum(w, 0.), V)
        Ke = np.einsum('e,eki,ekl,elj->eij', self.vol, self.B, A, self.B)
        return self.assemble(Ke)


def solve_free(model, H, rhs):
    f = model.free
    return spla.spsolve(H[f][:, f].tocsc(), rhs)


def predictor(model, u, t, kind):
    """u with the boundary increment to t imposed and extended inside by
    the tangent (the program's first Newton iteration) or the Laplacian."""
    du = np.zeros(model.ndof)
    du[model.fixed] = model.prescribed(t)[model.fixed] - u[model.fixed]
    H = model.laplacian if kind == 'laplace' else model.hessian(u)
    rhs = -(H @ du) if kind == 'laplace' else -(model.gradient(u) + H @ du)
    du[model.free] = solve_free(model, H, rhs[model.free])
    return u + du


def steihaug(H, g, radius, precondition, tolerance):
    """min g.p + p.H.p/2 with |p| <= radius (Steihaug-Toint CG)."""
    p = np.zeros_like(g)
    r = g.copy()
    z = precondition(r)
    d = -z
    rz = r @ z
    for k in range(1, 10 * len(g)):
        Hd = H @ d
        curvature = d @ Hd
        if curvature > 0.:
            alpha = rz / curvature
            if np.linalg.norm(p + alpha * d) < radius:
                p = p + alpha * d
                r = r + alpha * Hd
                if np.linalg.norm(r) <= tolerance * np.linalg.norm(g):
                    return p, k
                z = precondition(r)
                rz, rz_old = r @ z, rz
                d = -z + (rz / rz_old) * d
                continue
        # Negative curvature or the boundary: go to the boundary along d.
        a, b, c = d @ d, 2. * (p @ d), p @ p - radius ** 2
        return p + (-b + np.sqrt(b * b - 4. * a * c)) / (2. * a) * d, k
    return p, k


def newton(model, u, t, variant, max_iterations):
    """One load step; returns (state, iterations, converged)."""
    u = predictor(model, u, t, 'laplace' if variant == 'laplace' else
                  'tangent')
    f = model.free
    r0 = np.linalg.norm(model.gradient(u)[f])
    radius = np.linalg.norm(u)
    for it in range(2, max_iterations + 1):
        g = model.gradient(u)[f]
        r = np.linalg.norm(g)
        if r < 1e-10:
            return u, it - 1, True
        e0 = model.energy(u)
        d = np.zeros(model.ndof)
        if variant == 'trust region':
            H = model.hessian(u)[f][:, f].tocsr()
            lu = spla.splu((model.hessian(u, 'all')[f][:, f] +
                            1e-12 * sp.eye(len(f))).tocsc())
            p, _ = steihaug(H, g, radius, lu.solve, min(1e-8, np.sqrt(r)))
            predicted = -(g @ p + 0.5 * p @ (H @ p))
            d[f] = p
            rho = (e0 - model.energy(u + d)) / predicted
            if rho < 0.25:
                radius = 0.25 * np.linalg.norm(p)
            elif rho > 0.75 and np.linalg.norm(p) >= 0.99 * radius:
                radius *= 2.
            if rho > 1e-4:
                u = u + d
            continue
        H = model.hessian(u, 'inverted' if r > 1e-3 * r0 else 'none')
        d[f] = solve_free(model, H, -g)
        slope = g @ d[f]
        if slope >= 0.:
            d[f] = solve_free(model, model.hessian(u, 'all'), -g)
            slope = g @ d[f]
        alpha = 1.
        if variant == 'exact search':
            alpha = minimize_scalar(lambda a: model.energy(u + a * d),
                                    bounds=(0., 2.), method='bounded',
                                    options={'xatol': 1e-3}).x
        while model.energy(u + alpha * d) > e0 + 1e-4 * alpha * slope + 1e-14:
            alpha = 0.5 * alpha if alpha <= 1. else 1.
        u = u + alpha * d
    converged = np.linalg.norm(model.gradient(u)[f]) < 1e-10
    return u, max_iterations, converged


def crush(model, variant, max_iterations, smallest=1e-3):
    """The adaptive load stepping to t = 1, then one unloading step to 0."""
    u, t, dt = np.zeros(model.ndof), 0., 1.
    row = {"completed": 0, "load_steps": 0, "newton_iterations": 0,
           "largest_per_step": 0, "smallest_increment": 1., "last_t": 0.}
    while t < 1. - 1e-12:
        dt = min(dt, 1. - t)
        trial, its, ok = newton(model, u, t + dt, variant, max_iterations)
        row["newton_iterations"] += its
        if not ok:
            dt *= 0.5
            if dt < smallest:
                return row
            continue
        t, u = t + dt, trial
        row["load_steps"] += 1
        row["largest_per_step"] = max(row["largest_per_step"], its)
        row["smallest_increment"] = min(row["smallest_increment"], dt)
        row["last_t"] = t
        if its < 8:
            dt = min(1., 2. * dt)
    row["completed"] = 1
    row["energy"] = model.energy(u)
    row["min_J"] = model.min_J(u)
    back, its, ok = newton(model, u, 0., variant, max_iterations)
    row["unload_iterations"] = its if ok else -1
    row["unload_max_u"] = np.abs(back).max() if ok else float('nan')
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    cases = [("one step, 100 iterations", 6, 0.4, 0.9, v, 100)
             for v in ("line search", "exact search", "trust region",
                       "laplace")]
    cases += [("defaults", 6, 0.4, 0.9, v, 20)
              for v in ("line search", "trust region", "laplace")]
    if not args.quick:
        cases += [("neighbours", n, nu, c, v, 20)
                  for n, nu, c in ((4, 0.4, 0.9), (8, 0.4, 0.9),
                                   (6, 0.3, 0.9), (6, 0.45, 0.9),
                                   (6, 0.4, 0.8), (6, 0.4, 0.95))
                  for v in ("line search", "laplace")]
    columns = ["group", "n", "nu", "compression", "variant",
               "max_iterations", "completed", "load_steps",
               "newton_iterations", "largest_per_step", "smallest_increment",
               "last_t", "energy", "min_J", "unload_iterations",
               "unload_max_u"]
    rows = []
    for group, n, nu, c, variant, max_its in cases:
        model = Crush(n, nu, c)
        if max_its == 100:
            u, its, ok = newton(model, np.zeros(model.ndof), 1., variant, 100)
            row = {"completed": int(ok), "load_steps": 1,
                   "newton_iterations": its, "largest_per_step": its,
                   "smallest_increment": 1., "last_t": 1. if ok else 0.,
                   "energy": model.energy(u), "min_J": model.min_J(u)}
        else:
            row = crush(model, variant, max_its)
        row.update(group=group, n=n, nu=nu, compression=c, variant=variant,
                   max_iterations=max_its)
        rows.append(row)
        print(", ".join("%s=%s" % (k, row.get(k, "")) for k in columns),
              flush=True)
    name = "newton_model_quick.csv" if args.quick else "newton_model.csv"
    with open(os.path.join(HERE, name), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns, restval="")
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()

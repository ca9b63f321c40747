#!/usr/bin/env python3
"""Cook's membrane: the volumetric-locking sweep redone with the mixed
displacement-pressure elements (issue 14).

For nu = 0.3 ... 0.4999 and 0.5 (bulk modulus 'inf'), mu = 80.194 N/mm^2,
decoupled neo-Hookean, 100 N shear load: uy(48, 60) of each mixed element on
the 2D mesh N = 16 and the 3D mesh N = 8, as a fraction of P2/P1 on the
finest mesh run at the same nu (2D: N = 32; 3D: N = 16 with --full, else
N = 8). Iterative solver (GMRES with the block preconditioner).
Writes benchmarks/cook_locking_mixed.csv and prints the table.

  /usr/bin/python3 benchmarks/cook_locking_mixed.py [--full] [--quick]
"""
import csv
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
BINARY = os.path.join(ROOT, "build", "hyperelastic")
MPIRUN = os.path.join(ROOT, "scripts", "mpirun.sh")
CSV = os.path.join(HERE, "cook_locking_mixed.csv")
MU = 80.194
ELEMENTS = ["P1-bubble/P1", "P1/P1 stabilized", "P2/P1"]


def scene(dim, n, element, nu, out):
    if nu == 0.5:
        constants = ("  set Elastic constants = shear and bulk modulus\n"
                     f"  set Shear modulus = {MU}\n  set Bulk modulus = inf\n")
    else:
        lam = 2 * MU * nu / (1 - 2 * nu)
        constants = ("  set Elastic constants = Lame\n"
                     f"  set Shear modulus = {MU}\n  set Lame lambda = {lam!r}\n")
    three = dim == 3
    return f"""subsection Problem
  set Dimension = {dim}
  set Formulation = mixed
  set Mixed element = {element}
end
subsection Mesh
  set Source = file
  set File = {ROOT}/meshes/cook_{dim}d_{n}.msh
end
subsection Material
  set Model = decoupled neo-Hookean
{constants}end
subsection Loading
  set Number of load steps = 10
  set Constants = q = 6.25
end
subsection Dirichlet 1
  set Boundary id = 1
  set Components = {'x, y, z' if three else 'x, y'}
  set Displacement = {'0; 0; 0' if three else '0; 0'}
end
subsection Traction 1
  set Boundary id = 2
  set Traction = {'0; q*t; 0' if three else '0; q*t'}
end
subsection Output
  set Directory = {out}
  set Base name = cook
  set Write VTU = false
  set Points = {'48, 60, 0' if three else '48, 60'}
end
"""


def run(dim, n, element, nu):
    with tempfile.TemporaryDirectory() as tmp:
        prm = os.path.join(tmp, "cook.prm")
        with open(prm, "w") as f:
            f.write(scene(dim, n, element, nu, tmp))
        subprocess.run(["bash", MPIRUN, "-np", "2", BINARY, prm], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(os.path.join(tmp, "cook.csv")) as f:
            rows = list(csv.DictReader(f))
    newton = sum(int(r["newton_iterations"]) for r in rows)
    krylov = sum(int(r["linear_iterations"]) for r in rows)
    return float(rows[-1]["point1_uy"]), krylov / newton


def main():
    quick = "--quick" in sys.argv
    full = "--full" in sys.argv
    nus = [0.3, 0.4999, 0.5] if quick else [0.3, 0.4, 0.45, 0.49, 0.499, 0.4999, 0.5]
    cases = [(2, 16, 32), (3, 8, 16 if full else 8)]
    if quick:
        cases = [(2, 8, 16)]
    rows = []
    for dim, n, n_ref in cases:
        for nu in nus:
            ref, _ = run(dim, n_ref, "P2/P1", nu)
            for element in ELEMENTS:
                uy, its = run(dim, n, element, nu)
                rows.append({"dim": dim, "N": n, "element": element, "nu": nu,
                             "uy": uy, "reference_N": n_ref, "reference_uy": ref,
                             "ratio": uy / ref, "krylov_per_newton": its})
                print(f"{dim}D N={n} {element:18s} nu={nu:<7} uy={uy:.4f} "
                      f"ref={ref:.4f} ratio={uy / ref:.4f} its/Newton={its:.1f}",
                      flush=True)
    if not quick:
        with open(CSV, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Implicit dynamics benchmark: run time per simulated second against the
trajectory error of a swinging cantilever's tip, for backward Euler,
Newmark and implicit midpoint at several time steps, full Newton against one
linearised solve per step, and stiffness warping against the corotational and
neo-Hookean models.

Scene: the bar [0,4] x [0,0.5] x [0,0.5] of 16 x 2 x 2 boxes (5 tetrahedra
each), neo-Hookean E = 1, nu = 0.3, density 1, clamped at x = 0, released
from rest under the body force 0; 0; -0.002 (parameters/
swinging_cantilever_3d.prm on a shorter time), until t = 32; the
corotational and stiffness-warping rows use the same elastic constants.
Reference of each model: implicit midpoint with h = 0.0625 and that model.
Error (tip_error): the largest distance between the tip (point (4, 0.25,
0.25)) and the reference tip of the same model over the times t = 2, 4, ...,
32 (every run passes through them); model_difference: the same distance to
the neo-Hookean reference (the model's own difference plus its time error). Time: the whole process (2 MPI ranks, start-up included) divided by
the simulated time.

  /usr/bin/python3 benchmarks/dynamics/run.py          # runs (~5 min), CSV + PNG here
  /usr/bin/python3 benchmarks/dynamics/run.py --plot   # redraw from the CSV

Needs build/hyperelastic (Release) and python3-matplotlib.
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
EXE = os.path.join(ROOT, "build", "hyperelastic")
MPIRUN = os.path.join(ROOT, "scripts", "mpirun.sh")
SCRATCH = "/tmp/dynamics_bench"
END = 32.0
SCHEMES = ["backward Euler", "Newmark", "implicit midpoint"]
MODELS = ["neo-Hookean", "corotational", "stiffness warping"]
# (label, scheme, one linearised solve per step, model)
METHODS = [(s, s, False, "neo-Hookean") for s in SCHEMES] + [
    ("Newmark, linearized once", "Newmark", True, "neo-Hookean"),
    ("backward Euler, linearized once", "backward Euler", True, "neo-Hookean"),
    ("corotational, Newmark", "Newmark", False, "corotational"),
    ("corotational, Newmark linearized once", "Newmark", True, "corotational"),
    ("stiffness warping, Newmark", "Newmark", False, "stiffness warping"),
    ("stiffness warping, Newmark linearized once", "Newmark", True,
     "stiffness warping")]
STEPS = [2.0, 1.0, 0.5, 0.25]
REFERENCE = ("implicit midpoint", 0.0625)
CSV_FILE = os.path.join(HERE, "dynamics.csv")
PNG_FILE = os.path.join(HERE, "dynamics.png")


def scene(scheme, h, out_dir, once=False, model="neo-Hookean"):
    return f"""subsection Problem
  set Dimension = 3
end
subsection Mesh
  set Upper corner = 4, 0.5, 0.5
  set Subdivisions = 16, 2, 2
end
subsection Material
  set Model           = {model}
  set Young's modulus = 1
  set Poisson's ratio = 0.3
end
subsection Loading
  set Body force = 0; 0; -0.002
end
subsection Dirichlet 1
  set Boundary id  = 0
  set Components   = x, y, z
  set Displacement = 0; 0; 0
end
subsection Time integration
  set Scheme    = {scheme}
  set Density   = 1
  set Time step = {h!r}
  set End time  = {END!r}
  set Linearize once per step = {"true" if once else "false"}
end
subsection Output
  set Directory = {out_dir}
  set Base name = run
  set Write VTU = false
  set Verbose   = false
  set Points    = 4, 0.25, 0.25
end
"""


def run(scheme, h, once=False, model="neo-Hookean"):
    name = "%s_%s%s_h%g" % (model.replace(" ", "_"), scheme.replace(" ", "_"),
                            "_once" if once else "", h)
    out_dir = os.path.join(SCRATCH, name)
    os.makedirs(out_dir, exist_ok=True)
    prm = os.path.join(SCRATCH, name + ".prm")
    with open(prm, "w") as f:
        f.write(scene(scheme, h, out_dir, once, model))
    start = time.monotonic()
    result = subprocess.run(["bash", MPIRUN, "-np", "2", EXE, prm],
                            capture_output=True, text=True)
    wall = time.monotonic() - start
    if result.returncode != 0:
        sys.exit("%s failed:\n%s" % (name, result.stdout[-2000:] + result.stderr[-2000:]))
    rows = list(csv.DictReader(open(os.path.join(out_dir, "run.csv"))))
    tip = {round(float(r["load_factor"]), 9): tuple(float(r["point1_u" + a]) for a in "xyz")
           for r in rows}
    newton = sum(int(r["newton_iterations"]) for r in rows)
    return dict(scheme=scheme, h=h, wall=wall, steps=len(rows), newton=newton, tip=tip)


def error(run_result, reference):
    worst = 0.0
    for k in range(1, int(END / 2) + 1):
        t = round(2.0 * k, 9)
        a, b = run_result["tip"][t], reference["tip"][t]
        worst = max(worst, math.dist(a, b))
    return worst


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = list(csv.DictReader(open(CSV_FILE)))
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for (label, _, _, _), marker in zip(METHODS, "osd^v<>ph"):
        pts = [(float(r["seconds_per_simulated_second"]), float(r["tip_error"]),
                float(r["time_step"])) for r in rows if r["method"] == label]
        if not pts:
            continue
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker=marker, label=label)
        for x, y, h in pts:
            ax.annotate("h=%g" % h, (x, y), fontsize=7, xytext=(3, 3),
                        textcoords="offset points")
    ax.set_xlabel("wall seconds per simulated second (2 ranks, whole process)")
    ax.set_ylabel("max tip distance to the model's reference, t = 2 .. 32")
    ax.set_title("Swinging cantilever (459 unknowns)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(PNG_FILE, dpi=120)
    print("wrote", PNG_FILE)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--plot", action="store_true", help="only redraw the figure")
    args = parser.parse_args()
    if args.plot:
        plot()
        return
    if not os.path.exists(EXE):
        sys.exit("missing %s (build first: scripts/build.sh)" % EXE)
    references = {m: run(REFERENCE[0], REFERENCE[1], False, m) for m in MODELS}
    rows = []
    for label, scheme, once, model in METHODS:
        for h in STEPS:
            r = run(scheme, h, once, model)
            e = error(r, references[model])
            rows.append(dict(method=label, model=model, time_step=h, steps=r["steps"],
                             newton_iterations=r["newton"],
                             newton_per_step="%.2f" % (r["newton"] / r["steps"]),
                             wall_s="%.3f" % r["wall"],
                             seconds_per_simulated_second="%.4f" % (r["wall"] / END),
                             tip_error="%.3e" % e,
                             model_difference="%.3e" % error(r, references["neo-Hookean"])))
            print("%-44s h = %-6g %4d steps %5.2f Newton/step %7.2f s  error %.3e"
                  % (label, h, r["steps"], r["newton"] / r["steps"], r["wall"], e))
    with open(CSV_FILE, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    for m, ref in references.items():
        print("reference %s: %s h = %g, %.1f s" % (m, REFERENCE[0], REFERENCE[1], ref["wall"]))
    try:
        plot()
    except ImportError:
        print("matplotlib missing: no plot")


if __name__ == "__main__":
    main()

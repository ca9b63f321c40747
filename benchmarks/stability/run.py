#!/usr/bin/python3
"""Benchmark of the stability round (issue 28): Newton's tangent policies on
the extreme crush, and load control against arc length at limit points.

  crush      the cube of stress test 25 (6 x 6 x 6 boxes, E = 1, nu = 0.4,
             clamped top and bottom, the top pushed down to 10 % of the
             height in one nominal load step), stable neo-Hookean for each
             'Newton/Tangent' (exact; projected; exact, projected on
             failure; automatic) with 'Newton/Max iterations' 20 (the
             default), 50 and 100, and corotational with 20:
             whether it completes, load steps, Newton iterations (total and
             largest per step), cut-backs, the last converged t, wall time;
  crush path the same crush by arc length ('Number of load steps' 20, 80
             steps): t and 'stability' per step, which show where the
             displacement-controlled path folds;
  bar        the St. Venant-Kirchhoff bar of parameters/limit_point_bar_2d.prm
             under load control (to its stop at the maximum) and by arc
             length (24 steps): steps, Newton iterations, the largest t,
             wall time.
  arch       parameters/snap_through_arch_2d.prm and _3d.prm under load
             control (10 load steps) and by arc length: the same columns,
             the load factor at the first maximum, the crown's largest
             downward displacement.

Writes crush.csv, crush_path.csv, bar.csv, arch.csv and stability.png here.

  /usr/bin/python3 benchmarks/stability/run.py          # everything (~3 min)
  /usr/bin/python3 benchmarks/stability/run.py --plot   # redraw from the CSVs
"""
import argparse
import csv
import os
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
EXE = os.path.join(ROOT, "build", "hyperelastic")
OUT = os.path.join(HERE, "out")

CRUSH = """
subsection Problem
  set Dimension = 3
end
subsection Mesh
  set Upper corner = 1, 1, 1
  set Subdivisions = 6, 6, 6
end
subsection Material
  set Model = stable neo-Hookean
  set Young's modulus = 1
  set Poisson's ratio = 0.4
end
subsection Loading
  set Number of load steps = {steps}
end
subsection Load stepping
  set Method = {method}
  set Maximum steps = 80
end
subsection Dirichlet 1
  set Boundary id = 4
  set Components = x, y, z
  set Displacement = 0; 0; 0
end
subsection Dirichlet 2
  set Boundary id = 5
  set Components = x, y, z
  set Displacement = 0; 0; -0.9*t
end
subsection Newton
  set Tangent = {tangent}
  set Max iterations = {iterations}
end
subsection Output
  set Write VTU = false
  set Directory = {out}
  set Base name = {name}
end
"""


def run(name, text):
    """Runs a scene on 1 rank; returns (exit code, wall time, CSV rows)."""
    os.makedirs(OUT, exist_ok=True)
    scene = os.path.join(OUT, name + ".prm")
    with open(scene, "w") as f:
        f.write(text)
    start = time.time()
    code = subprocess.run([EXE, scene], stdout=subprocess.DEVNULL,
                          stderr=subprocess.DEVNULL).returncode
    wall = time.time() - start
    rows = []
    path = os.path.join(OUT, name + ".csv")
    if os.path.exists(path):
        with open(path) as f:
            rows = list(csv.DictReader(f))
    return code, wall, rows


def crush():
    table = []
    cases = [("stable neo-Hookean", tangent, iterations)
             for tangent in ("exact", "projected",
                             "exact, projected on failure", "automatic")
             for iterations in (20, 50, 100)]
    cases += [("corotational", tangent, 20)
              for tangent in ("exact, projected on failure", "automatic")]
    for model, tangent, iterations in cases:
        name = "crush_%s_%s_%d" % (model.split()[0],
                                   tangent.split(",")[0], iterations)
        if "failure" in tangent:
            name = "crush_%s_fallback_%d" % (model.split()[0], iterations)
        code, wall, rows = run(name, CRUSH.format(
            steps=1, method="load control", tangent=tangent,
            iterations=iterations, out=OUT,
            name=name).replace("stable neo-Hookean", model))
        its = [int(r["newton_iterations"]) for r in rows]
        table.append({
            "model": model,
            "tangent": tangent, "max_iterations": iterations,
            "completed": int(code == 0), "load_steps": len(rows),
            "newton_iterations": sum(its),
            "largest_per_step": max(its) if its else 0,
            "cut_backs": sum(int(r["cut_backs"]) for r in rows),
            "last_t": float(rows[-1]["load_factor"]) if rows else 0.,
            "wall_s": round(wall, 2)})
        print(table[-1])
    write(os.path.join(HERE, "crush.csv"), table)
    code, wall, rows = run("crush_path", CRUSH.format(
        steps=20, method="arc length",
        tangent="exact, projected on failure", iterations=20, out=OUT,
        name="crush_path"))
    path = [{"step": r["step"], "t": r["load_factor"],
             "newton_iterations": r["newton_iterations"],
             "stability": r["stability"], "min_J": r["min_J"]} for r in rows]
    write(os.path.join(HERE, "crush_path.csv"), path)


def bar():
    with open(os.path.join(ROOT, "parameters", "limit_point_bar_2d.prm")) as f:
        base = f.read().replace("set Directory = output",
                                "set Directory = " + OUT)
    table = []
    for method in ("load control", "arc length"):
        name = "bar_" + method.replace(" ", "_")
        text = base.replace("set Method        = arc length",
                            "set Method = " + method)
        text = text.replace("set Base name = limit_point_bar",
                            "set Base name = " + name)
        code, wall, rows = run(name, text)
        table.append({
            "method": method, "completed": int(code == 0),
            "steps": len(rows),
            "newton_iterations":
                sum(int(r["newton_iterations"]) for r in rows),
            "largest_t": max(float(r["load_factor"]) for r in rows),
            "smallest_stretch":
                min(float(r["deformed_max_x"]) / 2. for r in rows),
            "wall_s": round(wall, 2)})
        print(table[-1])
    write(os.path.join(HERE, "bar.csv"), table)


def arch():
    table = []
    for dim in (2, 3):
        scene = os.path.join(ROOT, "parameters", "snap_through_arch_%dd.prm" % dim)
        with open(scene) as f:
            base = f.read().replace("set Directory = output",
                                    "set Directory = " + OUT)
        base = base.replace("../meshes/", os.path.join(ROOT, "meshes") + "/")
        for method in ("load control", "arc length"):
            name = "arch_%dd_%s" % (dim, method.replace(" ", "_"))
            text = base.replace("set Method        = arc length",
                                "set Method = " + method)
            text = text.replace("set Base name = snap_through_arch_%dd" % dim,
                                "set Base name = " + name)
            if method == "load control":
                text = text.replace("set Number of load steps = 2",
                                    "set Number of load steps = 10")
            code, wall, rows = run(name, text)
            t = [float(r["load_factor"]) for r in rows]
            first = 0
            while first + 1 < len(t) and t[first + 1] >= t[first]:
                first += 1
            table.append({
                "dim": dim, "method": method, "completed": int(code == 0),
                "steps": len(rows),
                "newton_iterations":
                    sum(int(r["newton_iterations"]) for r in rows),
                "first_maximum_t": t[first] if t else 0.,
                "last_t": t[-1] if t else 0.,
                "crown_uy_lowest":
                    min(float(r["point1_uy"]) for r in rows) if rows else 0.,
                "wall_s": round(wall, 2)})
            print(table[-1])
            if dim == 2 and method == "arc length":
                write(os.path.join(HERE, "arch_path.csv"),
                      [{"step": r["step"], "t": r["load_factor"],
                        "crown_uy": r["point1_uy"],
                        "stability": r["stability"]} for r in rows])
    write(os.path.join(HERE, "arch.csv"), table)


FAMILY = [(6, 0.4, 0.9), (4, 0.4, 0.9), (8, 0.4, 0.9), (6, 0.3, 0.9),
          (6, 0.45, 0.9), (6, 0.4, 0.8), (6, 0.4, 0.95)]


def family(csv_name, iterations=20, default_only=False):
    """The crush of stress test 25 and its 6 neighbours (boxes, Poisson's
    ratio, crushed by), stable neo-Hookean with the default Newton
    settings (automatic tangent, 20 iterations), and with negative
    curvature followed in a trust region (automatic and exact tangent)."""
    table = []
    policies = [("automatic", "false"), ("automatic", "true"),
                ("exact", "true")]
    if default_only:
        policies = policies[:1]
    for (n, nu, c), (tangent, follow) in [(f, p) for p in policies
                                          for f in FAMILY]:
        name = "family_%d_%g_%g_%s_%s_%d" % (n, nu, c, tangent, follow,
                                              iterations)
        text = CRUSH.format(steps=1, method="load control",
                            tangent=tangent, iterations=iterations, out=OUT,
                            name=name)
        text = text.replace("  set Max iterations = %d" % iterations,
                            "  set Max iterations = %d\n"
                            "  set Follow negative curvature = %s"
                            % (iterations, follow))
        text = text.replace("Subdivisions = 6, 6, 6",
                            "Subdivisions = %d, %d, %d" % (n, n, n))
        text = text.replace("Poisson's ratio = 0.4",
                            "Poisson's ratio = %g" % nu)
        text = text.replace("-0.9*t", "-%g*t" % c)
        code, wall, rows = run(name, text)
        its = [int(r["newton_iterations"]) for r in rows]
        steps = [float(r["load_increment"]) for r in rows]
        table.append({
            "tangent": tangent, "follow_negative_curvature": follow,
            "max_iterations": iterations,
            "boxes": n, "nu": nu, "crushed_to": round(1. - c, 3),
            "completed": int(code == 0), "load_steps": len(rows),
            "newton_iterations": sum(its),
            "largest_per_step": max(its) if its else 0,
            "smallest_increment": min(steps) if steps else 0.,
            "cut_backs": sum(int(r["cut_backs"]) for r in rows),
            "last_t": float(rows[-1]["load_factor"]) if rows else 0.,
            "wall_s": round(wall, 2)})
        print(table[-1], flush=True)
    write(os.path.join(HERE, csv_name), table)


ARCH_PLATE = """
subsection Problem
  set Dimension = 2
end
subsection Mesh
  set Source = file
  set File   = {mesh}
end
subsection Material
  set Model           = neo-Hookean
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Loading
  set Number of load steps = {steps}
end
subsection Linear solver
  set Type = {solver}
end
subsection Newton
  set Follow negative curvature = {follow}
end
subsection Dirichlet 1
  set Boundary id  = 1
  set Components   = x, y
  set Displacement = 0; 0
end
subsection Dirichlet 2
  set Boundary id  = 2
  set Components   = x, y
  set Displacement = 0; 0
end
subsection Contact
  subsection Obstacle 1
    set Type   = plane
    set Point  = 0, 0.211
    set Normal = 0, -1
    set Motion = 0; -{travel}*t
  end
end
subsection Output
  set Write VTU = false
  set Directory = {out}
  set Base name = {name}
  set Points    = 0, 0.21
end
"""


def arch_plate():
    """The shallow arch of meshes/arch_2d.msh (rise 0.2, top of the crown
    at 0.21) pressed by a rigid plate: to half its height (0.105) in 10
    nominal steps (tests/stability.cc case arch_plate) and to 86 % (0.18)
    in 6, with the direct solver, CG, and CG with negative curvature
    followed. Writes every accepted step (plate travel, crown deflection,
    plate force, Newton iterations)."""
    summary, curves = [], []
    for travel, steps in ((0.105, 10), (0.18, 6)):
        for solver, follow in (("direct", "false"), ("CG with AMG", "false"),
                               ("CG with AMG", "true")):
            name = "arch_plate_%g_%s_%s" % (travel, solver.split()[0], follow)
            code, wall, rows = run(name, ARCH_PLATE.format(
                mesh=os.path.join(ROOT, "meshes", "arch_2d.msh"),
                steps=steps, solver=solver, follow=follow, travel=travel,
                out=OUT, name=name))
            its = [int(r["newton_iterations"]) for r in rows]
            force = [-float(r["contact_force_1_y"]) for r in rows]
            summary.append({
                "plate_travel": travel, "nominal_steps": steps,
                "solver": solver, "follow_negative_curvature": follow,
                "completed": int(code == 0), "steps": len(rows),
                "newton_iterations": sum(its),
                "largest_per_step": max(its) if its else 0,
                "smallest_increment_over_nominal": round(
                    min(float(r["load_increment"]) for r in rows) * steps,
                    5) if rows else 0.,
                "last_t": float(rows[-1]["load_factor"]) if rows else 0.,
                "largest_force": max(force) if force else 0.,
                "final_force": force[-1] if force else 0.,
                "wall_s": round(wall, 2)})
            print(summary[-1], flush=True)
            for r in rows:
                curves.append({
                    "plate_travel": travel, "solver": solver,
                    "follow_negative_curvature": follow, "step": r["step"],
                    "t": r["load_factor"],
                    "plate": travel * float(r["load_factor"]),
                    "crown_uy": r["point1_uy"],
                    "plate_force": -float(r["contact_force_1_y"]),
                    "newton_iterations": r["newton_iterations"],
                    "increment": r["load_increment"]})
    write(os.path.join(HERE, "arch_plate.csv"), summary)
    write(os.path.join(HERE, "arch_plate_curve.csv"), curves)


def write(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(os.path.join(HERE, "crush_path.csv")) as f:
        path = list(csv.DictReader(f))
    steps = [int(r["step"]) for r in path]
    fig, (a, b, c) = plt.subplots(1, 3, figsize=(16, 4))
    a.plot(steps, [float(r["t"]) for r in path], "o-", ms=3)
    a.axhline(1., color="grey", lw=0.5)
    a.set_xlabel("arc-length step")
    a.set_ylabel("load factor t (top pushed down by 0.9 t)")
    a.set_title("crush path by arc length: folds of t")
    b.plot(steps, [float(r["stability"]) for r in path], "o-", ms=3)
    b.axhline(0., color="grey", lw=0.5)
    b.set_xlabel("arc-length step")
    b.set_ylabel("stability (stiffness along the path / unloaded)")
    b.set_title("stability: zero at each fold")
    with open(os.path.join(HERE, "arch_path.csv")) as f:
        arch_path = list(csv.DictReader(f))
    c.plot([-float(r["crown_uy"]) for r in arch_path],
           [float(r["t"]) for r in arch_path], "o-", ms=3)
    c.set_xlabel("crown deflection (downwards)")
    c.set_ylabel("load factor t (crown load 0.03 t)")
    c.set_title("2D arch by arc length: snap-through")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "stability.png"), dpi=110)


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--plot", action="store_true")
    parser.add_argument("--family", metavar="CSV",
                        help="only the crush family, written to CSV")
    parser.add_argument("--iterations", type=int, default=20,
                        help="the crush family's Newton/Max iterations")
    parser.add_argument("--default-only", action="store_true",
                        help="the crush family with the default policy only")
    parser.add_argument("--arch-plate", action="store_true",
                        help="only the arch pressed by a plate")
    args = parser.parse_args()
    if args.arch_plate:
        arch_plate()
    elif args.family:
        family(args.family, args.iterations, args.default_only)
    elif not args.plot:
        crush()
        bar()
        arch()
    if not args.family and not args.arch_plate:
        plot()

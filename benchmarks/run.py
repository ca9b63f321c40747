#!/usr/bin/python3
"""Benchmark of run time against error for hyperelastic (P1, 3D).

Runs build/hyperelastic_benchmark for the homogeneous bar (exact answer known),
the twisted bar under gravity, and the same twist on gmsh meshes read from
files (generated once into build/benchmark_meshes/, needs gmsh) at increasing
resolution, on 1 and 2 MPI ranks, writes benchmarks/results.csv and draws the
figures from it.

  python3 benchmarks/run.py            # run everything, then plot (~15 min)
  python3 benchmarks/run.py --plot     # redraw the figures from results.csv
  python3 benchmarks/run.py --quick    # small sizes only (a smoke run)
  python3 benchmarks/run.py --scenes twist_file   # run only these scenes and
                                       # replace their rows in results.csv
  python3 benchmarks/run.py --degrees  # P1 against P2 on the manufactured
                                       # solution: degrees.csv and
                                       # work_precision_degree.png (~10 min)

The twisted bar has no closed-form answer: its error is the relative error of
the total potential energy against a Richardson extrapolation from the three
finest meshes (P1 energies converge like h^2); the gmsh meshes are not nested,
so their error is taken against the same extrapolated energy.
"""
import argparse
import csv
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
EXE = os.path.join(ROOT, "build", "hyperelastic_benchmark")
MPIRUN = os.path.join(ROOT, "scripts", "mpirun.sh")
CSV = os.path.join(HERE, "results.csv")
DEGREES_CSV = os.path.join(HERE, "degrees.csv")
# Manufactured solution (unit cube, n x n x n boxes), per degree; each list
# ends near 1e5 unknowns.
DEGREE_SIZES = {1: [4, 6, 8, 11, 16, 22, 32], 2: [2, 3, 4, 6, 8, 11, 16]}
QUICK_DEGREE_SIZES = {1: [4, 6], 2: [2, 3]}

# Cells across the bar's width: 4n x n x n boxes, 3 (4n+1)(n+1)^2 unknowns,
# from about 1e4 to 1e6.
SIZES = [8, 11, 16, 22, 32, 44]
QUICK_SIZES = [6, 8, 11]
TWO_RANK_MIN_N = 22  # 2 ranks from about 1.4e5 unknowns on
# The twist on gmsh meshes (mesh_input/bar_big.geo, L = 4, h = 1/n): about
# 19 n^3 tetrahedra, from 1.9e4 to 1.2e6 cells.
FILE_SIZES = [10, 14, 20, 28, 40]
QUICK_FILE_SIZES = [6, 8]
FILE_TWO_RANK_MIN_N = 20
GEO = os.path.join(HERE, "mesh_input", "bar_big.geo")
MESH_DIR = os.path.join(ROOT, "build", "benchmark_meshes")


def twist_mesh(n):
    """The gmsh file of the twist_file scene with h = 1/n (made once)."""
    path = os.path.join(MESH_DIR, f"twist_bar_{n}.msh")
    if not os.path.exists(path):
        os.makedirs(MESH_DIR, exist_ok=True)
        subprocess.run(["gmsh", "-3", "-format", "msh41", "-setnumber", "h", repr(1.0 / n),
                        "-setnumber", "L", "4", GEO, "-o", path],
                       check=True, capture_output=True)
    return path


def run_one(scene, n, ranks, degree=1):
    command = [MPIRUN, "-np", str(ranks), EXE, scene, str(n), str(degree)]
    if scene == "twist_file":
        command.append("Mesh/File=" + twist_mesh(n))
    out = subprocess.run(command, capture_output=True, text=True, cwd=HERE)
    if out.returncode != 0:
        sys.exit("benchmark failed: " + " ".join(command) + "\n" + out.stdout + out.stderr)
    return out.stdout.strip().splitlines()[-1]


def header():
    out = subprocess.run([EXE, "--header"], capture_output=True, text=True, check=True)
    return out.stdout.strip()


def richardson_twist_errors(rows):
    """Relative energy error of each twist row against the extrapolated limit."""
    twist = sorted({int(r["n"]): float(r["energy"]) for r in rows if r["scene"] == "twist"}.items())
    if len(twist) < 3:
        return
    (n1, e1), (n2, e2), (n3, e3) = twist[-3:]
    # E(h) = E* + C h^p with h = 1/n: the order from three meshes (solved by
    # bisection; the ratios of h are not constant), then E*.
    def mismatch(p):
        a = (e1 - e2) / (n1 ** -p - n2 ** -p)
        b = (e2 - e3) / (n2 ** -p - n3 ** -p)
        return a - b

    lo, hi = 0.5, 4.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mismatch(lo) * mismatch(mid) <= 0:
            hi = mid
        else:
            lo = mid
    p = 0.5 * (lo + hi)
    c = (e2 - e3) / (n2 ** -p - n3 ** -p)
    limit = e3 - c * n3 ** -p
    print(f"twist: energy order {p:.3f}, extrapolated energy {limit:.12g}")
    for r in rows:
        if r["scene"] in ("twist", "twist_file"):
            r["error"] = f"{abs(float(r['energy']) - limit) / abs(limit):.6g}"


def pyplot():
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("plotting needs matplotlib: apt-get install python3-matplotlib")
    return plt


def finish(fig, ax, xlabel, ylabel, title, file_name):
    """Labels, grid and legend; saves the figure next to this script."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, file_name), dpi=110)


SCENES = ("bar", "twist", "twist_file")
SCENE_MARKERS = (("bar", "o"), ("twist", "s"), ("twist_file", "^"))


def plot(rows):
    plt = pyplot()

    def series(scene, ranks):
        s = [r for r in rows if r["scene"] == scene and int(r["ranks"]) == ranks]
        return sorted(s, key=lambda r: int(r["dofs"]))

    fig, ax = plt.subplots(figsize=(6, 4.5))
    for scene, marker in SCENE_MARKERS:
        for ranks in (1, 2):
            s = [r for r in series(scene, ranks) if float(r["error"]) > 0]
            if s:
                ax.loglog([float(r["error"]) for r in s], [float(r["t_total"]) for r in s],
                          marker=marker, linestyle="-" if ranks == 1 else "--",
                          label=f"{scene}, {ranks} rank{'s' if ranks > 1 else ''}")
    finish(fig, ax, "relative error (bar: max nodal displacement; twist: energy)", "wall time [s]", "Work-precision, P1 neo-Hookean, 3D", "work_precision.png")

    fig, ax = plt.subplots(figsize=(6, 4.5))
    for scene, marker in SCENE_MARKERS:
        for ranks in (1, 2):
            s = series(scene, ranks)
            if s:
                ax.loglog([int(r["dofs"]) for r in s],
                          [1e6 * float(r["t_total"]) / int(r["dofs"]) for r in s],
                          marker=marker, linestyle="-" if ranks == 1 else "--",
                          label=f"{scene}, {ranks} rank{'s' if ranks > 1 else ''}")
    finish(fig, ax, "unknowns", "wall time per unknown [µs]", "Time per unknown (whole run)", "time_per_dof.png")

    fig, ax = plt.subplots(figsize=(6, 4.5))
    for scene, marker in SCENE_MARKERS:
        one = {int(r["n"]): r for r in series(scene, 1)}
        two = {int(r["n"]): r for r in series(scene, 2)}
        common = sorted(set(one) & set(two))
        if common:
            ax.semilogx([int(one[n]["dofs"]) for n in common],
                        [float(one[n]["t_total"]) / float(two[n]["t_total"]) for n in common],
                        marker=marker, label=scene)
    ax.axhline(1.7, color="gray", linestyle=":", label="target 1.7")
    finish(fig, ax, "unknowns", "speed-up, 2 ranks over 1", "1 versus 2 MPI ranks", "ranks.png")
    print("figures: benchmarks/work_precision.png, time_per_dof.png, ranks.png")


def plot_degrees(rows):
    """Wall time against the L2 and H1 errors of the manufactured solution."""
    plt = pyplot()

    fig, ax = plt.subplots(figsize=(6, 4.5))
    for degree, marker in ((1, "o"), (2, "s")):
        s = sorted((r for r in rows if int(r["degree"]) == degree), key=lambda r: int(r["dofs"]))
        for column, style, norm in (("error", "-", "L2"), ("error_h1", "--", "H1")):
            ax.loglog([float(r[column]) for r in s], [float(r["t_total"]) for r in s],
                      marker=marker, linestyle=style, label=f"P{degree}, {norm} error")
    finish(fig, ax, "relative error of the displacement", "wall time [s] (2 ranks)", "P1 against P2: manufactured solution, neo-Hookean, 3D", "work_precision_degree.png")
    print("figure: benchmarks/work_precision_degree.png")


def run_degrees(quick):
    sizes = QUICK_DEGREE_SIZES if quick else DEGREE_SIZES
    lines = [header()]
    for degree, ns in sizes.items():
        for n in ns:
            line = run_one("manufactured", n, 2, degree)
            print(line, flush=True)
            lines.append(line)
    with open(DEGREES_CSV, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("results: benchmarks/degrees.csv")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--plot", action="store_true", help="only redraw the figures")
    parser.add_argument("--quick", action="store_true", help="small sizes only")
    parser.add_argument("--degrees", action="store_true",
                        help="P1 against P2 on the manufactured solution")
    parser.add_argument("--scenes", nargs="+", choices=SCENES, default=list(SCENES),
                        help="run only these scenes; the other scenes' rows of "
                             "results.csv are kept")
    args = parser.parse_args()

    if args.degrees:
        if not args.plot:
            run_degrees(args.quick)
        with open(DEGREES_CSV) as f:
            plot_degrees(list(csv.DictReader(f)))
        return

    if not args.plot:
        if not os.path.exists(EXE):
            sys.exit("build first: scripts/build.sh (Release)")
        sizes = QUICK_SIZES if args.quick else SIZES
        file_sizes = QUICK_FILE_SIZES if args.quick else FILE_SIZES
        lines = [header()]
        for scene in args.scenes:
            two_rank_min = FILE_TWO_RANK_MIN_N if scene == "twist_file" else TWO_RANK_MIN_N
            for n in file_sizes if scene == "twist_file" else sizes:
                for ranks in (1, 2):
                    if ranks == 2 and n < two_rank_min and not args.quick:
                        continue
                    line = run_one(scene, n, ranks)
                    print(line, flush=True)
                    lines.append(line)
        rows = list(csv.DictReader(lines))
        if set(args.scenes) != set(SCENES) and os.path.exists(CSV):
            with open(CSV) as f:
                kept = [r for r in csv.DictReader(f) if r["scene"] not in args.scenes]
            rows = kept + rows
        richardson_twist_errors(rows)
        with open(CSV, "w", newline="") as f:
            fields = list(csv.DictReader(lines).fieldnames)
            writer = csv.DictWriter(f, fieldnames=fields, restval="")
            writer.writeheader()
            writer.writerows(rows)
        print("results: benchmarks/results.csv")
    with open(CSV) as f:
        rows = list(csv.DictReader(f))
    plot(rows)


if __name__ == "__main__":
    main()

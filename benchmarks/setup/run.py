#!/usr/bin/env python3
"""Set-up and preconditioner set-up: the two costs that are not Newton work
(issue 30). Two series, 1 and 2 ranks, one run per row:

  stages   the set-up alone (hyperelastic_benchmark --stages): wall time of
           each stage (read, order, check, build, partition, wait, describe,
           distribute, dofs, system, null space, operator, rest) for the
           gmsh bar of mesh_input/bar_big.geo (L = 4, h = 1/n, about 19 n^3
           tetrahedra) and for the generated box of the same bar (4n x n x n
           boxes, 24 n^3 tetrahedra), from 1e4 to 1.2e6 cells -> stages.csv
           (stages_before.csv: the same before one rank built a serial
           triangulation, kept for the comparison)
  twist    the twist of the gmsh bar (90 degrees, gravity) in ONE load step,
           the whole process: time per unknown, AMG set-ups per run and their
           share of the run, CG iterations per Newton step -> twist.csv
  p2       the P2 twist of the box bar (4n x n x n boxes) in one load step,
           its last tangent solved to 1e-8 with CG and ML on the P2 matrix
           against the two-level P2 -> P1 preconditioner (Chebyshev degree
           1, 2, 3; hyperelastic_benchmark --p2-preconditioner): set-up and
           solve time, iterations -> p2_preconditioner.csv; and the whole
           P2 twist (4 load steps) with each, 1 rank -> p2_twist.csv

  /usr/bin/python3 benchmarks/setup/run.py            # both (~15 min)
  /usr/bin/python3 benchmarks/setup/run.py --quick    # small sizes (~20 s)
  /usr/bin/python3 benchmarks/setup/run.py --plot     # redraw setup.png

Needs a Release build (scripts/build.sh) and gmsh for the meshes (made once
into build/benchmark_meshes/).
"""
import argparse
import csv
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
import run as main_benchmark  # noqa: E402  (twist_mesh, the gmsh files)

EXE = os.path.join(ROOT, "build", "hyperelastic_benchmark")
MPIRUN = os.path.join(ROOT, "scripts", "mpirun.sh")
STAGES = ["read", "order", "check", "build", "partition", "wait", "describe",
          "distribute", "dofs_setup", "system", "null_space", "operator",
          "rest"]

# gmsh bar h = 1/n: 1.9e4 ... 1.15e6 cells; box 4n x n x n: 1.2e4 ... 9.4e5.
FILE_SIZES = [10, 14, 20, 28, 40]
BOX_SIZES = [8, 12, 16, 24, 34]
TWIST_SIZES = [10, 14, 20, 28, 40]
P2_SIZES = [4, 8, 12]
QUICK = {"file": [6, 8], "box": [4, 6], "twist": [6, 8], "p2": [4]}


def command(ranks, args):
    return [MPIRUN, "-np", str(ranks), EXE] + args


def run_rows(ranks, args):
    """The CSV rows a benchmark run prints (after its progress lines)."""
    out = subprocess.run(command(ranks, args), capture_output=True, text=True,
                         cwd=HERE)
    if out.returncode != 0:
        sys.exit("failed: " + " ".join(command(ranks, args)) + "\n" +
                 out.stdout + out.stderr)
    return out.stdout.strip().splitlines()


def run_row(ranks, args):
    return run_rows(ranks, args)[-1]


def header(args):
    out = subprocess.run([EXE] + args + ["--header"], capture_output=True,
                         text=True, check=True)
    return out.stdout.strip().split(",")


def stages(quick):
    names = header(["--stages"])
    rows = []
    for scene, sizes in (("twist_file", QUICK["file"] if quick else FILE_SIZES),
                         ("twist", QUICK["box"] if quick else BOX_SIZES)):
        for n in sizes:
            for ranks in (1, 2):
                args = ["--stages", scene, str(n), "1"]
                if scene == "twist_file":
                    args.append("Mesh/File=" + main_benchmark.twist_mesh(n))
                row = dict(zip(names, run_row(ranks, args).split(",")))
                cells = float(row["cells"])
                row["us_per_cell"] = "%.3f" % (1e6 * float(row["t_setup"]) / cells)
                print(scene, n, ranks, row["cells"], row["t_setup"],
                      row["us_per_cell"], "us/cell", flush=True)
                rows.append(row)
    write(os.path.join(HERE, "stages.csv"), rows)
    return rows


def twist(quick):
    names = header([])
    rows = []
    for n in QUICK["twist"] if quick else TWIST_SIZES:
        for ranks in (1, 2):
            args = ["twist_file", str(n), "1",
                    "Mesh/File=" + main_benchmark.twist_mesh(n),
                    "Loading/Number of load steps=1"]
            start = time.time()
            row = dict(zip(names, run_row(ranks, args).split(",")))
            row["t_process"] = "%.3f" % (time.time() - start)
            dofs = float(row["dofs"])
            row["us_per_dof_process"] = "%.2f" % (
                1e6 * float(row["t_process"]) / dofs)
            row["amg_share"] = "%.3f" % (
                float(row["t_preconditioner"]) / float(row["t_total"]))
            row["setup_share"] = "%.3f" % (
                float(row["t_setup"]) / float(row["t_total"]))
            print("twist", n, ranks, row["dofs"], "newton",
                  row["newton_iterations"], "cg/newton",
                  row["krylov_per_newton"], "amg", row["amg_setups"],
                  "share", row["amg_share"], "process", row["t_process"], "s",
                  row["us_per_dof_process"], "us/dof", flush=True)
            rows.append(row)
    write(os.path.join(HERE, "twist.csv"), rows)
    return rows


def p2(quick):
    names = header(["--p2-preconditioner"])
    rows = []
    for n in QUICK["p2"] if quick else P2_SIZES:
        for ranks in (1, 2):
            args = ["--p2-preconditioner", "twist", str(n), "2",
                    "Loading/Number of load steps=1"]
            for line in run_rows(ranks, args)[-4:]:
                row = dict(zip(names, line.split(",")))
                print("p2", n, ranks, row["dofs"], row["preconditioner"],
                      "setup", row["t_setup"], "cg", row["cg_iterations"],
                      "solve", row["t_solve"], flush=True)
                rows.append(row)
    write(os.path.join(HERE, "p2_preconditioner.csv"), rows)
    # The whole P2 twist (4 load steps, as in benchmarks/run.py) with each
    # preconditioner: the same discrete solution, so the run time at equal
    # error.
    names = header([])
    runs = []
    for n in QUICK["p2"] if quick else P2_SIZES:
        for name in ("two-level", "AMG"):
            args = ["twist", str(n), "2",
                    "Linear solver/P2 preconditioner=" + name]
            row = dict(zip(names, run_row(1, args).split(",")))
            row["p2_preconditioner"] = name
            print("p2 twist", n, row["dofs"], name, "newton",
                  row["newton_iterations"], "cg", row["krylov_iterations"],
                  "amg", row["t_preconditioner"], "total", row["t_total"],
                  "energy", row["energy"], flush=True)
            runs.append(row)
    write(os.path.join(HERE, "p2_twist.csv"), runs)
    return rows


def write(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def plot():
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("plotting needs matplotlib: apt-get install python3-matplotlib")
    fig, axes = plt.subplots(1, 3, figsize=(17, 5))
    rows = read(os.path.join(HERE, "stages.csv"))
    # Left: stacked stages per cell, gmsh file, 1 rank.
    a = axes[0]
    sel = [r for r in rows if r["scene"] == "twist_file" and r["ranks"] == "1"]
    labels = [r["cells"] for r in sel]
    bottom = [0.0] * len(sel)
    for stage in STAGES:
        values = [1e6 * float(r[stage]) / float(r["cells"]) for r in sel]
        if max(values) < 0.05:
            continue
        a.bar(labels, values, bottom=bottom, label=stage)
        bottom = [b + v for b, v in zip(bottom, values)]
    a.axhline(2.0, color="k", linestyle="--", label="target 2 us/cell")
    a.set_xlabel("cells (gmsh file, 1 rank)")
    a.set_ylabel("set-up [us per cell]")
    a.set_title("set-up stages per cell")
    a.legend(fontsize=7)
    # Middle: total per cell, all series.
    a = axes[1]
    for scene in ("twist_file", "twist"):
        for ranks in ("1", "2"):
            sel = [r for r in rows if r["scene"] == scene and r["ranks"] == ranks]
            a.semilogx([float(r["cells"]) for r in sel],
                       [float(r["us_per_cell"]) for r in sel], "o-",
                       label="%s, %s rank(s)" % (
                           "gmsh file" if scene == "twist_file" else "box",
                           ranks))
    a.axhline(2.0, color="k", linestyle="--")
    a.set_xlabel("cells")
    a.set_ylabel("set-up [us per cell] (slowest rank)")
    a.set_title("whole set-up per cell")
    a.legend(fontsize=8)
    # Right: the twist in one step: time per unknown and AMG share.
    a = axes[2]
    path = os.path.join(HERE, "twist.csv")
    if os.path.exists(path):
        rows = read(path)
        for ranks in ("1", "2"):
            sel = [r for r in rows if r["ranks"] == ranks]
            x = [float(r["dofs"]) for r in sel]
            a.semilogx(x, [float(r["us_per_dof_process"]) for r in sel], "o-",
                       label="us per unknown, %s rank(s)" % ranks)
        b = a.twinx()
        for ranks in ("1", "2"):
            sel = [r for r in rows if r["ranks"] == ranks]
            b.semilogx([float(r["dofs"]) for r in sel],
                       [100 * float(r["amg_share"]) for r in sel], "s--",
                       label="AMG set-up share, %s rank(s)" % ranks)
        b.set_ylabel("AMG set-up [% of the run]")
        b.legend(loc="lower right", fontsize=8)
        a.set_xlabel("unknowns")
        a.set_ylabel("whole process [us per unknown]")
        a.set_title("twist in one load step")
        a.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "setup.png"), dpi=110)
    plot_p2(plt)


def plot_p2(plt):
    """p2.png: the P2 preconditioners on one tangent, and whole runs."""
    path = os.path.join(HERE, "p2_preconditioner.csv")
    if not os.path.exists(path):
        return
    rows = read(path)
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    a = axes[0]
    for name in sorted(set(r["preconditioner"] for r in rows)):
        for ranks in ("1", "2"):
            sel = [r for r in rows
                   if r["preconditioner"] == name and r["ranks"] == ranks]
            if sel:
                a.loglog([float(r["dofs"]) for r in sel],
                         [float(r["t_total"]) for r in sel], "o-",
                         label="%s, %s rank(s)" % (name, ranks))
    a.set_xlabel("P2 unknowns")
    a.set_ylabel("set-up + CG to 1e-8 [s]")
    a.set_title("the twist's last tangent")
    a.legend(fontsize=7)
    path = os.path.join(HERE, "p2_twist.csv")
    if os.path.exists(path):
        rows = read(path)
        a = axes[1]
        for name in ("two-level", "AMG"):
            sel = [r for r in rows if r["p2_preconditioner"] == name]
            a.loglog([float(r["dofs"]) for r in sel],
                     [float(r["t_total"]) for r in sel], "o-",
                     label="P2, " + name)
        a.set_xlabel("P2 unknowns")
        a.set_ylabel("whole run [s] (same error)")
        a.set_title("P2 twist, 4 load steps, 1 rank")
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "p2.png"), dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--plot", action="store_true")
    parser.add_argument("--only", choices=["stages", "twist", "p2"])
    args = parser.parse_args()
    if not args.plot:
        if args.only in (None, "stages"):
            stages(args.quick)
        if args.only in (None, "twist"):
            twist(args.quick)
        if args.only in (None, "p2"):
            p2(args.quick)
    plot()


if __name__ == "__main__":
    main()

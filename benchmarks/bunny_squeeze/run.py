#!/usr/bin/python3
"""The TetWild bunny squeeze of issue 57 (bunny_squeeze.prm): CG iterations
per Newton iteration with and without the exact solve on the contact's stiff
unknowns ('Linear solver/Exact solve on stiff couplings').

The mesh is wildmeshing/data's bunny_tetwild_80.msh (binary gmsh 2.2; not
in the repository).

  /usr/bin/python3 benchmarks/bunny_squeeze/run.py --mesh PATH/bunny_tetwild_80.msh
        --label NAME [--exe BUILD/hyperelastic] [--stiff-solve true,false]
  /usr/bin/python3 benchmarks/bunny_squeeze/run.py --plot

Each run (2 MPI ranks) keeps its CSV in runs/ (LABEL_stiffSOLVE.csv) and
replaces its row of bunny_squeeze.csv: rows, Newton iterations per row (mean
of newton_iterations), CG iterations per Newton iteration (sum linear / sum
Newton), cut-backs, the smallest load_increment over the nominal time step,
wall time, and the log's 'linear solve' and 'preconditioner setup' times.
--plot draws bunny_squeeze.png: CG per Newton iteration at every step, one
curve per run.
"""
import argparse
import csv
import os
import re
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
MPIRUN = os.path.join(ROOT, "scripts", "mpirun.sh")
SCENE = os.path.join(HERE, "bunny_squeeze.prm")
LOGS = os.path.join(ROOT, "build", "bunny_squeeze_logs")
SUMMARY = os.path.join(HERE, "bunny_squeeze.csv")
RUNS = os.path.join(HERE, "runs")
PLOT = os.path.join(HERE, "bunny_squeeze.png")
TIME_STEP = 0.05
COLUMNS = ["label", "stiff_solve", "rows", "newton_per_row", "cg_per_newton",
           "cut_backs", "smallest_step_fraction", "wall_s", "linear_solve_s",
           "preconditioner_setup_s"]


def timer_section(log, name):
    match = re.search(r"\| " + re.escape(name) + r"\s+\|\s+\d+\s+\|\s+([\d.e+]+)s", log)
    return float(match.group(1)) if match else float("nan")


def run(exe, mesh, label, stiff_solve):
    os.makedirs(LOGS, exist_ok=True)
    os.makedirs(RUNS, exist_ok=True)
    name = "%s_stiff%s" % (label, stiff_solve)
    output = os.path.join(LOGS, name)
    scene = os.path.join(LOGS, name + ".prm")
    text = open(SCENE).read().replace("set File   = MESH", "set File   = " + mesh)
    text = text.replace("set Directory = output", "set Directory = " + output)
    text += ("\nsubsection Linear solver\n  set Exact solve on stiff couplings = %s\nend\n"
             % stiff_solve)
    open(scene, "w").write(text)
    start = time.time()
    result = subprocess.run([MPIRUN, "-np", "2", exe, scene],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)
    wall = time.time() - start
    open(os.path.join(LOGS, name + ".log"), "w").write(result.stdout)
    if result.returncode != 0:
        raise SystemExit("%s failed (exit %d), log in %s" %
                         (name, result.returncode, LOGS))
    rows = list(csv.DictReader(open(os.path.join(output, "bunny_squeeze.csv"))))
    open(os.path.join(RUNS, name + ".csv"), "w").write(
        open(os.path.join(output, "bunny_squeeze.csv")).read())
    newton = sum(int(r["newton_iterations"]) for r in rows)
    linear = sum(int(r["linear_iterations"]) for r in rows)
    return {"label": label, "stiff_solve": stiff_solve, "rows": len(rows),
            "newton_per_row": "%.2f" % (newton / len(rows)),
            "cg_per_newton": "%.1f" % (linear / newton),
            "cut_backs": sum(int(r["cut_backs"]) for r in rows),
            "smallest_step_fraction": "%.4g" % (
                min(float(r["load_increment"]) for r in rows) / TIME_STEP),
            "wall_s": "%.0f" % wall,
            "linear_solve_s": "%.0f" % timer_section(result.stdout, "linear solve"),
            "preconditioner_setup_s": "%.0f" % timer_section(
                result.stdout, "preconditioner setup")}


def store(row):
    rows = []
    if os.path.exists(SUMMARY):
        rows = [r for r in csv.DictReader(open(SUMMARY))
                if (r["label"], r["stiff_solve"]) != (row["label"], row["stiff_solve"])]
    rows.append({k: str(v) for k, v in row.items()})
    with open(SUMMARY, "w", newline="") as f:
        writer = csv.DictWriter(f, COLUMNS)
        writer.writeheader()
        writer.writerows(rows)


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(1, 2, figsize=(11, 4))
    for name in sorted(os.listdir(RUNS)):
        rows = list(csv.DictReader(open(os.path.join(RUNS, name))))
        t = [float(r["load_factor"]) for r in rows]
        cg = [int(r["linear_iterations"]) / max(1, int(r["newton_iterations"]))
              for r in rows]
        newton = [int(r["newton_iterations"]) for r in rows]
        label = name[:-4].replace("_stiff", ", exact solve on stiff couplings = ")
        axes[0].plot(t, cg, marker=".", label=label)
        axes[1].plot(t, newton, marker=".", label=label)
    axes[0].set_xlabel("time (plate down by 40 % at t = 1)")
    axes[0].set_ylabel("CG iterations per Newton iteration")
    axes[1].set_xlabel("time")
    axes[1].set_ylabel("Newton iterations per step")
    axes[0].legend(fontsize=7)
    axes[0].set_title("TetWild bunny squeeze, 23,874 unknowns, 2 ranks",
                      fontsize=9)
    figure.tight_layout()
    figure.savefig(PLOT, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--mesh")
    parser.add_argument("--label")
    parser.add_argument("--exe", default=os.path.join(ROOT, "build", "hyperelastic"))
    parser.add_argument("--stiff-solve", default="true,false")
    parser.add_argument("--plot", action="store_true")
    arguments = parser.parse_args()
    if arguments.plot:
        plot()
        return
    if not arguments.mesh or not arguments.label:
        parser.error("--mesh and --label are needed for a run")
    mesh = os.path.abspath(arguments.mesh)
    for stiff_solve in arguments.stiff_solve.split(","):
        row = run(os.path.abspath(arguments.exe), mesh, arguments.label, stiff_solve)
        print(row)
        store(row)
    plot()


if __name__ == "__main__":
    main()

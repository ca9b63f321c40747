#!/usr/bin/python3
"""Two deformable blocks sliding with friction (issue 57, item 2): the
friction answer and Newton's cost of a frictional slide.

The scene is sliding_blocks_2d.prm (the test contact.sliding_friction's):
the upper block of meshes/sliding_blocks_2d.msh pressed 0.025 onto the
clamped lower one, then slid 0.5 along x, 30 load steps, self contact with
friction coefficient MU, defaults otherwise, NP ranks. Once the block
slides (t >= 0.3) Coulomb's law gives the top's reaction |Fx|/|Fy| = mu.

  /usr/bin/python3 benchmarks/sliding_friction/run.py --label NAME
        [--exe BUILD/hyperelastic] [--mu 0.3,0] [--np 1]
  /usr/bin/python3 benchmarks/sliding_friction/run.py --plot   # sliding_friction.png

Each run keeps its rows in runs/LABEL_muMU.csv and replaces its row of
sliding_friction.csv (label, mu): rows, Newton iterations in all and per
row, the ratio to the same label's frictionless run, CG iterations per
Newton iteration, cut-backs, |Fx|/|Fy| over the sliding rows (min, max,
mean), lagged-quantity updates (from the log), wall time.
"""
import argparse
import csv
import os
import subprocess
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
MPIRUN = os.path.join(ROOT, "scripts", "mpirun.sh")
SCENE = os.path.join(HERE, "sliding_blocks_2d.prm")
SUMMARY = os.path.join(HERE, "sliding_friction.csv")
RUNS = os.path.join(HERE, "runs")
PLOT = os.path.join(HERE, "sliding_friction.png")
KEPT = ["load_factor", "newton_iterations", "linear_iterations",
        "reaction_2_x", "reaction_2_y", "cut_backs"]
FIELDS = ["label", "mu", "np", "exit", "rows", "newton", "newton_per_row",
          "newton_over_frictionless", "cg_per_newton", "cut_backs",
          "ratio_min", "ratio_max", "ratio_mean", "lagged_updates", "wall_s"]


def run(exe, mu, np):
    """Runs the scene with friction coefficient mu; returns rows, exit code,
    log and wall time."""
    with tempfile.TemporaryDirectory() as out:
        prm = os.path.join(out, "scene.prm")
        text = open(SCENE).read().replace(
            "../../meshes/", os.path.join(ROOT, "meshes") + "/")
        with open(prm, "w") as f:
            f.write(text + """
subsection Contact
  set Self contact friction coefficient = {mu}
end
subsection Output
  set Directory = {out}
  set Base name = run
end
""".format(mu=mu, out=out))
        start = time.time()
        done = subprocess.run([MPIRUN, "-np", str(np), exe, prm],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True)
        wall = time.time() - start
        path = os.path.join(out, "run.csv")
        rows = list(csv.DictReader(open(path))) if os.path.exists(path) else []
        return rows, done.returncode, done.stdout, wall


def sliding_ratios(rows):
    return [abs(float(r["reaction_2_x"]) / float(r["reaction_2_y"]))
            for r in rows if float(r["load_factor"]) >= 0.3 - 1e-12]


def summarise(label, mu, np, rows, code, log, wall):
    s = {"label": label, "mu": mu, "np": np, "exit": code, "rows": len(rows),
         "wall_s": "%.1f" % wall,
         "lagged_updates": log.count("(lagged quantities updated)")}
    if not rows:
        return s
    newton = sum(int(r["newton_iterations"]) for r in rows)
    linear = sum(int(r["linear_iterations"]) for r in rows)
    ratios = sliding_ratios(rows)
    s.update({"newton": newton, "newton_per_row": "%.2f" % (newton / len(rows)),
              "cg_per_newton": "%.1f" % (linear / max(newton, 1)),
              "cut_backs": sum(int(r["cut_backs"]) for r in rows),
              "ratio_min": "%.4g" % min(ratios), "ratio_max": "%.4g" % max(ratios),
              "ratio_mean": "%.4g" % (sum(ratios) / len(ratios))})
    return s


def read_summary():
    return list(csv.DictReader(open(SUMMARY))) if os.path.exists(SUMMARY) else []


def write_summary(table):
    # Newton iterations over the same label's frictionless run.
    for row in table:
        base = [r for r in table if r["label"] == row["label"] and
                float(r["mu"]) == 0. and r.get("newton")]
        if base and row.get("newton") and float(row["mu"]) > 0.:
            row["newton_over_frictionless"] = "%.2f" % (
                float(row["newton"]) / float(base[0]["newton"]))
    with open(SUMMARY, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS, extrasaction="ignore")
        w.writeheader()
        for row in table:
            w.writerow(row)


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for name in sorted(os.listdir(RUNS)):
        if not name.endswith("_mu0.3.csv"):
            continue
        label = name[:-len("_mu0.3.csv")]
        rows = list(csv.DictReader(open(os.path.join(RUNS, name))))
        t = [float(r["load_factor"]) for r in rows
             if float(r["load_factor"]) >= 0.3 - 1e-12]
        ax[0].plot(t, sliding_ratios(rows), "o-", ms=3, label=label)
        ax[1].plot([float(r["load_factor"]) for r in rows],
                   [int(r["newton_iterations"]) for r in rows], "o-", ms=3,
                   label=label)
    ax[0].axhline(0.3, color="k", lw=0.8, ls="--", label="mu = 0.3")
    ax[0].set_xlabel("load factor t (sliding from t = 0.2)")
    ax[0].set_ylabel("|Fx| / |Fy| of the top's reaction")
    ax[0].set_title("friction answer, mu = 0.3")
    ax[1].set_xlabel("load factor t")
    ax[1].set_ylabel("Newton iterations of the row")
    ax[1].set_title("Newton's cost, mu = 0.3")
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(PLOT, dpi=110)
    print("wrote", PLOT)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--label")
    parser.add_argument("--exe", default=os.path.join(ROOT, "build",
                                                      "hyperelastic"))
    parser.add_argument("--mu", default="0.3,0")
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--plot", action="store_true")
    args = parser.parse_args()
    if args.plot:
        plot()
        return
    if not args.label:
        parser.error("--label NAME is needed to run")
    os.makedirs(RUNS, exist_ok=True)
    table = read_summary()
    for mu in [float(m) for m in args.mu.split(",")]:
        rows, code, log, wall = run(args.exe, mu, args.np)
        with open(os.path.join(RUNS, "%s_mu%g.csv" % (args.label, mu)), "w",
                  newline="") as f:
            w = csv.DictWriter(f, fieldnames=KEPT, extrasaction="ignore")
            w.writeheader()
            for r in rows:
                w.writerow(r)
        s = summarise(args.label, "%g" % mu, args.np, rows, code, log, wall)
        table = [r for r in table if not (r["label"] == args.label and
                                          float(r["mu"]) == mu)] + [s]
        print(s)
    write_summary(table)
    plot()


if __name__ == "__main__":
    main()

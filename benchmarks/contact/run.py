#!/usr/bin/python3
"""Benchmark of obstacle contact (issue 26): its cost against the elastic
assembly, and Newton iterations against the barrier distance d_hat.

Runs build/hyperelastic_benchmark on the 'ball' scene (a rigid ball of radius
0.5 pressed 0.1 deep into the soft slab [0,2] x [0,2] x [0,0.5] of
4n x 4n x n boxes, 5 load steps, frictionless) and writes

  cost.csv  per size: unknowns, Newton iterations, the wall time of the
            tangent assembly and residual phases (each includes the contact
            term) and of the contact term alone (forces, stiffness, potential,
            feasible step), and their ratio contact / (assembly + residual -
            contact)
  dhat.csv  n = 8 at d_hat = 0.02 ... 0.00125: Newton iterations per load step
  cost.png, dhat.png

  python3 benchmarks/contact/run.py          # sizes 1e4 ... 1e6 unknowns (~20 min)
  python3 benchmarks/contact/run.py --quick  # small sizes (~1 min)
  python3 benchmarks/contact/run.py --plot   # redraw from the CSVs
"""
import argparse
import csv
import os
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
EXE = os.path.join(ROOT, "build", "hyperelastic_benchmark")
MPIRUN = os.path.join(ROOT, "scripts", "mpirun.sh")
COST = os.path.join(HERE, "cost.csv")
DHAT = os.path.join(HERE, "dhat.csv")
# 3 (4n+1)^2 (n+1) unknowns: 4.3e3 ... 1.1e6.
SIZES = [4, 6, 8, 12, 16, 22, 28]
QUICK_SIZES = [4, 6]
D_HATS = [0.02, 0.01, 0.005, 0.0025, 0.00125]


def run(n, ranks, extra=()):
    header = subprocess.run([MPIRUN, "-np", "1", EXE, "--header"], check=True,
                            capture_output=True, text=True).stdout.strip()
    out = subprocess.run([MPIRUN, "-np", str(ranks), EXE, "ball", str(n), "1",
                          *extra], check=True, capture_output=True,
                         text=True).stdout.strip().splitlines()[-1]
    return dict(zip(header.split(","), out.split(",")))


def write(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


def measure(sizes):
    cost = []
    for n in sizes:
        ranks = 2 if n >= 16 else 1
        r = run(n, ranks)
        assembly = float(r["t_tangent_assembly"]) + float(r["t_residual"])
        contact = float(r["t_contact"])
        row = {"n": n, "ranks": ranks, "dofs": int(r["dofs"]),
               "newton_iterations": int(r["newton_iterations"]),
               "t_assembly_and_residual": assembly, "t_contact": contact,
               "contact_over_elastic": contact / max(assembly - contact, 1e-300),
               "t_total": float(r["t_total"])}
        print(row, flush=True)
        cost.append(row)
    write(COST, cost)
    dhat = []
    for d in D_HATS:
        r = run(8, 1, [f"Contact/Barrier distance={d}"])
        row = {"d_hat": d, "dofs": int(r["dofs"]),
               "load_steps": int(r["load_steps"]),
               "newton_iterations": int(r["newton_iterations"]),
               "newton_per_step": int(r["newton_iterations"]) / int(r["load_steps"]),
               "energy": float(r["energy"])}
        print(row, flush=True)
        dhat.append(row)
    write(DHAT, dhat)


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cost = list(csv.DictReader(open(COST)))
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.semilogx([int(r["dofs"]) for r in cost],
                [float(r["contact_over_elastic"]) for r in cost], "o-")
    ax.axhline(0.5, ls="--", c="gray", label="goal 0.5")
    ax.set_xlabel("unknowns")
    ax.set_ylabel("contact time / elastic assembly time")
    ax.set_title("ball in slab: cost of obstacle contact")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "cost.png"), dpi=120)
    dhat = list(csv.DictReader(open(DHAT)))
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.semilogx([float(r["d_hat"]) for r in dhat],
                [float(r["newton_per_step"]) for r in dhat], "o-")
    ax.set_xlabel("barrier distance d_hat")
    ax.set_ylabel("Newton iterations per load step")
    ax.set_title("ball in slab (n = 8)")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "dhat.png"), dpi=120)


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--plot", action="store_true")
    args = parser.parse_args()
    if not args.plot:
        measure(QUICK_SIZES if args.quick else SIZES)
    plot()

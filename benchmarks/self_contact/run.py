#!/usr/bin/python3
"""Benchmark of self-contact (issue 27): its cost per Newton iteration
against the elastic assembly, split into broad phase, narrow phase, CCD and
the exchange of boundary positions, on the hollow ball squashed by a plate.

For each mesh size h (meshes/hollow_ball_3d.geo meshed by gmsh into
benchmarks/self_contact/meshes/), on 1 and 2 MPI ranks, runs build/hyperelastic
on the scene of parameters/hollow_ball_3d.prm (written here): the shell
0.7 <= r <= 1 standing on its flat bottom, a rigid plate coming down from its
top at speed 0.5, backward Euler with time step 0.05,

  squash  to t = 3 (the plate 1.5 down): the walls fold and the inner surface
          meets itself (self pairs active), for the small sizes;
  start   to t = 0.1, 2 time steps (no self pair active yet: the fixed cost
          of self-contact, broad phase, CCD and exchange, on every Newton
          iteration), for every size;

and parses the run's timing table (sections "assembly", "residual") and its
line "self contact: ... evaluations; wall time: exchange ... broad phase ...
narrow phase ... CCD ..." (rank 0). The elastic assembly per Newton iteration
(tangent + residual) comes from the same mesh's 'start' run without
self-contact. Writes

  cost.csv  per run: scene, h, ranks, unknowns, boundary vertices, the
            doubles rank 0 received per evaluation (the other ranks'
            vertices within reach of its own),
            Newton iterations, self-contact evaluations per iteration, and
            per Newton iteration (s): the elastic assembly, self-contact and
            its parts, with the ratio self-contact / elastic assembly
  cost.png

  /usr/bin/python3 benchmarks/self_contact/run.py           # all sizes (~40 min)
  /usr/bin/python3 benchmarks/self_contact/run.py --quick   # h = 0.15 only (~1 min)
  python3 benchmarks/self_contact/run.py --plot    # redraw from cost.csv
"""
import argparse
import csv
import os
import re
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
EXE = os.path.join(ROOT, "build", "hyperelastic")
MPIRUN = os.path.join(ROOT, "scripts", "mpirun.sh")
GEO = os.path.join(ROOT, "meshes", "hollow_ball_3d.geo")
MESHES = os.path.join(HERE, "meshes")
COST = os.path.join(HERE, "cost.csv")
# (h, scenes, ranks): 4e3 ... 9e5 unknowns.
SIZES = [(0.15, ("squash", "start"), (1, 2)), (0.1, ("start",), (1, 2)),
         (0.07, ("start",), (1, 2)), (0.045, ("start",), (1, 2)),
         (0.03, ("start",), (2,)), (0.02, ("start",), (2,))]
QUICK_SIZES = [(0.15, ("start",), (1, 2))]

SCENE = """
subsection Problem
  set Dimension = 3
end
subsection Mesh
  set Source = file
  set File   = {mesh}
end
subsection Material
  set Model           = neo-Hookean
  set Young's modulus = 1.0
  set Poisson's ratio = 0.3
end
subsection Time integration
  set Scheme    = backward Euler
  set Density   = 1
  set Time step = 0.05
  set End time  = {end}
end
subsection Dirichlet 1
  set Boundary id  = 1
  set Components   = x, y, z
  set Displacement = 0; 0; 0
end
subsection Contact
  set Barrier distance = 0.004
  set Self contact     = {self_contact}
  subsection Obstacle 1
    set Type   = plane
    set Point  = 0, 0, 1.002
    set Normal = 0, 0, -1
    set Motion = 0; 0; -0.5*t
  end
end
subsection Output
  set Directory = {out}
  set Base name = hollow_ball
  set Write VTU = false
end
"""


def mesh(h):
    os.makedirs(MESHES, exist_ok=True)
    path = os.path.join(MESHES, "hollow_ball_%g.msh" % h)
    if not os.path.exists(path):
        subprocess.run(["gmsh", "-3", "-format", "msh41", "-setnumber", "h",
                        str(h), GEO, "-o", path], check=True,
                       capture_output=True)
    return path


def seconds(text, section):
    # A row of deal.II's timing table: | section | calls | wall time | % |
    m = re.search(r"\|\s*" + re.escape(section) + r"\s*\|\s*\d+\s*\|\s*"
                  r"([0-9.e+-]+)s", text)
    return float(m.group(1)) if m else 0.


def run(h, scene, ranks, self_contact=True):
    out = os.path.join(HERE, "out")
    end = 3. if scene == "squash" else 0.1
    prm = os.path.join(HERE, "scene.prm")
    with open(prm, "w") as f:
        f.write(SCENE.format(mesh=mesh(h), end=end, out=out,
                             self_contact=str(self_contact).lower()))
    text = subprocess.run([MPIRUN, "-np", str(ranks), EXE, prm], check=True,
                          capture_output=True, text=True).stdout
    with open(os.path.join(out, "hollow_ball.csv")) as f:
        iterations = sum(int(r["newton_iterations"])
                         for r in csv.DictReader(f))
    result = {"unknowns": int(re.search(r"(\d+) unknowns", text).group(1)),
              "newton_iterations": iterations,
              "t_assembly": seconds(text, "assembly"),
              "t_residual": seconds(text, "residual")}
    if self_contact:
        result["boundary_vertices"] = int(re.search(
            r"self contact: (\d+) boundary vertices", text).group(1))
        cost = re.search(r"self contact: (\d+) evaluations; wall time: "
                         r"exchange (\S+) s, broad phase (\S+) s, narrow "
                         r"phase (\S+) s, CCD (\S+) s; \d+ sparsity "
                         r"rebuilds; (\S+) doubles received", text)
        result["received"] = float(cost.group(6))
        result["evaluations"] = int(cost.group(1))
        for k, name in enumerate(["exchange", "broad", "narrow", "ccd"]):
            result["t_" + name] = float(cost.group(k + 2))
    return result


def measure(h, scene, ranks):
    """Self-contact's time per Newton iteration (its four parts, rank 0)
    against the elastic assembly's (tangent + residual) per Newton iteration
    of the same mesh without self-contact ('start', 2 time steps)."""
    on = run(h, scene, ranks)
    off = run(h, "start", ranks, self_contact=False)
    per_it = lambda r, t: t / r["newton_iterations"]
    elastic = per_it(off, off["t_assembly"] + off["t_residual"])
    parts = {k: per_it(on, on["t_" + k])
             for k in ("exchange", "broad", "narrow", "ccd")}
    contact = sum(parts.values())
    return {"scene": scene, "h": h, "ranks": ranks,
            "unknowns": on["unknowns"],
            "boundary_vertices": on["boundary_vertices"],
            "received_per_evaluation": round(on["received"], 1),
            "newton_iterations": on["newton_iterations"],
            "evaluations_per_iteration":
                round(on["evaluations"] / on["newton_iterations"], 2),
            "elastic_assembly_per_iteration": round(elastic, 6),
            "contact_per_iteration": round(contact, 6),
            "exchange_per_iteration": round(parts["exchange"], 6),
            "broad_per_iteration": round(parts["broad"], 6),
            "narrow_per_iteration": round(parts["narrow"], 6),
            "ccd_per_iteration": round(parts["ccd"], 6),
            "contact_over_assembly": round(contact / elastic, 4)}


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(COST) as f:
        rows = list(csv.DictReader(f))
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for scene in ("start", "squash"):
        for ranks in ("1", "2"):
            sel = [r for r in rows if r["scene"] == scene and
                   r["ranks"] == ranks]
            if not sel:
                continue
            ax.plot([int(r["unknowns"]) for r in sel],
                    [float(r["contact_over_assembly"]) for r in sel],
                    "o-", label="%s, %s rank(s)" % (scene, ranks))
    ax.axhline(1., color="gray", ls="--", lw=0.8, label="goal: <= 1")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("unknowns")
    ax.set_ylabel("self-contact time / elastic assembly time")
    ax.set_title("Self-contact cost, hollow ball squashed by a plate")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "cost.png"), dpi=110)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--plot", action="store_true")
    args = parser.parse_args()
    if not args.plot:
        rows = []
        for h, scenes, rank_counts in (QUICK_SIZES if args.quick else SIZES):
            for scene in scenes:
                for ranks in rank_counts:
                    r = measure(h, scene, ranks)
                    print(r, flush=True)
                    rows.append(r)
        with open(COST, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)
    plot()


if __name__ == "__main__":
    main()

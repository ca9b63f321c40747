#!/usr/bin/python3
"""Benchmark of friction's cost (issue 43, item 5): Newton iterations per
step with friction against the same scene without it, for the lagging of
friction's normal forces and tangents inside the Newton iteration.

Scenes (written here; neo-Hookean E = 1, nu = 0.3 unless said):
  block_on_plane     a unit block (8 x 8 x 8 boxes, 3072 tetrahedra) sliding
                     at speed 2 on a plane, under gravity 10, E = 1e4,
                     backward Euler h = 0.01 to t = 0.3 (mu = 0.5 decelerates
                     it; mu = 0 lets it slide on)
  block_between_plates  a unit block (8 x 8 x 8 boxes) between a floor and a
                     plate pressing it 30 % in 10 quasi-static steps, no
                     Dirichlet condition (held by the plates)
  ball_between_plates  the hollow ball of meshes/hollow_ball_3d.geo meshed
                     with h = 0.08 (over 20k tetrahedra) between a floor and
                     a plate that squeezes it 40 % (0.8 of its height 1.98),
                     backward Euler h = 0.05 to t = 1.6, self contact, no
                     Dirichlet condition
each with mu = 0 and mu = 0.5 (both plates), 2 MPI ranks. Each run's CSV
gives the Newton iterations and Krylov iterations per step.

  /usr/bin/python3 benchmarks/friction/run.py [--exe BUILD/hyperelastic]
        [--label NAME] [--scenes block_on_plane,...]
appends to cost.csv (label, scene, mu, steps, Newton iterations, Krylov
iterations, wall time); --table prints the table of cost.csv by label.
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
COST = os.path.join(HERE, "cost.csv")
GEO = os.path.join(ROOT, "meshes", "hollow_ball_3d.geo")
BALL_MESH = os.path.join(HERE, "meshes", "hollow_ball_h0.08.msh")

COMMON = """
subsection Problem
  set Dimension = 3
end
subsection Material
  set Model           = neo-Hookean
  set Young's modulus = {young}
  set Poisson's ratio = 0.3
end
subsection Output
  set Write VTU = false
  set Directory = {out}
  set Base name = run
end
"""

BLOCK = """
subsection Mesh
  set Lower corner = 0, 0, {bottom}
  set Upper corner = 1, 1, {top}
  set Subdivisions = 8, 8, 8
end
"""

SCENES = {
    "block_on_plane": COMMON.format(young="1e4", out="{out}") +
    BLOCK.format(bottom=0.00495, top=1.00495) + """
subsection Loading
  set Body force = 0; 0; -10
end
subsection Time integration
  set Scheme           = backward Euler
  set Density          = 1
  set Time step        = 0.01
  set End time         = 0.3
  set Initial velocity = 2; 0; 0
end
subsection Contact
  set Barrier distance = 0.005
  subsection Obstacle 1
    set Type                 = plane
    set Point                = 0, 0, 0
    set Normal               = 0, 0, 1
    set Friction coefficient = {mu}
  end
end
""",
    "block_between_plates": COMMON.format(young="1", out="{out}") +
    BLOCK.format(bottom=0, top=1) + """
subsection Loading
  set Number of load steps = 10
end
subsection Contact
  set Barrier distance = 0.002
  subsection Obstacle 1
    set Type                 = plane
    set Point                = 0, 0, -0.001
    set Normal               = 0, 0, 1
    set Friction coefficient = {mu}
  end
  subsection Obstacle 2
    set Type                 = plane
    set Point                = 0, 0, 1.001
    set Normal               = 0, 0, -1
    set Motion               = 0; 0; -0.3*t
    set Friction coefficient = {mu}
  end
end
""",
    "ball_between_plates": COMMON.format(young="1", out="{out}") + """
subsection Mesh
  set Source = file
  set File   = """ + BALL_MESH + """
end
subsection Time integration
  set Scheme    = backward Euler
  set Density   = 1
  set Time step = 0.05
  set End time  = 1.6
end
subsection Contact
  set Barrier distance = 0.004
  set Self contact     = true
  subsection Obstacle 1
    set Type                 = plane
    set Point                = 0, 0, -0.982
    set Normal               = 0, 0, 1
    set Friction coefficient = {mu}
  end
  subsection Obstacle 2
    set Type                 = plane
    set Point                = 0, 0, 1.002
    set Normal               = 0, 0, -1
    set Motion               = 0; 0; -0.5*t
    set Friction coefficient = {mu}
  end
end
""",
}


def ball_mesh():
    if not os.path.exists(BALL_MESH):
        os.makedirs(os.path.dirname(BALL_MESH), exist_ok=True)
        subprocess.run(["gmsh", "-3", "-format", "msh41", "-setnumber", "h",
                        "0.08", GEO, "-o", BALL_MESH], check=True,
                       stdout=subprocess.DEVNULL)


def run(exe, scene, mu):
    with tempfile.TemporaryDirectory() as out:
        prm = os.path.join(out, "scene.prm")
        with open(prm, "w") as f:
            f.write(SCENES[scene].replace("{out}", out).replace(
                "{mu}", str(mu)))
        start = time.time()
        done = subprocess.run([MPIRUN, "-np", "2", exe, prm],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True)
        wall = time.time() - start
        csv_file = os.path.join(out, "run.csv")
        rows = list(csv.DictReader(open(csv_file))) if os.path.exists(
            csv_file) else []
        rows = [r for r in rows if int(r["step"]) > 0]
        newton = sum(int(r["newton_iterations"]) for r in rows)
        krylov = sum(int(r["linear_iterations"]) for r in rows)
        return {"scene": scene, "mu": mu, "exit": done.returncode,
                "steps": len(rows), "newton_iterations": newton,
                "linear_iterations": krylov, "wall_s": round(wall, 1),
                "t_end": rows[-1]["load_factor"] if rows else "",
                "tail": done.stdout[-2000:] if done.returncode else ""}


def table():
    rows = list(csv.DictReader(open(COST)))
    print("| label | scene | mu | steps | Newton its | Newton/step | "
          "Krylov its | wall s | exit |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        steps = max(int(r["steps"]), 1)
        print("| {label} | {scene} | {mu} | {steps} | {newton_iterations} | "
              "{per:.2f} | {linear_iterations} | {wall_s} | {exit} |".format(
                  per=int(r["newton_iterations"]) / steps, **r))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", default=os.path.join(ROOT, "build",
                                                      "hyperelastic"))
    parser.add_argument("--label", default="in Newton")
    parser.add_argument("--scenes", default=",".join(SCENES))
    parser.add_argument("--table", action="store_true")
    args = parser.parse_args()
    if args.table:
        table()
        return
    fields = ["label", "scene", "mu", "exit", "steps", "t_end",
              "newton_iterations", "linear_iterations", "wall_s"]
    new = not os.path.exists(COST)
    with open(COST, "a", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        if new:
            writer.writeheader()
        for scene in args.scenes.split(","):
            if scene == "ball_between_plates":
                ball_mesh()
            for mu in (0.0, 0.5):
                r = run(args.exe, scene, mu)
                r["label"] = args.label
                print(r, flush=True)
                writer.writerow(r)
                f.flush()
    table()


if __name__ == "__main__":
    main()

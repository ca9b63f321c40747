#!/usr/bin/env python3
"""The twisting hemisphere (issue 67): meshes twisting_hemisphere.geo with
gmsh, runs twisting_hemisphere.prm on 2 ranks (settings appended with
--set), stops it after --timeout seconds if it has not ended, and appends
a row to twisting_hemisphere.csv: how far it got (load factor, degrees
turned), Newton iterations per nominal step over the part it ran (the CSV's
newton_iterations summed, over the nominal steps that part spans), the
smallest step, CG per Newton iteration, wall time, and the torque
reaction_moment_2_z every 20 degrees. The run's own CSV goes to runs/.

    python3 benchmarks/twisting_hemisphere/run.py --label NAME [--h 0.1]
        [--timeout 900] [--set 'Contact/Friction lagging updates=1']
"""
import argparse
import csv
import math
import os
import shutil
import subprocess
import tempfile
import time

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(here))


def scene_text(mesh, output, settings):
    text = open(os.path.join(here, "twisting_hemisphere.prm")).read()
    text = text.replace("set File   = MESH", "set File   = " + mesh)
    text = text.replace("set Directory    = OUTPUT", "set Directory    = " + output)
    for s in settings:
        path, value = s.split("=", 1)
        parts = path.split("/")
        block = "  " * (len(parts) - 1) + "set " + parts[-1] + " = " + value + "\n"
        for depth, name in reversed(list(enumerate(parts[:-1]))):
            block = ("  " * depth + "subsection " + name + "\n" + block +
                     "  " * depth + "end\n")
        text += "\n" + block
    return text


def degrees(t):
    return 180. * max(0., (t - 0.2) / 0.8)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--label", required=True)
    p.add_argument("--exe", default=os.path.join(root, "build", "hyperelastic"))
    p.add_argument("--h", default="0.1")
    p.add_argument("--timeout", type=float, default=900.)
    p.add_argument("--set", action="append", default=[])
    a = p.parse_args()
    work = tempfile.mkdtemp()
    mesh = os.path.join(work, "hemisphere.msh")
    subprocess.run(["gmsh", "-3", "-format", "msh22", "-setnumber", "h", a.h,
                    os.path.join(here, "twisting_hemisphere.geo"), "-o", mesh],
                   check=True, stdout=subprocess.DEVNULL)
    scene = os.path.join(work, "scene.prm")
    open(scene, "w").write(scene_text(mesh, work, a.set))
    start = time.time()
    log = open(os.path.join(work, "log.txt"), "w")
    run = subprocess.Popen([os.path.join(root, "scripts", "mpirun.sh"), "-np",
                            "2", a.exe, scene], stdout=log, stderr=subprocess.STDOUT)
    try:
        run.wait(timeout=a.timeout)
        ended = "yes" if run.returncode == 0 else "exit %d" % run.returncode
    except subprocess.TimeoutExpired:
        run.kill()
        run.wait()
        ended = "stopped"
    wall = time.time() - start
    rows = list(csv.DictReader(open(os.path.join(work, "twisting_hemisphere.csv"))))
    steps = 50
    t_end = float(rows[-1]["load_factor"])
    newton = sum(float(r["newton_iterations"]) for r in rows)
    cg = sum(float(r.get("linear_iterations", 0) or 0) for r in rows)
    increments = [float(b["load_factor"]) - float(a_["load_factor"])
                  for a_, b in zip(rows, rows[1:])]
    smallest = min(increments) * steps if increments else float("nan")
    torque = {}
    for target in range(20, 181, 20):
        for r in rows:
            if degrees(float(r["load_factor"])) >= target - 1e-9:
                torque[target] = float(r["reaction_moment_2_z"])
                break
    row = {"label": a.label, "h": a.h, "settings": "; ".join(a.set),
           "ended": ended, "rows": len(rows), "t_end": "%.4f" % t_end,
           "degrees": "%.1f" % degrees(t_end),
           "newton": int(newton),
           "per_nominal": "%.2f" % (newton / (t_end * steps)),
           "cg_per_newton": "%.1f" % (cg / newton) if newton else "",
           "smallest_step": "%.4g" % smallest, "wall_s": "%.0f" % wall}
    for target in range(20, 181, 20):
        row["torque_%d" % target] = ("%.5g" % torque[target]) if target in torque else ""
    out = os.path.join(here, "twisting_hemisphere.csv")
    new = not os.path.exists(out)
    with open(out, "a", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(row))
        if new:
            w.writeheader()
        w.writerow(row)
    os.makedirs(os.path.join(here, "runs"), exist_ok=True)
    shutil.copy(os.path.join(work, "twisting_hemisphere.csv"),
                os.path.join(here, "runs", a.label + ".csv"))
    print(row)


if __name__ == "__main__":
    main()

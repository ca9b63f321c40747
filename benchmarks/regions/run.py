#!/usr/bin/python3
"""Contrast benchmark of regions (issue 45, item 3): Krylov iterations per
Newton step on a rubber bar with a bonded steel band (Young's moduli 1e4
apart) against the same bar of rubber alone, with 'Linear solver/AMG for
contrast' off and on (auto).

The scene is contrast.prm (the bar [0,4] x [0,1] x [0,1], 24,843 unknowns,
clamped at x = 0, its end twisted by 60 degrees and pulled, 4 load steps);
'band' adds Region 1 = 1.5 < x < 2.5 with E = 1e4 (nu = 0.3). Cases:
  CG + AMG (displacement formulation, neo-Hookean), and
  GMRES + the block preconditioner (mixed formulation, decoupled
  neo-Hookean; an eighth of the load in 2 steps: with the whole load the
  banded bar's Newton cuts the step back, see README.md).
One MPI rank. Writes contrast.csv (case, material, AMG for contrast, load
steps, Newton iterations, Krylov iterations, per Newton step, wall time)
and checks the issue's bound: the band's Krylov iterations per Newton step
at most 2x the one-material bar's with the default settings.

  /usr/bin/python3 benchmarks/regions/run.py [--exe BUILD/hyperelastic]
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SCENE = os.path.join(HERE, "contrast.prm")

BAND = """
subsection Region 1
  set Cells = x > 1.5 && x < 2.5
  subsection Material
    set Model = {model}
    set Young's modulus = 1e4
    set Poisson's ratio = 0.3
  end
end
"""

MIXED = """
subsection Problem
  set Formulation = mixed
end
subsection Material
  set Model = decoupled neo-Hookean
end
subsection Loading
  set Number of load steps = 2
  set Constants = a = 0.1308996938995747, s = 0.025
end
"""


def run(exe, case, band, contrast, out):
    text = open(SCENE).read()
    mixed = case == "mixed"
    if mixed:
        text += MIXED
    if band:
        text += BAND.format(
            model="decoupled neo-Hookean" if mixed else "neo-Hookean")
    text += ("subsection Linear solver\n  set AMG for contrast = %s\nend\n"
             "subsection Output\n  set Directory = %s\n  set Base name = run\n"
             "end\n" % (contrast, out))
    prm = os.path.join(out, "scene.prm")
    with open(prm, "w") as f:
        f.write(text)
    start = time.time()
    subprocess.run([exe, prm], check=True, stdout=subprocess.DEVNULL)
    wall = time.time() - start
    rows = list(csv.DictReader(open(os.path.join(out, "run.csv"))))
    newton = sum(int(float(r["newton_iterations"])) for r in rows)
    krylov = sum(int(float(r["linear_iterations"])) for r in rows)
    return {"case": "CG + AMG" if not mixed else "mixed, block preconditioner",
            "material": "rubber + steel band" if band else "rubber",
            "AMG for contrast": contrast, "load steps": len(rows),
            "Newton iterations": newton, "Krylov iterations": krylov,
            "per Newton step": "%.1f" % (krylov / newton),
            "wall time [s]": "%.1f" % wall}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", default=os.path.join(ROOT, "build",
                                                       "hyperelastic"))
    args = parser.parse_args()
    results = []
    with tempfile.TemporaryDirectory() as tmp:
        for case, band, contrast in [("cg", False, "auto"),
                                     ("cg", True, "false"),
                                     ("cg", True, "auto"),
                                     ("mixed", False, "auto"),
                                     ("mixed", True, "false"),
                                     ("mixed", True, "auto")]:
            out = os.path.join(tmp, "%s_%d_%s" % (case, band, contrast))
            os.makedirs(out)
            results.append(run(args.exe, case, band, contrast, out))
            print(results[-1], flush=True)
    with open(os.path.join(HERE, "contrast.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(results[0].keys()))
        writer.writeheader()
        writer.writerows(results)
    ok = True
    for case in ["CG + AMG", "mixed, block preconditioner"]:
        per = {(r["material"], r["AMG for contrast"]): float(r["per Newton step"])
               for r in results if r["case"] == case}
        ratio = per[("rubber + steel band", "auto")] / per[("rubber", "auto")]
        off = per[("rubber + steel band", "false")] / per[("rubber", "auto")]
        print("%s: band / one material %.2f (AMG for contrast off: %.2f)"
              % (case, ratio, off))
        ok = ok and ratio <= 2.
    print("bound (at most 2x):", "PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()

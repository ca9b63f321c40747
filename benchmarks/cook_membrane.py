#!/usr/bin/python3
"""Cook's membrane: mesh convergence and volumetric locking.

Runs the scenes parameters/cook_membrane_2d.prm and cook_membrane_3d.prm
through build/hyperelastic (2 MPI ranks) on the meshes meshes/cook_{2,3}d_N.msh
(scripts/make-cook-meshes.sh) and reads the displacement of the reported
points from the last row of each run's CSV summary.

  /usr/bin/python3 benchmarks/cook_membrane.py            # everything (~10-15 min)
  /usr/bin/python3 benchmarks/cook_membrane.py --quick    # coarse subset (~1-2 min)
  /usr/bin/python3 benchmarks/cook_membrane.py --plot     # redraw from the CSV files
  options: --build DIR (default build), --ranks R (default 2), --full (adds
           3D P2 on N = 16, about 10 more minutes)

1. Convergence (benchmarks/cook_membrane.csv): the scenes as they are
   (nu = 0.4999) for P1 and P2 and N = 2 ... 32 (2D), 2 ... 16 (3D; P2 up
   to 8 without --full).
2. Locking sweep (benchmarks/cook_locking.csv): nu = 0.3 ... 0.4999 at fixed
   shear modulus mu = 80.194 (lambda = 2 mu nu / (1 - 2 nu)), P1 and P2, 2D
   on N = 8 and 32, 3D on N = 4 and 8; uy(48, 60) and its ratio to the P2
   value on the finest mesh of the same sweep at the same nu.

Each run is a copy of the scene in a temporary folder with a few entries set
again at its end (the last setting of an entry wins). A run that fails
(Newton, exit status 3) is recorded as failed; the script goes on.
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
MPIRUN = os.path.join(ROOT, "scripts", "mpirun.sh")
CONVERGENCE_CSV = os.path.join(HERE, "cook_membrane.csv")
LOCKING_CSV = os.path.join(HERE, "cook_locking.csv")
PLOT = os.path.join(HERE, "cook_convergence.png")

MU = 80.194  # N/mm^2, as in the scenes
NUS = [0.3, 0.4, 0.45, 0.49, 0.499, 0.4999]
# The published plane-strain reference (OpenGeoSys F-bar Q1 benchmark with
# the same data, 30 x 30 elements; de Souza Neto et al. 1996).
LITERATURE_UY = 6.89

CONVERGENCE_FIELDS = ["dim", "degree", "N", "dofs", "uy_48_60", "uy_48_52",
                      "newton_iterations", "cut_backs", "wall_time_s", "status"]
LOCKING_FIELDS = ["dim", "degree", "N", "nu", "lambda", "dofs", "uy_48_60",
                  "ratio_to_p2_finest", "newton_iterations", "cut_backs",
                  "wall_time_s", "status"]


def scene_file(dim):
    return os.path.join(ROOT, "parameters", f"cook_membrane_{dim}d.prm")


def mesh_file(dim, n):
    return os.path.join(ROOT, "meshes", f"cook_{dim}d_{n}.msh")


class Runner:
    """Runs one configuration once; the same one asked for again is reused."""

    def __init__(self, exe, ranks, workdir):
        self.exe = exe
        self.ranks = ranks
        self.workdir = workdir
        self.cache = {}

    def run(self, dim, degree, n, nu=None):
        key = (dim, degree, n, nu)
        if key in self.cache:
            return self.cache[key]
        name = f"cook_{dim}d_p{degree}_n{n}" + ("" if nu is None else f"_nu{nu}")
        overrides = (f"subsection Problem\n  set Finite element degree = {degree}\nend\n"
                     f"subsection Mesh\n  set File = {mesh_file(dim, n)}\nend\n"
                     f"subsection Output\n  set Directory = {self.workdir}\n"
                     f"  set Base name = {name}\n  set Write VTU = false\n"
                     f"  set Verbose = false\nend\n")
        if nu is not None:
            lam = 2 * MU * nu / (1 - 2 * nu)
            overrides += (f"subsection Material\n  set Elastic constants = Lame\n"
                          f"  set Shear modulus = {MU!r}\n  set Lame lambda = {lam!r}\nend\n")
        with open(scene_file(dim)) as f:
            text = f.read()
        prm = os.path.join(self.workdir, name + ".prm")
        with open(prm, "w") as f:
            f.write(text + "\n# benchmarks/cook_membrane.py\n" + overrides)

        start = time.time()
        try:
            out = subprocess.run([MPIRUN, "-np", str(self.ranks), self.exe, prm],
                                 capture_output=True, text=True, cwd=self.workdir,
                                 timeout=1800)
            returncode, log = out.returncode, out.stdout + out.stderr
        except subprocess.TimeoutExpired:
            returncode, log = None, ""
        wall = time.time() - start

        result = {"dim": dim, "degree": degree, "N": n, "dofs": "", "uy_48_60": "",
                  "uy_48_52": "", "newton_iterations": "", "cut_backs": "",
                  "wall_time_s": f"{wall:.1f}"}
        m = re.search(r"(\d+) unknowns", log)
        if m:
            result["dofs"] = int(m.group(1))
        if returncode == 0:
            with open(os.path.join(self.workdir, name + ".csv")) as f:
                rows = list(csv.DictReader(f))
            result["uy_48_60"] = float(rows[-1]["point1_uy"])
            result["uy_48_52"] = float(rows[-1]["point2_uy"])
            result["newton_iterations"] = sum(int(r["newton_iterations"]) for r in rows)
            result["cut_backs"] = sum(int(r["cut_backs"]) for r in rows)
            result["status"] = "ok"
        elif returncode == 3:
            result["status"] = "failed (convergence)"
        elif returncode is None:
            result["status"] = "failed (timeout)"
        else:
            result["status"] = f"failed (exit {returncode})"
            tail = "\n".join(log.strip().splitlines()[-5:])
            print(f"    {name}: exit status {returncode}\n{tail}", file=sys.stderr)
        print(f"  {name:28s} {result['status']:22s} uy(48,60) = {result['uy_48_60']!s:20s}"
              f" {result['dofs']!s:>6} unknowns, {wall:6.1f} s", flush=True)
        self.cache[key] = result
        return result


def fmt(x, digits=4):
    try:
        return f"{float(x):.{digits}f}"
    except ValueError:
        return str(x)


def write_csv(path, fields, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.10g}" if isinstance(v, float) else v) for k, v in r.items()})


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def print_tables(convergence, locking):
    print("\n## Cook's membrane, nu = 0.4999: uy (mm) at the top corner and the middle "
          "of the loaded edge\n")
    print("| dim | degree | N | unknowns | uy(48,60) | uy(48,52) | Newton its | wall (s) | status |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in convergence:
        print(f"| {r['dim']}D | P{r['degree']} | {r['N']} | {r['dofs']} | {fmt(r['uy_48_60'])} "
              f"| {fmt(r['uy_48_52'])} | {r['newton_iterations']} | {r['wall_time_s']} "
              f"| {r['status']} |")
    print(f"\n(3D: points at mid-thickness z = 5. Literature, plane strain: about "
          f"{LITERATURE_UY} mm.)")
    if not locking:
        return
    print("\n## Locking sweep at mu = 80.194: uy(48,60) and its ratio to P2 on the finest "
          "mesh of the sweep\n")
    configs = sorted({(r["dim"], r["N"], r["degree"]) for r in locking},
                     key=lambda c: tuple(int(x) for x in c))
    print("| nu | " + " | ".join(f"{d}D P{p} N={n}" for d, n, p in configs) + " |")
    print("|---|" + "---|" * len(configs))
    for nu in sorted({r["nu"] for r in locking}, key=float):
        cells = []
        for d, n, p in configs:
            r = next(x for x in locking if (x["dim"], x["N"], x["degree"], x["nu"]) == (d, n, p, nu))
            cells.append(f"{fmt(r['uy_48_60'], 3)} ({fmt(r['ratio_to_p2_finest'], 3)})"
                         if r["status"] == "ok" else r["status"])
        print(f"| {nu} | " + " | ".join(cells) + " |")


def plot(convergence):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is missing: no plot")
        return
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for dim, color in (("2", "tab:blue"), ("3", "tab:red")):
        for degree, style, marker in (("1", "--", "o"), ("2", "-", "s")):
            pts = sorted((int(r["dofs"]), float(r["uy_48_60"])) for r in convergence
                         if str(r["dim"]) == dim and str(r["degree"]) == degree
                         and r["status"] == "ok")
            if pts:
                ax.plot(*zip(*pts), style, marker=marker, color=color,
                        label=f"{dim}D P{degree}")
    ax.axhline(LITERATURE_UY, color="gray", lw=0.8, ls=":",
               label=f"plane strain, literature ({LITERATURE_UY})")
    ax.set_xscale("log")
    ax.set_xlabel("unknowns")
    ax.set_ylabel("uy(48, 60) [mm]")
    ax.set_title("Cook's membrane, nu = 0.4999 (3D: z = 5)")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(PLOT, dpi=120)
    print(f"\nwrote {os.path.relpath(PLOT, ROOT)}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="coarse subset")
    parser.add_argument("--full", action="store_true", help="also 3D P2 on N = 16")
    parser.add_argument("--plot", action="store_true", help="only redraw from the CSV files")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"),
                        help="build folder with the hyperelastic executable")
    parser.add_argument("--ranks", type=int, default=2)
    args = parser.parse_args()

    if args.plot:
        convergence = read_csv(CONVERGENCE_CSV)
        locking = read_csv(LOCKING_CSV) if os.path.exists(LOCKING_CSV) else []
        print_tables(convergence, locking)
        plot(convergence)
        return

    exe = os.path.join(os.path.abspath(args.build), "hyperelastic")
    if not os.access(exe, os.X_OK):
        sys.exit(f"{exe} not found: build first (scripts/build.sh) or pass --build")
    for dim, sizes in ((2, (2, 4, 8, 16, 32)), (3, (2, 4, 8, 16))):
        for n in sizes:
            if not os.path.exists(mesh_file(dim, n)):
                sys.exit(f"{mesh_file(dim, n)} is missing: run scripts/make-cook-meshes.sh")

    if args.quick:
        plan = {(2, 1): [2, 4, 8], (2, 2): [2, 4, 8], (3, 1): [2, 4], (3, 2): [2, 4]}
        sweep = {2: [4, 8], 3: [2]}
        nus = [0.3, 0.49, 0.4999]
    else:
        plan = {(2, 1): [2, 4, 8, 16, 32], (2, 2): [2, 4, 8, 16, 32],
                (3, 1): [2, 4, 8, 16], (3, 2): [2, 4, 8] + ([16] if args.full else [])}
        sweep = {2: [8, 32], 3: [4, 8]}
        nus = NUS

    with tempfile.TemporaryDirectory(prefix="cook_membrane_") as workdir:
        runner = Runner(exe, args.ranks, workdir)
        print("Convergence, nu = 0.4999:")
        convergence = [runner.run(dim, degree, n)
                       for (dim, degree), sizes in plan.items() for n in sizes]
        write_csv(CONVERGENCE_CSV, CONVERGENCE_FIELDS, convergence)

        print("Locking sweep, mu = 80.194:")
        locking = []
        for dim, sizes in sweep.items():
            for nu in nus:
                # At nu = 0.4999 the sweep's material is the scene's own.
                runs = {(degree, n): runner.run(dim, degree, n, None if nu == 0.4999 else nu)
                        for degree in (1, 2) for n in sizes}
                reference = runs[(2, max(sizes))]
                for (degree, n), r in runs.items():
                    row = dict(r, nu=nu, **{"lambda": 2 * MU * nu / (1 - 2 * nu)})
                    row["ratio_to_p2_finest"] = (
                        r["uy_48_60"] / reference["uy_48_60"]
                        if r["status"] == "ok" and reference["status"] == "ok" else "")
                    locking.append(row)
        write_csv(LOCKING_CSV, LOCKING_FIELDS, locking)

    convergence = read_csv(CONVERGENCE_CSV)
    locking = read_csv(LOCKING_CSV)
    print(f"\nwrote {os.path.relpath(CONVERGENCE_CSV, ROOT)} and "
          f"{os.path.relpath(LOCKING_CSV, ROOT)}")
    print_tables(convergence, locking)
    plot(convergence)


if __name__ == "__main__":
    main()

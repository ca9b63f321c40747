#!/usr/bin/python3
"""Benchmark of the mixed displacement-pressure formulation (3D cantilever).

Writes scene files into a scratch folder, runs build/hyperelastic on 2 MPI
ranks (one run at a time), parses each run's CSV summary and the timing table
on stdout, and writes CSV files and PNG plots next to this script.

  /usr/bin/python3 benchmarks/mixed/run.py           # all three series (~30-45 min)
  /usr/bin/python3 benchmarks/mixed/run.py --quick   # a small subset (< 1 min),
                                                     # written to the scratch folder
  /usr/bin/python3 benchmarks/mixed/run.py --plot    # redraw the figures and print
                                                     # the tables from the CSV files

Scene: the bar [0,4] x [0,1] x [0,1] of 4n x n x n boxes (5 tetrahedra each),
decoupled neo-Hookean, E = 1, clamped at x = 0, dead traction (0, 0.001 t, 0)
on x = 4, 2 load steps, quantity of interest: the tip deflection uy at the
corner (4, 1, 1).

Series:
  1. nu    -> mixed_nu.csv, mixed_nu.png: n = 4, nu = 0.3 ... 0.49999, each
              mixed element, GMRES + block preconditioner; once with the
              default inexact Newton (Eisenstat-Walker forcing terms) and once
              with every Krylov solve to the fixed relative tolerance 1e-8.
  2. size  -> mixed_size.csv, mixed_size.png: nu = 0.4999, growing n, each
              mixed element (default inexact Newton); a size is skipped when
              its predicted time exceeds the per-run or the series budget.
  3. work-precision -> mixed_work_precision.csv, mixed_work_precision.png:
              nu = 0.4999, error of the tip deflection against the finest
              P2/P1 run (the reference), mixed elements (iterative, the runs
              of series 2 are reused) and the displacement-only P2
              formulation with the direct solver (Amesos_Mumps).
Every run is also listed in mixed_runs.csv.
"""
import argparse
import csv
import math
import os
import re
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
EXE = os.path.join(ROOT, "build", "hyperelastic")
MPIRUN = os.path.join(ROOT, "scripts", "mpirun.sh")
GNU_TIME = "/usr/bin/time"
RANKS = 2

TRACTION = 0.001        # force per reference area on x = 4, times t
LOAD_STEPS = 2
NU_SERIES = [0.3, 0.45, 0.49, 0.499, 0.4999, 0.49999]
NU_HIGH = 0.4999        # series 2 and 3

ELEMENTS = ["P1-bubble/P1", "P1/P1 stabilized", "P2/P1"]
SHORT = {"P1-bubble/P1": "MINI", "P1/P1 stabilized": "P1P1stab", "P2/P1": "TH",
         "displacement P2 (direct)": "dispP2"}
COLORS = {"P1-bubble/P1": "tab:blue", "P1/P1 stabilized": "tab:orange",
          "P2/P1": "tab:green", "displacement P2 (direct)": "tab:red"}

# Series 2: sizes n (4n x n x n boxes) per element, from about 1e4 unknowns.
# P1 mixed: 4 (4n+1)(n+1)^2 unknowns (n = 32: 561,924); P2/P1 n = 16: ~4.4e5.
# P1/P1 stabilized n = 40: 1,082,564 unknowns (the 1e6 target; about
# 12 min and 4 GB per rank, so it needs --size-cap 1500 --series-budget 3600).
SIZES = {"P1/P1 stabilized": [8, 12, 16, 24, 32, 40],
         "P2/P1": [4, 6, 8, 12],
         "P1-bubble/P1": [8, 12, 16, 20, 24]}
SIZE_RUN_CAP = 360.0      # s: skip a size predicted to take longer
SIZE_SERIES_BUDGET = 900.0  # s: for all of series 2
# Series 3 (runs of series 2 are reused where the size matches).
WP_SIZES = {"P1-bubble/P1": [4, 8, 12, 16],
            "P1/P1 stabilized": [8, 16, 24, 32],
            "P2/P1": [4, 6, 8, 12]}
WP_DISP_SIZES = [2, 4, 6, 8]
WP_DISP_CAP = 360.0
REFERENCE_N = 16          # P2/P1 reference, if predicted under REFERENCE_CAP
REFERENCE_CAP = 600.0
TOTAL_BUDGET = 45 * 60.0  # s: optional runs are skipped beyond this

QUICK = dict(nu=[0.3, 0.4999], nu_n=2,
             sizes={"P1/P1 stabilized": [2, 4], "P2/P1": [1, 2], "P1-bubble/P1": [2, 3]},
             wp_sizes={"P1-bubble/P1": [2, 3], "P1/P1 stabilized": [2, 4], "P2/P1": [1]},
             wp_disp=[1, 2], reference_n=2)

FILES = dict(nu="mixed_nu", size="mixed_size", wp="mixed_work_precision", runs="mixed_runs")

SECTIONS = {"assembly": "t_assembly", "line search": "t_line_search",
            "linear solve": "t_linear_solve", "mesh and setup": "t_setup",
            "preconditioner setup": "t_preconditioner", "residual": "t_residual",
            "postprocessing": "t_output"}

RUN_FIELDS = ["name", "series", "method", "formulation", "element", "solver", "inexact_newton",
              "nu", "n", "cells", "unknowns", "status", "exit_code", "load_steps", "cut_backs",
              "newton_iterations", "linear_solves", "krylov_iterations", "krylov_per_newton",
              "line_search_backtracks", "tip_ux", "tip_uy", "tip_uz", "min_J",
              "t_total", "t_setup", "t_assembly", "t_residual", "t_line_search",
              "t_preconditioner", "t_linear_solve", "t_output", "t_elapsed",
              "peak_rss_mb", "loadavg_before"]


def method_of(cfg):
    if cfg["formulation"] == "displacement":
        return "displacement P%d (%s)" % (cfg["degree"], cfg["solver"])
    return cfg["element"]


def run_name(cfg):
    if cfg["formulation"] == "displacement":
        head = "disp_P%d" % cfg["degree"]
    else:
        head = "mixed_" + SHORT[cfg["element"]]
    return "%s_n%d_nu%s_%s%s" % (head, cfg["n"], repr(cfg["nu"]), cfg["solver"],
                                 "" if cfg["inexact"] else "_exact")


def scene_text(cfg, out_dir, base):
    n = cfg["n"]
    if cfg["formulation"] == "mixed":
        problem = "  set Formulation   = mixed\n  set Mixed element = %s\n" % cfg["element"]
    else:
        problem = ("  set Formulation           = displacement\n"
                   "  set Finite element degree = %d\n" % cfg["degree"])
    if cfg["solver"] == "direct":
        solver = "  set Type          = direct\n  set Direct solver = Amesos_Mumps\n"
    else:
        solver = "  set Type               = CG with AMG\n  set Relative tolerance = 1e-8\n"
    return f"""# written by benchmarks/mixed/run.py: {run_name(cfg)}
subsection Problem
  set Dimension     = 3
{problem}end

subsection Mesh
  set Source       = box
  set Lower corner = 0, 0, 0
  set Upper corner = 4, 1, 1
  set Subdivisions = {4 * n}, {n}, {n}
end

subsection Material
  set Model             = decoupled neo-Hookean
  set Elastic constants = Young's modulus and Poisson's ratio
  set Young's modulus   = 1
  set Poisson's ratio   = {cfg["nu"]!r}
end

subsection Loading
  set Number of load steps = {LOAD_STEPS}
end

subsection Dirichlet 1
  set Boundary id  = 0
  set Components   = x, y, z
  set Displacement = 0; 0; 0
end

subsection Traction 1
  set Boundary id = 1
  set Traction    = 0; {TRACTION!r}*t; 0
end

subsection Newton
  set Inexact Newton = {"true" if cfg["inexact"] else "false"}
end

subsection Linear solver
{solver}end

subsection Output
  set Directory = {out_dir}
  set Base name = {base}
  set Write VTU = false
  set Points    = 4, 1, 1
  set Verbose   = false
end
"""


def parse_stdout(text, result):
    m = re.search(r"(\d+) cells, (\d+) unknowns", text)
    if m:
        result["cells"], result["unknowns"] = int(m.group(1)), int(m.group(2))
    m = re.search(r"Total wallclock time elapsed since start\s*\|\s*([0-9.eE+-]+)\s*s", text)
    if m:
        result["t_total"] = float(m.group(1))
    for line in text.splitlines():
        m = re.match(r"\|\s*([a-z ]+?)\s*\|\s*(\d+)\s*\|\s*([0-9.eE+-]+)\s*s\s*\|", line)
        if m and m.group(1) in SECTIONS:
            result[SECTIONS[m.group(1)]] = float(m.group(3))
            if m.group(1) == "linear solve":
                # one solve per Newton iteration, failed (cut-back) attempts included
                result["linear_solves"] = int(m.group(2))


def parse_csv(path, result):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return
    newton = sum(int(r["newton_iterations"]) for r in rows)
    krylov = sum(int(r["linear_iterations"]) for r in rows)
    last = rows[-1]
    result.update(load_steps=len(rows), newton_iterations=newton, krylov_iterations=krylov,
                  krylov_per_newton=krylov / newton if newton else float("nan"),
                  cut_backs=sum(int(r["cut_backs"]) for r in rows),
                  line_search_backtracks=sum(int(r["line_search_backtracks"]) for r in rows),
                  tip_ux=float(last["point1_ux"]), tip_uy=float(last["point1_uy"]),
                  tip_uz=float(last["point1_uz"]),
                  min_J=min(float(r["min_J"]) for r in rows))
    if abs(float(last["load_factor"]) - 1.0) > 1e-12:
        result["status"] = "stopped at t = %s" % last["load_factor"]


class Runner:
    """Runs scenes one at a time; a run already done (same name) is reused."""

    def __init__(self, scratch, reuse=()):
        self.scratch = scratch
        self.done = {r["name"]: r for r in reuse}
        for r in reuse:  # fields added to the parser since (the logs are kept)
            log = os.path.join(scratch, r["name"] + ".out")
            if os.path.exists(log):
                parse_stdout(open(log).read(), r)
        self.start = time.time()
        os.makedirs(scratch, exist_ok=True)

    def elapsed(self):
        return time.time() - self.start

    def has(self, cfg):
        return run_name(cfg) in self.done

    def run(self, cfg, series, timeout=None):
        name = run_name(cfg)
        if name in self.done:
            return self.done[name]
        out_dir = os.path.join(self.scratch, name)
        os.makedirs(out_dir, exist_ok=True)
        prm = os.path.join(self.scratch, name + ".prm")
        with open(prm, "w") as f:
            f.write(scene_text(cfg, out_dir, "run"))
        csv_path = os.path.join(out_dir, "run.csv")
        if os.path.exists(csv_path):
            os.remove(csv_path)
        time_file = os.path.join(self.scratch, name + ".time")
        command = [MPIRUN, "-np", str(RANKS), EXE, prm]
        if os.path.exists(GNU_TIME):
            command = [GNU_TIME, "-v", "-o", time_file] + command
        result = dict(name=name, series=series, method=method_of(cfg),
                      formulation=cfg["formulation"],
                      element=cfg.get("element", "P%d" % cfg.get("degree", 1)),
                      solver=cfg["solver"], inexact_newton=cfg["inexact"], nu=cfg["nu"],
                      n=cfg["n"], status="ok",
                      loadavg_before=float(open("/proc/loadavg").read().split()[0]))
        print("  %-48s" % name, end="", flush=True)
        t0 = time.time()
        proc = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                text=True, cwd=self.scratch, start_new_session=True)
        try:
            stdout, stderr = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGTERM)  # the process group this script started
            try:
                stdout, stderr = proc.communicate(timeout=30)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                stdout, stderr = proc.communicate()
            result["status"] = "timeout after %.0f s" % timeout
        result["t_elapsed"] = time.time() - t0
        result["exit_code"] = proc.returncode
        with open(os.path.join(self.scratch, name + ".out"), "w") as f:
            f.write(stdout + "\n--- stderr ---\n" + stderr)
        parse_stdout(stdout, result)
        if os.path.exists(csv_path):
            parse_csv(csv_path, result)
        if proc.returncode != 0 and result["status"] == "ok":
            result["status"] = "failed (exit %d)" % proc.returncode
        if os.path.exists(time_file):
            m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", open(time_file).read())
            if m:
                result["peak_rss_mb"] = int(m.group(1)) / 1024.0
        if "t_total" not in result:
            result["t_total"] = result["t_elapsed"]
        print("%9s unknowns  %4s Newton  %6.1f Krylov/Newton  %8.2f s  %s" % (
            result.get("unknowns", "?"), result.get("newton_iterations", "?"),
            result.get("krylov_per_newton", float("nan")), result["t_total"],
            result["status"]), flush=True)
        self.done[name] = result
        return result


def load_runs(path):
    """Successful runs of an earlier invocation (mixed_runs.csv), typed as run() returns them."""
    if not os.path.exists(path):
        return []
    runs = []
    for row in read_csv(path):
        if row["status"] != "ok":
            continue
        r = {}
        for k, v in row.items():
            if v == "":
                continue
            if k in ("name", "series", "method", "formulation", "element", "solver", "status"):
                r[k] = v
            elif k == "inexact_newton":
                r[k] = v == "True"
            elif k in ("n", "cells", "unknowns", "exit_code", "load_steps", "cut_backs",
                       "linear_solves",
                       "newton_iterations", "krylov_iterations", "line_search_backtracks"):
                r[k] = int(v)
            else:
                r[k] = float(v)
        runs.append(r)
    return runs


def mixed_cfg(element, n, nu, inexact=True):
    return dict(formulation="mixed", element=element, n=n, nu=nu, solver="iterative",
                inexact=inexact)


def disp_cfg(n, nu):
    return dict(formulation="displacement", degree=2, n=n, nu=nu, solver="direct",
                inexact=True)


def predict(done_runs, n, exponent):
    """Time of size n from the largest smaller run: cells ~ n^3, time ~ cells^exponent."""
    smaller = [r for r in done_runs if r["n"] < n and r["status"] == "ok"]
    if not smaller:
        return 0.0
    last = max(smaller, key=lambda r: r["n"])
    return last["t_total"] * ((n / last["n"]) ** 3) ** exponent


def write_csv(path, rows, fields):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: fmt(r.get(k, "")) for k in fields})


def fmt(v):
    if isinstance(v, float):
        return "%.10g" % v
    return v


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


NU_FIELDS = ["element", "nu", "inexact_newton", "n", "unknowns", "load_steps", "cut_backs",
             "newton_iterations", "linear_solves", "krylov_iterations", "krylov_per_newton", "t_total",
             "tip_uy", "peak_rss_mb", "status"]
SIZE_FIELDS = ["element", "n", "cells", "unknowns", "load_steps", "cut_backs",
               "newton_iterations", "linear_solves", "krylov_iterations", "krylov_per_newton", "t_total",
               "t_assembly", "t_residual", "t_line_search", "t_preconditioner",
               "t_linear_solve", "peak_rss_mb", "tip_uy", "loadavg_before", "status"]
WP_FIELDS = ["method", "n", "unknowns", "load_steps", "cut_backs", "newton_iterations",
             "linear_solves", "krylov_per_newton", "t_total",
             "peak_rss_mb", "tip_uy", "reference_uy", "rel_error", "is_reference",
             "extrapolated_uy", "extrapolation_order", "rel_error_extrapolated", "status"]


def series_nu(runner, nus, n):
    print("series 1: Krylov iterations against nu (n = %d)" % n)
    rows = []
    for inexact in (True, False):
        for element in ELEMENTS:
            for nu in nus:
                rows.append(runner.run(mixed_cfg(element, n, nu, inexact), "nu"))
    return rows


def series_size(runner, sizes):
    print("series 2: against size (nu = %g)" % NU_HIGH)
    rows, t_series = [], 0.0
    for element in ["P1/P1 stabilized", "P2/P1", "P1-bubble/P1"]:
        done = []
        for n in sizes.get(element, []):
            cfg = mixed_cfg(element, n, NU_HIGH)
            guess = 0.0 if runner.has(cfg) else predict(done, n, 1.15)
            if runner.has(cfg):
                pass  # already run (--reuse, or by an earlier series): costs nothing now
            elif guess > SIZE_RUN_CAP or t_series + guess > SIZE_SERIES_BUDGET \
                    or runner.elapsed() + guess > TOTAL_BUDGET:
                print("  skip %s n = %d: predicted %.0f s" % (element, n, guess))
                continue
            r = runner.run(cfg, "size", timeout=2 * SIZE_RUN_CAP)
            t_series += r["t_total"]
            done.append(r)
            rows.append(r)
    return rows


def series_wp(runner, wp_sizes, disp_sizes, reference_n):
    print("series 3: work-precision (nu = %g)" % NU_HIGH)
    runs = []
    for element in ELEMENTS:
        done = []
        for n in wp_sizes[element]:
            cfg = mixed_cfg(element, n, NU_HIGH)
            guess = 0.0 if runner.has(cfg) else predict(done, n, 1.15)
            if guess > SIZE_RUN_CAP or runner.elapsed() + guess > TOTAL_BUDGET:
                print("  skip %s n = %d: predicted %.0f s" % (element, n, guess))
                continue
            r = runner.run(cfg, "wp", timeout=2 * SIZE_RUN_CAP)
            done.append(r)
            runs.append(r)
    done = []
    for n in disp_sizes:
        cfg = disp_cfg(n, NU_HIGH)
        guess = 0.0 if runner.has(cfg) else predict(done, n, 2.0)
        if guess > WP_DISP_CAP or runner.elapsed() + guess > TOTAL_BUDGET:
            print("  skip displacement P2 n = %d: predicted %.0f s" % (n, guess))
            continue
        r = runner.run(cfg, "wp", timeout=2 * WP_DISP_CAP)
        done.append(r)
        runs.append(r)
    # Reference: the finest P2/P1 run that can be afforded.
    th = [r for r in runner.done.values() if r["element"] == "P2/P1" and r["nu"] == NU_HIGH
          and r["inexact_newton"] and r["status"] == "ok"]
    guess = predict(th, reference_n, 1.15)
    finest = max([r["n"] for r in th] or [0])
    if reference_n > finest and guess <= REFERENCE_CAP \
            and runner.elapsed() + guess <= TOTAL_BUDGET:
        th.append(runner.run(mixed_cfg("P2/P1", reference_n, NU_HIGH), "reference",
                             timeout=2 * REFERENCE_CAP))
    elif reference_n > finest:
        print("  skip reference P2/P1 n = %d: predicted %.0f s" % (reference_n, guess))
    th = [r for r in th if r["status"] == "ok"]
    if not th:
        print("  no P2/P1 run succeeded: no reference, no errors")
        return runs
    ref = max(th, key=lambda r: r["n"])
    extrapolated = richardson(th)
    rows, seen = [], set()
    for r in runs + [ref]:
        if r["name"] in seen:
            continue
        seen.add(r["name"])
        row = dict(r)
        row["reference_uy"] = ref["tip_uy"]
        row["is_reference"] = r is ref
        if r["status"] == "ok" and "tip_uy" in r:
            row["rel_error"] = abs(r["tip_uy"] - ref["tip_uy"]) / abs(ref["tip_uy"])
            if extrapolated:
                row["extrapolated_uy"], row["extrapolation_order"] = extrapolated
                row["rel_error_extrapolated"] = (abs(r["tip_uy"] - extrapolated[0])
                                                 / abs(extrapolated[0]))
        rows.append(row)
    print("  reference: P2/P1 n = %d, %d unknowns, tip uy = %.10g"
          % (ref["n"], ref["unknowns"], ref["tip_uy"]))
    if extrapolated:
        print("  Richardson extrapolation of the three finest P2/P1 runs: %.10g (order %.2f); "
              "the reference's own relative error: %.2e"
              % (extrapolated[0], extrapolated[1],
                 abs(ref["tip_uy"] - extrapolated[0]) / abs(extrapolated[0])))
    return rows


def richardson(runs):
    """(limit, order) of u(h) = u0 + C h^p through the three finest runs (h = 1/n)."""
    runs = sorted(runs, key=lambda r: r["n"])[-3:]
    if len(runs) < 3:
        return None
    (n1, u1), (n2, u2), (n3, u3) = [(r["n"], r["tip_uy"]) for r in runs]
    if (u2 - u1) * (u3 - u2) <= 0:
        return None  # not monotone: no asymptotic range

    def ratio(p):
        return (n1 ** -p - n2 ** -p) / (n2 ** -p - n3 ** -p)

    target = (u2 - u1) / (u3 - u2)
    lo, hi = 0.05, 8.0
    if not ratio(lo) < target < ratio(hi):
        return None
    for _ in range(200):  # ratio(p) increases with p
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if ratio(mid) < target else (lo, mid)
    p = 0.5 * (lo + hi)
    c = (u3 - u2) / (n2 ** -p - n3 ** -p)
    return u3 + c * n3 ** -p, p


# ---------------------------------------------------------------- plots


def num(row, key):
    try:
        return float(row[key])
    except (KeyError, TypeError, ValueError):
        return float("nan")


def plot_all(out_dir, stem_suffix=""):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def path(key, ext):
        return os.path.join(out_dir, FILES[key] + stem_suffix + "." + ext)

    if os.path.exists(path("nu", "csv")):
        rows = [r for r in read_csv(path("nu", "csv")) if r["status"] == "ok"]
        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        for element in ELEMENTS:
            for inexact, style, label in (("False", "-o", "Krylov tol 1e-8"),
                                          ("True", "--s", "inexact Newton (default)")):
                sel = sorted((r for r in rows if r["element"] == element
                              and r["inexact_newton"] == inexact), key=lambda r: num(r, "nu"))
                if sel:
                    ax.plot([0.5 - num(r, "nu") for r in sel],
                            [num(r, "krylov_per_newton") for r in sel], style,
                            color=COLORS[element], label="%s, %s" % (element, label))
        ax.set_xscale("log")
        ax.invert_xaxis()
        ax.set_xlabel("0.5 - nu  (nu = 0.3 ... 0.49999)")
        ax.set_ylabel("Krylov iterations per Newton step")
        top = max([num(r, "krylov_per_newton") for r in rows] or [1.0])
        ax.set_ylim(0, 1.45 * top)  # room for the legend above the curves
        n = int(rows[0]["n"]) if rows else 4
        ax.set_title("3D cantilever %dx%dx%d boxes, GMRES + block preconditioner, 2 ranks"
                     % (4 * n, n, n), fontsize=10)
        ax.legend(fontsize=7, ncol=2, loc="upper center")
        ax.grid(True, which="both", alpha=0.3)
        fig.tight_layout()
        fig.savefig(path("nu", "png"), dpi=120)
        plt.close(fig)

    if os.path.exists(path("size", "csv")):
        rows = [r for r in read_csv(path("size", "csv")) if r["status"] == "ok"]
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.4))
        for element in ELEMENTS:
            sel = sorted((r for r in rows if r["element"] == element), key=lambda r: num(r, "unknowns"))
            if not sel:
                continue
            x = [num(r, "unknowns") for r in sel]
            ax1.plot(x, [num(r, "krylov_per_newton") for r in sel], "-o",
                     color=COLORS[element], label=element)
            ax2.plot(x, [num(r, "t_total") for r in sel], "-o", color=COLORS[element],
                     label=element)
        ax1.set_xscale("log")
        ax1.set_ylim(bottom=0)
        ax1.set_xlabel("unknowns")
        ax1.set_ylabel("Krylov iterations per Newton step")
        ax1.set_title("nu = 0.4999, inexact Newton (default)")
        ax2.set_xscale("log")
        ax2.set_yscale("log")
        ax2.set_xlabel("unknowns")
        ax2.set_ylabel("total wall time [s] (2 ranks)")
        xs = [num(r, "unknowns") for r in rows]
        if xs:
            x0 = min(xs)
            t0 = min(num(r, "t_total") for r in rows if num(r, "unknowns") == x0)
            ax2.plot([x0, max(xs)], [t0, t0 * max(xs) / x0], ":", color="gray",
                     label="linear in unknowns")
        ax2.set_title("wall time")
        for ax in (ax1, ax2):
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(path("size", "png"), dpi=120)
        plt.close(fig)

    if os.path.exists(path("wp", "csv")):
        all_rows = [r for r in read_csv(path("wp", "csv")) if r["status"] == "ok"]
        ref = [r for r in all_rows if r["is_reference"] == "True"]
        panels = [("rel_error", "relative error against the reference")]
        if any(r.get("rel_error_extrapolated") for r in all_rows):
            panels.append(("rel_error_extrapolated",
                           "relative error against the extrapolated limit"))
        fig, axes = plt.subplots(1, len(panels), figsize=(6.0 * len(panels), 4.8), squeeze=False)
        for ax, (key, xlabel) in zip(axes[0], panels):
            for method in ELEMENTS + ["displacement P2 (direct)"]:
                sel = sorted((r for r in all_rows if r["method"] == method and r.get(key)
                              and num(r, key) > 0), key=lambda r: num(r, "unknowns"))
                if not sel:
                    continue
                ax.plot([num(r, key) for r in sel], [num(r, "t_total") for r in sel], "-o",
                        color=COLORS[method],
                        label=method + ("" if "direct" in method else " (GMRES)"))
                for r in sel:
                    ax.annotate("n=%s" % r["n"], (num(r, key), num(r, "t_total")),
                                fontsize=6, xytext=(3, 3), textcoords="offset points")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.invert_xaxis()
            ax.set_xlabel(xlabel + ", tip uy(4, 1, 1)", fontsize=9)
            ax.set_ylabel("total wall time [s] (2 ranks)")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=8)
        if ref:
            axes[0][0].set_title("nu = 0.4999; reference: P2/P1 n = %s (%s unknowns), uy = %.6f"
                                 % (ref[0]["n"], ref[0]["unknowns"], num(ref[0], "tip_uy")),
                                 fontsize=8)
            if len(panels) > 1:
                axes[0][1].set_title("Richardson limit of the 3 finest P2/P1: uy = %.6f (order %.2f)"
                                     % (num(ref[0], "extrapolated_uy"),
                                        num(ref[0], "extrapolation_order")), fontsize=8)
        fig.tight_layout()
        fig.savefig(path("wp", "png"), dpi=120)
        plt.close(fig)


def print_tables(out_dir, stem_suffix=""):
    """Markdown tables of the CSV files (pasted into README.md)."""
    def path(key):
        return os.path.join(out_dir, FILES[key] + stem_suffix + ".csv")

    def g(row, key, spec):
        v = num(row, key)
        return "-" if math.isnan(v) else spec % v

    if os.path.exists(path("nu")):
        rows = read_csv(path("nu"))
        print("\nKrylov iterations per Newton step (Newton iterations in parentheses):\n")
        nus = sorted({r["nu"] for r in rows}, key=float)
        print("| element | Newton | " + " | ".join("nu = %s" % nu for nu in nus) + " |")
        print("|---|---|" + "---|" * len(nus))
        for inexact, label in (("False", "Krylov tol 1e-8"), ("True", "inexact (default)")):
            for element in ELEMENTS:
                cells = []
                for nu in nus:
                    sel = [r for r in rows if r["element"] == element and r["nu"] == nu
                           and r["inexact_newton"] == inexact]
                    if not sel:
                        cells.append("")
                    elif sel[0]["status"] != "ok":
                        cells.append(sel[0]["status"])
                    else:
                        cells.append("%s (%s)" % (g(sel[0], "krylov_per_newton", "%.1f"),
                                                  sel[0]["newton_iterations"]))
                if any(cells):
                    print("| %s | %s | %s |" % (element, label, " | ".join(cells)))
    def newton(r):
        """Newton iterations of the converged attempts, plus all attempts if cut-backs."""
        text = r["newton_iterations"]
        if r.get("linear_solves") and r["linear_solves"] != r["newton_iterations"]:
            text += " (%s)" % r["linear_solves"]
        return text

    def unknowns(r):
        return "{:,}".format(int(num(r, "unknowns"))) if r["unknowns"] else "-"

    if os.path.exists(path("size")):
        rows = read_csv(path("size"))
        print("\n| element | n | unknowns | Newton | Krylov / Newton | total [s] | linear solve [s] "
              "| assembly + residual + line search [s] | peak RSS [MB] | tip uy | load avg | status |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|")
        for r in rows:
            other = num(r, "t_assembly") + num(r, "t_residual") + num(r, "t_line_search")
            print("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                r["element"], r["n"], unknowns(r), newton(r),
                g(r, "krylov_per_newton", "%.1f"), g(r, "t_total", "%.3g"),
                g(r, "t_linear_solve", "%.3g"),
                "-" if math.isnan(other) else "%.3g" % other,
                g(r, "peak_rss_mb", "%.0f"), g(r, "tip_uy", "%.6f"),
                g(r, "loadavg_before", "%.1f"), r["status"]))
    if os.path.exists(path("wp")):
        rows = read_csv(path("wp"))
        print("\n| method | n | unknowns | load steps | Newton | Krylov / Newton | total [s] "
              "| peak RSS [MB] | tip uy | rel. error vs reference | rel. error vs extrapolation |")
        print("|---|---|---|---|---|---|---|---|---|---|---|")
        for r in rows:
            err = "reference" if r["is_reference"] == "True" else g(r, "rel_error", "%.2e")
            steps = r["load_steps"] + (" (%s cut-backs)" % r["cut_backs"]
                                       if r["cut_backs"] not in ("", "0") else "")
            print("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                r["method"], r["n"], unknowns(r), steps, newton(r),
                "-" if "direct" in r["method"] else g(r, "krylov_per_newton", "%.1f"),
                g(r, "t_total", "%.3g"), g(r, "peak_rss_mb", "%.0f"),
                g(r, "tip_uy", "%.8f"), err, g(r, "rel_error_extrapolated", "%.2e")))


def main():
    global SIZE_RUN_CAP, SIZE_SERIES_BUDGET, TOTAL_BUDGET
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true",
                        help="small subset (< 1 min); CSV and PNG go to the scratch folder")
    parser.add_argument("--plot", action="store_true",
                        help="only redraw the figures and print the tables from the CSV files")
    parser.add_argument("--scratch", default="/tmp/mixed_bench",
                        help="folder for scenes, run output and logs (default /tmp/mixed_bench)")
    parser.add_argument("--reuse", action="store_true",
                        help="reuse the successful runs listed in the existing mixed_runs.csv "
                             "and run only the missing ones")
    parser.add_argument("--size-cap", type=float, default=SIZE_RUN_CAP,
                        help="series 2: skip sizes predicted to take longer (s, default %(default)s)")
    parser.add_argument("--series-budget", type=float, default=SIZE_SERIES_BUDGET,
                        help="series 2: time for all its new runs (s, default %(default)s); "
                             "raises the total budget to match")
    parser.add_argument("--only", choices=["nu", "size", "wp"], action="append",
                        help="run only these series (repeatable; default all)")
    args = parser.parse_args()

    scratch = os.path.join(args.scratch, "quick" if args.quick else "full")
    out_dir = scratch if args.quick else HERE
    if args.plot:
        plot_all(out_dir)
        print_tables(out_dir)
        return
    for f in (EXE, MPIRUN):
        if not os.path.exists(f):
            sys.exit("missing %s (build first: scripts/build.sh)" % f)

    SIZE_RUN_CAP = args.size_cap
    SIZE_SERIES_BUDGET = args.series_budget
    TOTAL_BUDGET = max(TOTAL_BUDGET, 2 * SIZE_SERIES_BUDGET)
    series = set(args.only or ["nu", "size", "wp"])
    reuse = load_runs(os.path.join(out_dir, FILES["runs"] + ".csv")) if args.reuse else []
    runner = Runner(scratch, reuse)
    if args.quick:
        nus, nu_n = QUICK["nu"], QUICK["nu_n"]
        sizes, wp_sizes, wp_disp, ref_n = (QUICK["sizes"], QUICK["wp_sizes"],
                                           QUICK["wp_disp"], QUICK["reference_n"])
    else:
        nus, nu_n, sizes, wp_sizes, wp_disp, ref_n = (NU_SERIES, 4, SIZES, WP_SIZES,
                                                      WP_DISP_SIZES, REFERENCE_N)

    def out(key):
        return os.path.join(out_dir, FILES[key] + ".csv")

    if "nu" in series:
        write_csv(out("nu"), series_nu(runner, nus, nu_n), NU_FIELDS)
    if "size" in series:
        write_csv(out("size"), series_size(runner, sizes), SIZE_FIELDS)
    if "wp" in series:
        write_csv(out("wp"), series_wp(runner, wp_sizes, wp_disp, ref_n), WP_FIELDS)
    write_csv(os.path.join(out_dir, FILES["runs"] + ".csv"), list(runner.done.values()),
              RUN_FIELDS)
    print("all runs: %.0f s" % runner.elapsed())
    try:
        plot_all(out_dir)
    except ImportError:
        print("matplotlib missing (apt-get install -y python3-matplotlib): no plots")
    print_tables(out_dir)
    failed = [r for r in runner.done.values() if r["status"] != "ok"]
    for r in failed:
        print("FAILED: %s: %s (log %s.out in %s)" % (r["name"], r["status"], r["name"], scratch))
    print("results in", out_dir)


if __name__ == "__main__":
    main()

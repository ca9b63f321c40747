#!/usr/bin/python3
"""The shallow ironing benchmark (issue 57, item 6) against the published
curves of five codes (reference_forces.csv: Yastrebov 2011, Code_Aster
SSNP153, Hartmann-Oliver, Fischer-Wriggers, Poulios-Renard, as digitised by
solids4foam's hyperElasticity/shallowIroning).

The scene is parameters/shallow_ironing_2d.prm (the slab pressed 1 mm into
the foundation, then slid 10 mm; neo-Hookean; self contact between the two
bodies of one mesh) with the mesh of meshes/shallow_ironing_2d.geo at
contact-edge size H (generated into build/benchmark_meshes/), N equal load
steps and the friction coefficient MU; 2 MPI ranks, default solver settings.
The load factor t is the references' time halved, T = 2 t.

  /usr/bin/python3 benchmarks/ironing/run.py --label NAME [--exe BUILD/hyperelastic]
        [--h 0.1] [--steps 400] [--mu 0.3,0]
  /usr/bin/python3 benchmarks/ironing/run.py --plot    # redraw ironing.png (finest h of each mu)
  /usr/bin/python3 benchmarks/ironing/run.py --table   # ironing.csv as tables
  /usr/bin/python3 benchmarks/ironing/run.py --summarise-again  # ironing.csv from runs/

Each run keeps its forces and solver counts per row in runs/ (LABEL_hH_nN_muMU.csv)
and replaces its row of ironing.csv (same label, h, steps, mu):
  with friction: Fx and Fy on the slab's top at T = 0.5, 0.7, ..., 1.9
    (interpolated between rows; Fx along the slide, Fy pressing down), how
    many of them lie in the envelope of the five codes, the global friction
    coefficient mu_g = |Fx|/|Fy| at T = 1.5 (Code_Aster 0.34, solids4foam 0.36);
  both: mean and max |Fx|/|Fy| over the rows where the slab is at least 3 mm
    from both ends of the foundation (T in [1.28, 1.76]; without friction it
    should vanish, with friction it is mu_g along the middle of the slide),
    rows, Newton iterations per row (mean of newton_iterations), CG
    iterations per Newton iteration (sum linear / sum Newton), cut-backs (sum
    of cut_backs), the smallest load_increment over the nominal 1/N, wall and
    CPU time (user + system of both ranks), and counts from the log: Newton
    iterations with a projected line-search path, with a trust region, with
    negative curvature; snap steps; lagged-quantity updates.
"""
import argparse
import csv
import os
import re
import resource
import subprocess
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
MPIRUN = os.path.join(ROOT, "scripts", "mpirun.sh")
SCENE = os.path.join(ROOT, "parameters", "shallow_ironing_2d.prm")
GEO = os.path.join(ROOT, "meshes", "shallow_ironing_2d.geo")
MESHES = os.path.join(ROOT, "build", "benchmark_meshes")
LOGS = os.path.join(ROOT, "build", "ironing_logs")
REFERENCE = os.path.join(HERE, "reference_forces.csv")
SUMMARY = os.path.join(HERE, "ironing.csv")
RUNS = os.path.join(HERE, "runs")
PLOT = os.path.join(HERE, "ironing.png")

CODES = ["yastrebov", "code_aster", "hartmann_oliver", "fischer_wriggers",
         "poulios_renard"]
CODE_NAMES = {"yastrebov": "Yastrebov", "code_aster": "Code_Aster",
              "hartmann_oliver": "Hartmann, Oliver et al.",
              "fischer_wriggers": "Fischer, Wriggers",
              "poulios_renard": "Poulios, Renard"}
TIMES = [0.5, 0.7, 0.9, 1.1, 1.3, 1.5, 1.7, 1.9]
KEPT_COLUMNS = ["load_factor", "newton_iterations", "linear_iterations",
                "reaction_2_x", "reaction_2_y", "load_increment", "cut_backs"]
# Log lines counted per run: (column, pattern); iteration lines are those
# starting with the iteration number.
LOG_COUNTS = [("its_projected", r"^\s+\d+\s.*\bprojected\b"),
              ("its_trust_region", r"^\s+\d+\s.*\btrust region\b"),
              ("its_negative_curvature", r"^\s+\d+\s.*negative curvature\)"),
              ("snap_steps", r"^Load step .*, snap step"),
              ("lagged_updates", r"\(lagged quantities updated\)")]
FIELDS = (["label", "h", "steps", "mu", "exit", "rows", "t_end"] +
          ["fx_%g" % t for t in TIMES] + ["fy_%g" % t for t in TIMES] +
          ["fx_in_envelope", "fy_in_envelope", "mu_g_1.5",
           "ratio_mean", "ratio_max", "newton_per_row",
           "newton_per_nominal", "press_per_nominal", "slide_per_nominal",
           "in_all_per_nominal", "cg_per_newton",
           "cut_backs", "smallest_step_fraction", "wall_s", "cpu_s"] +
          [name for name, _ in LOG_COUNTS])


def read_csv(path):
    return list(csv.DictReader(line for line in open(path)
                               if not line.startswith("#")))


def references():
    """{(code, 'Fx'|'Fy'): {T: force}} from reference_forces.csv."""
    table = {}
    for row in read_csv(REFERENCE):
        t = round(float(row["T"]), 2)
        for key, value in row.items():
            if key != "T" and value != "":
                code, component = key.rsplit("_", 1)
                table.setdefault((code, component), {})[t] = float(value)
    return table


def envelope(table, component, t):
    values = [table[(code, component)].get(round(t, 2)) for code in CODES]
    values = [v for v in values if v is not None]
    return (min(values), max(values)) if values else (None, None)


def forces(rows):
    """(T, Fx, Fy) per row: Fx along the slide, Fy pressing down."""
    return [(2 * float(r["load_factor"]), float(r["reaction_2_x"]),
             -float(r["reaction_2_y"])) for r in rows]


def at(series, t):
    """The forces (Fx, Fy) at T = t, linear between the rows around it."""
    points = [(0., 0., 0.)] + series
    for (t0, x0, y0), (t1, x1, y1) in zip(points, points[1:]):
        if t0 <= t + 1e-12 and t <= t1 + 1e-12:
            w = (t - t0) / (t1 - t0) if t1 > t0 else 1.
            return x0 + w * (x1 - x0), y0 + w * (y1 - y0)
    return None, None


def mesh(h):
    path = os.path.join(MESHES, "shallow_ironing_h%g.msh" % h)
    if not os.path.exists(path):
        os.makedirs(MESHES, exist_ok=True)
        subprocess.run(["gmsh", "-2", "-format", "msh41", "-setnumber", "h",
                        str(h), GEO, "-o", path], check=True,
                       stdout=subprocess.DEVNULL)
    return path


def run(exe, h, steps, mu, extra=()):
    """Runs the scene (with EXTRA settings SECTION/ENTRY=VALUE appended);
    returns its rows, exit code, log, wall and CPU time."""
    settings = """
subsection Mesh
  set File = {mesh}
end
subsection Loading
  set Number of load steps = {steps}
end
subsection Contact
  set Self contact friction coefficient = {mu}
end
subsection Output
  set Directory = {out}
  set Base name = run
  set Write VTU = false
end
"""
    with tempfile.TemporaryDirectory() as out:
        prm = os.path.join(out, "scene.prm")
        with open(prm, "w") as f:
            f.write(open(SCENE).read() + settings.format(
                mesh=mesh(h), steps=steps, mu=mu, out=out))
            for setting in extra:
                entry, value = setting.split("=", 1)
                sections = entry.split("/")
                for section in sections[:-1]:
                    f.write("subsection %s\n" % section)
                f.write("set %s = %s\n" % (sections[-1], value))
                f.write("end\n" * (len(sections) - 1))
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.time()
        done = subprocess.run([MPIRUN, "-np", "2", exe, prm],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True)
        wall = time.time() - start
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime -
                                                    before.ru_stime)
        path = os.path.join(out, "run.csv")
        rows = read_csv(path) if os.path.exists(path) else []
        return rows, done.returncode, done.stdout, wall, cpu


def summarise(rows, steps, mu, table):
    s = {"rows": len(rows),
         "t_end": "%.4f" % float(rows[-1]["load_factor"]) if rows else ""}
    if not rows:
        return s
    series = forces(rows)
    if mu > 0:
        inside = {"Fx": 0, "Fy": 0}
        for t in TIMES:
            fx, fy = at(series, t)
            s["fx_%g" % t] = "" if fx is None else "%.1f" % fx
            s["fy_%g" % t] = "" if fy is None else "%.1f" % fy
            for component, value in (("Fx", fx), ("Fy", fy)):
                low, high = envelope(table, component, t)
                if value is not None and low <= value <= high:
                    inside[component] += 1
        s["fx_in_envelope"] = "%d/%d" % (inside["Fx"], len(TIMES))
        s["fy_in_envelope"] = "%d/%d" % (inside["Fy"], len(TIMES))
        fx, fy = at(series, 1.5)
        s["mu_g_1.5"] = "" if fx is None else "%.3f" % abs(fx / fy)
    # |Fx|/|Fy| where the slab (x in [0.2, 1.4] at rest, moved by 10 (T - 1))
    # is at least 3 mm from both ends of the foundation [0, 12]: with
    # friction the global friction coefficient there, without the spurious
    # resistance to the slide.
    ratios = [abs(fx / fy) for t, fx, fy in series
              if 0.2 + 10 * (t - 1) >= 3 - 1e-9 and
              1.4 + 10 * (t - 1) <= 9 + 1e-9]
    if ratios:
        s["ratio_mean"] = "%.3g" % (sum(ratios) / len(ratios))
        s["ratio_max"] = "%.3g" % max(ratios)
    newton = sum(int(r["newton_iterations"]) for r in rows)
    linear = sum(int(r["linear_iterations"]) for r in rows)
    s["newton_per_row"] = "%.2f" % (newton / len(rows))
    # Per nominal step (issue 67): the CSV's Newton iterations over the
    # nominal steps of the run, of the press (t <= 0.5) and of the slide.
    s["newton_per_nominal"] = "%.2f" % (newton / steps)
    press = sum(int(r["newton_iterations"]) for r in rows
                if float(r["load_factor"]) <= 0.5 + 1e-9)
    s["press_per_nominal"] = "%.2f" % (press / (steps / 2))
    s["slide_per_nominal"] = "%.2f" % ((newton - press) / (steps / 2))
    s["cg_per_newton"] = "%.2f" % (linear / max(newton, 1))
    s["cut_backs"] = sum(int(r["cut_backs"]) for r in rows)
    s["smallest_step_fraction"] = "%.4g" % (
        min(float(r["load_increment"]) for r in rows) * steps)
    return s


def store(result):
    rows = read_csv(SUMMARY) if os.path.exists(SUMMARY) else []
    key = ("label", "h", "steps", "mu")
    rows = [r for r in rows if tuple(r[k] for k in key) !=
            tuple(str(result[k]) for k in key)] + [result]
    rows.sort(key=lambda r: (-float(r["h"]), int(r["steps"]), -float(r["mu"]),
                             r["label"]))
    with open(SUMMARY, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)


def run_name(label, h, steps, mu):
    return "%s_h%s_n%s_mu%s" % (re.sub(r"[^A-Za-z0-9.-]+", "-", label), h,
                                steps, mu)


def print_tables():
    rows = read_csv(SUMMARY)
    table = references()
    print("| T | " + " | ".join("%g" % t for t in TIMES) + " |")
    print("|---" * (len(TIMES) + 1) + "|")
    for component in ("Fx", "Fy"):
        print("| %s envelope | " % component + " | ".join(
            "%.0f-%.0f" % envelope(table, component, t) for t in TIMES) + " |")
        for r in rows:
            if float(r["mu"]) > 0:
                print("| %s %s (h %s, %s steps) | " % (
                    component, r["label"], r["h"], r["steps"]) + " | ".join(
                        r["%s_%g" % (component.lower(), t)] for t in TIMES) +
                    " |")
    print()
    columns = ["label", "h", "steps", "mu", "exit", "rows", "mu_g_1.5",
               "fx_in_envelope", "fy_in_envelope", "ratio_mean", "ratio_max",
               "newton_per_row", "cg_per_newton", "cut_backs",
               "smallest_step_fraction", "wall_s", "cpu_s"] + [
                   name for name, _ in LOG_COUNTS]
    print("| " + " | ".join(columns) + " |")
    print("|---" * len(columns) + "|")
    for r in rows:
        print("| " + " | ".join(r[c] for c in columns) + " |")


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    table = references()
    grid = sorted(set(t for key in table for t in table[key]))
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.8))
    for ax, component in zip(axes[:2], ("Fx", "Fy")):
        low = [envelope(table, component, t) for t in grid]
        ts = [t for t, (a, b) in zip(grid, low) if a is not None]
        ax.fill_between(ts, [a for a, b in low if a is not None],
                        [b for a, b in low if b is not None], color="0.85",
                        label="envelope of the five codes")
        for code in CODES:
            points = sorted(table[(code, component)].items())
            ax.plot([p[0] for p in points], [p[1] for p in points], lw=0.7,
                    label=CODE_NAMES[code])
    ratio_axis = axes[2]
    for code in CODES:
        fx, fy = table[(code, "Fx")], table[(code, "Fy")]
        ts = [t for t in sorted(fx) if t in fy and t >= 1 and fy[t] > 0]
        ratio_axis.plot(ts, [abs(fx[t] / fy[t]) for t in ts], lw=0.7,
                        label=CODE_NAMES[code])
    # For each friction coefficient the runs on its finest mesh only (all of
    # them are in the tables), a colour per label, dashed without friction.
    colours = "brkgm"
    summary = read_csv(SUMMARY) if os.path.exists(SUMMARY) else []
    finest = {}
    for r in summary:
        finest[r["mu"]] = min(finest.get(r["mu"], 1e300), float(r["h"]))
    summary = [r for r in summary if float(r["h"]) == finest[r["mu"]]]
    labels = sorted(set(r["label"] for r in summary))
    for r in summary:
        path = os.path.join(RUNS, run_name(r["label"], r["h"], r["steps"],
                                           r["mu"]) + ".csv")
        if not os.path.exists(path):
            continue
        series = forces(read_csv(path))
        name = "%s, h %s, %s steps, mu %s" % (r["label"], r["h"], r["steps"],
                                               r["mu"])
        colour = colours[labels.index(r["label"]) % len(colours)]
        style = colour + ("-" if float(r["mu"]) > 0 else "--")
        axes[0].plot([p[0] for p in series], [p[1] for p in series], style,
                     lw=1.4, label=name)
        axes[1].plot([p[0] for p in series], [p[2] for p in series], style,
                     lw=1.4, label=name)
        slide = [p for p in series if p[0] >= 1 and p[2] != 0]
        ratio_axis.plot([p[0] for p in slide],
                        [abs(p[1] / p[2]) for p in slide], style, lw=1.4,
                        label=name)
    axes[0].set_title("horizontal reaction on the slab's top")
    axes[1].set_title("vertical reaction on the slab's top")
    ratio_axis.set_title("|Fx| / |Fy| along the slide")
    for ax, unit in zip(axes, ["Fx [N/mm]", "Fy [N/mm]", "|Fx| / |Fy|"]):
        ax.set_xlabel("T (press on [0, 1], slide on [1, 2])")
        ax.set_ylabel(unit)
        ax.grid(alpha=0.3)
    axes[0].set_xlim(0, 2)
    axes[1].set_xlim(0, 2)
    ratio_axis.set_xlim(1, 2)
    ratio_axis.set_ylim(0, 0.7)
    axes[1].legend(fontsize=7, loc="lower right")
    ratio_axis.legend(fontsize=6, loc="upper right")
    fig.tight_layout()
    fig.savefig(PLOT, dpi=110)
    print("wrote", PLOT)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", default=os.path.join(ROOT, "build",
                                                      "hyperelastic"))
    parser.add_argument("--label", default="current")
    parser.add_argument("--h", type=float, default=0.1)
    parser.add_argument("--steps", type=int, default=400)
    parser.add_argument("--mu", default="0.3,0")
    parser.add_argument("--set", action="append", default=[],
                        metavar="SECTION/ENTRY=VALUE",
                        help="a setting appended to the scene (repeatable)")
    parser.add_argument("--plot", action="store_true")
    parser.add_argument("--table", action="store_true")
    parser.add_argument("--summarise-again", action="store_true",
                        help="recompute ironing.csv's columns from runs/ "
                        "(exit, times and log counts kept)")
    args = parser.parse_args()
    if args.table:
        print_tables()
        return
    if args.summarise_again:
        table = references()
        for r in read_csv(SUMMARY):
            rows = read_csv(os.path.join(RUNS, run_name(
                r["label"], r["h"], r["steps"], r["mu"]) + ".csv"))
            kept = {k: r[k] for k in ["label", "h", "steps", "mu", "exit",
                                      "wall_s", "cpu_s"] +
                    [name for name, _ in LOG_COUNTS]}
            kept.update(summarise(rows, int(r["steps"]), float(r["mu"]),
                                  table))
            store(kept)
        print_tables()
        return
    if not args.plot:
        table = references()
        os.makedirs(RUNS, exist_ok=True)
        for mu in [float(m) for m in args.mu.split(",")]:
            rows, code, log, wall, cpu = run(args.exe, args.h, args.steps, mu,
                                             args.set)
            result = {"label": args.label, "h": "%g" % args.h,
                      "steps": args.steps, "mu": "%g" % mu, "exit": code,
                      "wall_s": "%.0f" % wall, "cpu_s": "%.0f" % cpu}
            result.update(summarise(rows, args.steps, mu, table))
            for name, pattern in LOG_COUNTS:
                result[name] = len(re.findall(pattern, log, re.MULTILINE))
            # The run's own count, failed attempts included (closing line).
            in_all = re.search(r"Newton iterations: (\d+) in all", log)
            if in_all:
                result["in_all_per_nominal"] = "%.2f" % (
                    int(in_all.group(1)) / args.steps)
            name = run_name(args.label, result["h"], args.steps, result["mu"])
            with open(os.path.join(RUNS, name + ".csv"), "w",
                      newline="") as f:
                writer = csv.DictWriter(f, fieldnames=KEPT_COLUMNS,
                                        extrasaction="ignore")
                writer.writeheader()
                writer.writerows(rows)
            os.makedirs(LOGS, exist_ok=True)
            with open(os.path.join(LOGS, name + ".log"), "w") as f:
                f.write(log)
            print(result, flush=True)
            store(result)
    plot()


if __name__ == "__main__":
    main()

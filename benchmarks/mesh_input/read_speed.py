#!/usr/bin/env python3
"""Reading speed of the mesh file formats (issue 46).

The large bar of bar_big.geo (h = 0.025: about 875,000 tetrahedra) is meshed
once with gmsh as ASCII 4.1 (the file run.sh uses) and converted by gmsh to
binary 4.1, ASCII and binary 2.2, MEDIT and legacy VTK (ASCII and binary).
hyperelastic_read_speed reads each file REPEATS times with read_mesh_file()
(what 'Mesh/File' does on rank 0) and reports the median wall time. The
script writes read_speed.csv next to itself, prints the table, and fails
unless every file gives the same mesh (cells, faces, vertices, id checksum)
and binary gmsh reads at least 2x faster than its ASCII twin (4.1 and 2.2).

    python3 benchmarks/mesh_input/read_speed.py [--build BUILD] [--h H]
                                                [--repeats N]
"""
import argparse
import csv
import io
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# name in the table, file name, gmsh options of the conversion
FORMATS = [
    ("gmsh ASCII 4.1", "bar_big.msh", None),
    ("gmsh binary 4.1", "bar_big_binary41.msh", ["-format", "msh41", "-bin"]),
    ("gmsh ASCII 2.2", "bar_big_ascii22.msh", ["-format", "msh22"]),
    ("gmsh binary 2.2", "bar_big_binary22.msh", ["-format", "msh22", "-bin"]),
    ("MEDIT", "bar_big.mesh",
     ["-format", "mesh", "-setnumber", "Mesh.SaveElementTagType", "2"]),
    ("VTK ASCII", "bar_big_ascii.vtk",
     ["-format", "vtk", "-setnumber", "Mesh.SaveElementTagType", "2"]),
    ("VTK binary", "bar_big_binary.vtk",
     ["-format", "vtk", "-bin", "-setnumber", "Mesh.SaveElementTagType", "2"]),
]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--h", default="0.025")
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()

    work = os.path.join(args.build, "mesh_input_benchmark")
    os.makedirs(work, exist_ok=True)
    source = os.path.join(work, "bar_big.msh")
    if not os.path.exists(source):
        subprocess.run(["gmsh", "-3", "-format", "msh41", "-setnumber", "h",
                        args.h, os.path.join(HERE, "bar_big.geo"), "-o",
                        source], check=True, stdout=subprocess.DEVNULL)
    for _, name, options in FORMATS:
        path = os.path.join(work, name)
        if options and not os.path.exists(path):
            subprocess.run(["gmsh", "-0", source] + options + ["-o", path],
                           check=True, stdout=subprocess.DEVNULL)

    reader = os.path.join(args.build, "hyperelastic_read_speed")
    out = subprocess.run([reader, "3", str(args.repeats)] +
                         [os.path.join(work, name) for _, name, _ in FORMATS],
                         check=True, capture_output=True, text=True).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    for (label, _, _), row in zip(FORMATS, rows):
        row["format"] = label
    ascii41 = float(rows[0]["median_s"])

    with open(os.path.join(HERE, "read_speed.csv"), "w", newline="") as f:
        fields = ["format", "file", "bytes", "median_s", "min_s", "max_s",
                  "speedup_vs_ascii41", "cells", "faces", "vertices",
                  "id_sum"]
        writer = csv.DictWriter(f, fieldnames=fields, lineterminator="\n")
        writer.writeheader()
        for row in rows:
            row["speedup_vs_ascii41"] = "%.2f" % (ascii41 /
                                                 float(row["median_s"]))
            writer.writerow({k: row[k] for k in fields})

    print("%-16s %10s %10s %8s %9s %8s" %
          ("format", "MB", "median s", "speedup", "cells", "faces"))
    for row in rows:
        print("%-16s %10.1f %10.3f %8s %9s %8s" %
              (row["format"], int(row["bytes"]) / 1e6, float(row["median_s"]),
               row["speedup_vs_ascii41"], row["cells"], row["faces"]))

    failures = []
    first = rows[0]
    for row in rows[1:]:
        for key in ("cells", "faces", "vertices", "id_sum"):
            if row[key] != first[key]:
                failures.append("%s: %s %s, but %s in %s" %
                                (row["format"], key, row[key], first[key],
                                 first["format"]))
    by_name = {row["format"]: float(row["median_s"]) for row in rows}
    for version in ("4.1", "2.2"):
        ratio = by_name["gmsh ASCII " + version] / \
            by_name["gmsh binary " + version]
        print("gmsh %s: binary reads %.2fx faster than ASCII" %
              (version, ratio))
        if ratio < 2.:
            failures.append("gmsh %s: binary only %.2fx faster than ASCII "
                            "(at least 2x expected)" % (version, ratio))
    for failure in failures:
        print("FAIL: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

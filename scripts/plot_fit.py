#!/usr/bin/env python3
"""Draws a fit written by 'hyperelastic --fit': one panel per data set, the
measured values as points and the fitted model as a curve.

    python3 scripts/plot_fit.py OUTPUT/BASE_fit.csv [PICTURE.png]

The picture defaults to the CSV's name with _fit.csv replaced by _fit.png.
The curve comes from BASE_curve.csv beside the CSV (the model along each
test's range); without it, a line joins the fitted values at the data.
Columns read: data, test, stretch_1, stretch_2, measured, fitted, component,
time. A biaxial data set draws one curve per stress and first stretch
against the second stretch, a relaxation test the stress against time.
"""
import csv
import math
import os
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

X_LABEL = {"simple shear": "shear g", "volumetric": "J", "relaxation": "time",
           "biaxial": "stretch_2"}
Y_LABEL = {"simple shear": "nominal shear stress",
           "volumetric": "pressure (-mean Cauchy stress)"}


def read(path):
    """The rows of a fit or curve CSV, per data set."""
    sets = OrderedDict()
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            key = int(row["data"])
            sets.setdefault(key, {"test": row["test"], "rows": []})
            sets[key]["rows"].append(row)
    return sets


def grouped(test, rows, value):
    """(label, sorted [(x, value)]) per curve of a data set."""
    groups = OrderedDict()
    for row in rows:
        label, x = "", float(row["stretch_1"])
        if test == "biaxial":
            label = "P%s, stretch_1 = %.3g" % (row["component"],
                                              float(row["stretch_1"]))
            x = float(row["stretch_2"])
        elif test == "relaxation":
            label = "stretch %.3g" % float(row["stretch_1"])
            x = float(row["time"])
        groups.setdefault(label, []).append((x, float(row[value])))
    return [(label, sorted(points)) for label, points in groups.items()]


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    path = sys.argv[1]
    base = path[:-len("_fit.csv")] if path.endswith("_fit.csv") else path
    picture = sys.argv[2] if len(sys.argv) == 3 else base + "_fit.png"
    sets = read(path)
    curves = read(base + "_curve.csv") if os.path.exists(
        base + "_curve.csv") else None
    columns = min(len(sets), 3)
    rows_of_panels = math.ceil(len(sets) / columns)
    figure, axes = plt.subplots(rows_of_panels, columns,
                                figsize=(4.6 * columns, 3.8 * rows_of_panels),
                                squeeze=False)
    for panel, (index, data) in zip(axes.flat, sets.items()):
        test = data["test"]
        measured = grouped(test, data["rows"], "measured")
        fitted = grouped(test, (curves[index] if curves else data)["rows"],
                         "fitted")
        many = len(measured) > 6
        for k, ((label, points), (_, line)) in enumerate(zip(measured,
                                                             fitted)):
            colour = "C%d" % (k % 10)
            panel.plot([p[0] for p in points], [p[1] for p in points], "o",
                       color=colour, markersize=3 if many else 4,
                       label=None if many else ("data " + label).strip())
            panel.plot([p[0] for p in line], [p[1] for p in line], "-",
                       color=colour, linewidth=1,
                       label=None if many else ("fit " + label).strip())
        panel.set_title("Data %d: %s%s" % (
            index, test, " (%d curves)" % len(measured) if many else ""))
        panel.set_xlabel(X_LABEL.get(test, "stretch"))
        panel.set_ylabel(Y_LABEL.get(test, "nominal stress"))
        panel.grid(alpha=0.3)
        if not many:
            panel.legend(fontsize=7)
    for panel in list(axes.flat)[len(sets):]:
        panel.axis("off")
    figure.tight_layout()
    figure.savefig(picture, dpi=110)
    print("wrote", picture)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Draws a fit written by 'hyperelastic --fit': one panel per data set, the
measured values as points and the fitted model as a curve through them.

    python3 scripts/plot_fit.py OUTPUT/BASE_fit.csv [PICTURE.png]

The picture defaults to the CSV's name with _fit.csv replaced by _fit.png.
Columns read: data, test, stretch_1, stretch_2, measured, fitted, component,
time (biaxial data sets draw one curve per stress and second stretch,
relaxation tests the stress against time).
"""
import csv
import math
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

X_LABEL = {"simple shear": "shear g", "volumetric": "J", "relaxation": "time"}
Y_LABEL = {"simple shear": "nominal shear stress",
           "volumetric": "pressure (-mean Cauchy stress)"}


def read(path):
    sets = OrderedDict()
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            key = int(row["data"])
            sets.setdefault(key, {"test": row["test"], "rows": []})
            sets[key]["rows"].append(row)
    return sets


def curves(test, rows):
    """(label, [(x, measured, fitted)]) per curve of a data set."""
    groups = OrderedDict()
    for row in rows:
        label = ""
        if test == "biaxial":
            label = "P%s, stretch_2 = %.3g" % (row["component"],
                                              float(row["stretch_2"]))
        if test == "relaxation":
            label = "stretch %.3g" % float(row["stretch_1"])
        x = float(row["time"] if test == "relaxation" else row["stretch_1"])
        groups.setdefault(label, []).append(
            (x, float(row["measured"]), float(row["fitted"])))
    return [(label, sorted(points)) for label, points in groups.items()]


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    path = sys.argv[1]
    picture = sys.argv[2] if len(sys.argv) == 3 else \
        path.replace("_fit.csv", "") + "_fit.png"
    sets = read(path)
    columns = min(len(sets), 3)
    rows_of_panels = math.ceil(len(sets) / columns)
    figure, axes = plt.subplots(rows_of_panels, columns,
                                figsize=(4.6 * columns, 3.8 * rows_of_panels),
                                squeeze=False)
    for panel, (index, data) in zip(axes.flat, sets.items()):
        test = data["test"]
        for k, (label, points) in enumerate(curves(test, data["rows"])):
            colour = "C%d" % (k % 10)
            x = [p[0] for p in points]
            panel.plot(x, [p[1] for p in points], "o", color=colour,
                       markersize=4, label=("data " + label).strip())
            panel.plot(x, [p[2] for p in points], "-", color=colour,
                       label=("fit " + label).strip())
        panel.set_title("Data %d: %s" % (index, test))
        panel.set_xlabel(X_LABEL.get(test, "stretch"))
        panel.set_ylabel(Y_LABEL.get(test, "nominal stress"))
        panel.grid(alpha=0.3)
        panel.legend(fontsize=7)
    for panel in list(axes.flat)[len(sets):]:
        panel.axis("off")
    figure.tight_layout()
    figure.savefig(picture, dpi=110)
    print("wrote", picture)


if __name__ == "__main__":
    main()

"""Patch tests of sliding contact (issue 57): a flat block pressed on a flat
block and slid along x at a constant indentation.
Frictionless (MU = 0): over the rows of the slide (load factor above 0.2)
the horizontal reaction on the pressed top (reaction_2_x) stays within 1e-3
of the vertical one, and the vertical one within 1e-3 of its mean along the
slide. With a barrier that counted a vertex's pairs twice over a boundary
vertex the first failed (2D: 1.0e-2, 3D: 1.5e-3, measured before issue 57).
With friction (MU > 0): once sliding (load factor above 0.35), |Fx| / |Fy|
lies within 3 % of MU in every row (measured 1.7 % at 2 ranks). With
friction's normal forces taken at Newton iterates far from the answer it
ranged from 0.30 to 0.92 at mu = 0.3 (before issue 57).
Usage: python3 sliding_patch.py DIM MU CSV COMMAND ...
Runs COMMAND, then reads CSV."""
import csv
import subprocess
import sys

dim = int(sys.argv[1])
mu = float(sys.argv[2])
run = subprocess.run(sys.argv[4:])
if run.returncode != 0:
    sys.exit('the scene failed (exit %d)' % run.returncode)
start = 0.35 if mu > 0 else 0.2
rows = [r for r in csv.DictReader(open(sys.argv[3]))
        if float(r['load_factor']) > start + 1e-9]
normal_axis = 'y' if dim == 2 else 'z'
normal = [float(r['reaction_2_' + normal_axis]) for r in rows]
tangential = [abs(float(r['reaction_2_x']) / n) for r, n in zip(rows, normal)]
mean = sum(normal) / len(normal)
spread = max(abs(n - mean) for n in normal) / abs(mean)
newton = sum(int(r['newton_iterations']) for r in rows) / len(rows)
print('rows of the slide: %d, Newton iterations per row %.2f' % (len(rows), newton))
print('largest |Fx| / |Fn|: %.3e (mean %.3e)'
      % (max(tangential), sum(tangential) / len(tangential)))
print('largest |Fn - mean| / |mean|: %.3e (range %.3e), mean Fn %.6e'
      % (spread, (max(normal) - min(normal)) / abs(mean), mean))
failures = []
if len(rows) < 20:
    failures.append('only %d rows of the slide' % len(rows))
if mu > 0:
    worst = max(abs(t / mu - 1) for t in tangential)
    print('largest | |Fx| / |Fy| / mu - 1 |: %.3e' % worst)
    if not worst <= 0.03:
        failures.append('|Fx| / |Fy| not within 3 % of mu')
else:
    if not max(tangential) <= 1e-3:
        failures.append('tangential force above 1e-3 of the normal one')
    if not spread <= 1e-3:
        failures.append('normal force not constant within 1e-3')
if not abs(mean) > 0:
    failures.append('no normal force')
for f in failures:
    print('FAIL: ' + f)
sys.exit(1 if failures else 0)

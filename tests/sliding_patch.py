"""Frictionless patch test of contact (issue 57): a flat block pressed on a
flat block and slid along x at a constant indentation. Over the rows of the
slide (load factor above 0.2) the horizontal reaction on the pressed top
(reaction_2_x) stays within 1e-3 of the vertical one, and the vertical one
within 1e-3 of its mean along the slide. With a barrier that counted a
vertex's pairs twice over a boundary vertex the first failed (2D: 1.0e-2,
3D: 1.5e-3, measured before issue 57).
Usage: python3 sliding_patch.py DIM CSV COMMAND ...
Runs COMMAND, then reads CSV."""
import csv
import subprocess
import sys

dim = int(sys.argv[1])
run = subprocess.run(sys.argv[3:])
if run.returncode != 0:
    sys.exit('the scene failed (exit %d)' % run.returncode)
rows = [r for r in csv.DictReader(open(sys.argv[2]))
        if float(r['load_factor']) > 0.2 + 1e-9]
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
if not max(tangential) <= 1e-3:
    failures.append('tangential force above 1e-3 of the normal one')
if not spread <= 1e-3:
    failures.append('normal force not constant within 1e-3')
if not abs(mean) > 0:
    failures.append('no normal force')
for f in failures:
    print('FAIL: ' + f)
sys.exit(1 if failures else 0)

"""Runs scripts/plot_fit.py on a fit's CSV and checks the picture: one panel
per data set (4.6 x 3.8 inches at 110 dpi each), and its curves drawn (at
least 2 % of the pixels not white).
Usage: python3 plot_fit_check.py SOURCE_DIR FIT_CSV PANELS"""
import subprocess
import sys

import matplotlib.image

root, csv_file, panels = sys.argv[1], sys.argv[2], int(sys.argv[3])
picture = csv_file.replace("_fit.csv", "_fit.png")
subprocess.run([sys.executable, root + "/scripts/plot_fit.py", csv_file],
               check=True)
image = matplotlib.image.imread(picture)
height, width = image.shape[0], image.shape[1]
columns = min(panels, 3)
rows = (panels + columns - 1) // columns
expected = (round(3.8 * rows * 110), round(4.6 * columns * 110))
drawn = (image[:, :, :3].sum(axis=2) < 2.9).mean()
print("%s: %d x %d pixels (expected %d x %d), %.1f %% drawn"
      % (picture, width, height, expected[1], expected[0], 100 * drawn))
ok = abs(height - expected[0]) <= 1 and abs(width - expected[1]) <= 1 \
    and drawn >= 0.02
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)

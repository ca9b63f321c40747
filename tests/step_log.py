"""Checks the log of a scene whose steps cut back and snap (issue 56):
within each load step the cut-backs are numbered 1, 2, 3, ... without a gap,
and a snap sequence that gives up has counted exactly the iterations its
sub-steps' Newton tables show (a failed sub-step is charged what it used, not
the whole budget: 20 each before issue 56).
Usage: python3 step_log.py MIN_CUT_BACKS COMMAND ...
Runs COMMAND and asserts the above, and that some step cut back at least
MIN_CUT_BACKS times (the log is not vacuous)."""
import re
import subprocess
import sys

min_cut_backs = int(sys.argv[1])
run = subprocess.run(sys.argv[2:], stdout=subprocess.PIPE,
                     stderr=subprocess.STDOUT, text=True)
log = run.stdout
print(log)
failures = []

# The cut-backs of each load step (its attempts each have a header with the
# same step number), in the order printed.
steps = {}
for block in re.split(r'\n(?=(?:Load|Time) step \d+:)', log):
    header = re.match(r'(?:Load|Time) step (\d+):', block)
    if header:
        steps.setdefault(int(header.group(1)), []).extend(
            int(n) for n in re.findall(r'^   cut-back (\d+):', block,
                                       re.MULTILINE))
most = 0
for step, numbers in sorted(steps.items()):
    if numbers != list(range(1, len(numbers) + 1)):
        failures.append('load step %d: cut-backs numbered %s' % (step, numbers))
    most = max(most, len(numbers))
print('most cut-backs in one step: %d (at least %d asked)'
      % (most, min_cut_backs))
if most < min_cut_backs:
    failures.append('no step cut back %d times' % min_cut_backs)

# A snap sequence that gave up: the iterations it counted against those its
# sub-steps' tables show (rows whose first field is an iteration number).
for match in re.finditer(r'snap sub-steps to t = [^:]*: .*? after \d+ '
                         r'sub-steps \((\d+) Newton iterations counted', log):
    counted = int(match.group(1))
    start = log.rfind('snap sub-steps from t', 0, match.start())
    section = log[start:match.start()]
    rows = len(re.findall(r'^ {4,8}\d+ {5,}[0-9.e+-]+ ', section, re.MULTILINE))
    print('snap sequence: %d iterations counted, %d table rows' % (counted, rows))
    if counted != rows:
        failures.append('the snap sequence counted %d Newton iterations, its '
                        'tables show %d' % (counted, rows))

for f in failures:
    print('FAIL: ' + f)
print('%d passed, %d failed' % (1 if not failures else 0, len(failures)))
sys.exit(1 if failures else 0)

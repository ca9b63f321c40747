#!/usr/bin/env python3
"""The cold build on this machine (issue 68, item 6): a fresh clone of the
repository's HEAD configured with Ninja in a scratch folder, no ccache,
Release, -j <cores>; first the program (what scripts/run-default.sh builds),
then everything else (what scripts/test.sh builds on top). Records

  benchmarks/build/<label>_units.csv    target, seconds (ninja's log: each
                                        compile and link, wall time of the
                                        step while -j cores ran)
  benchmarks/build/builds.csv           one row a run: label, commit, cores,
                                        program wall s, all wall s, units,
                                        sum of unit s (appended)

and prints the ten slowest units. Usage:

  /usr/bin/python3 benchmarks/build/cold_build.py LABEL [--keep DIR]

The package installation is not included (scripts/install-dependencies.sh
takes about a minute and a half on a fresh machine and nothing here).
"""
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def run(command, cwd=None, env=None):
    subprocess.run(command, cwd=cwd, env=env, check=True,
                   stdout=subprocess.DEVNULL)


def units(log):
    """[(target, seconds)] from a .ninja_log (v5: start end mtime target)."""
    rows = []
    with open(log) as f:
        for line in f:
            if line.startswith('#'):
                continue
            start, end, _, target, _ = line.split('\t')
            rows.append((target, (int(end) - int(start)) / 1000.))
    return rows


def main(argv):
    if not argv or argv[0].startswith('-'):
        print(__doc__)
        return 2
    label = argv[0]
    keep = argv[argv.index('--keep') + 1] if '--keep' in argv else None
    cores = os.cpu_count()
    commit = subprocess.run(['git', 'rev-parse', '--short', 'HEAD'], cwd=ROOT,
                            capture_output=True, text=True,
                            check=True).stdout.strip()
    scratch = keep or tempfile.mkdtemp(prefix='hyperelastic-cold-')
    source = os.path.join(scratch, 'source')
    build = os.path.join(scratch, 'build')
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    run(['git', 'clone', '--quiet', ROOT, source])
    env = dict(os.environ, CCACHE_DISABLE='1')
    run(['cmake', '-S', source, '-B', build, '-G', 'Ninja',
         '-DCMAKE_BUILD_TYPE=Release'], env=env)
    start = time.monotonic()
    run(['ninja', '-C', build, '-j', str(cores), 'hyperelastic'], env=env)
    program = time.monotonic() - start
    run(['ninja', '-C', build, '-j', str(cores)], env=env)
    everything = time.monotonic() - start
    rows = units(os.path.join(build, '.ninja_log'))
    with open(os.path.join(HERE, f'{label}_units.csv'), 'w', newline='') as f:
        writer = csv.writer(f)
        writer.writerow(['target', 'seconds'])
        for target, seconds in sorted(rows, key=lambda r: -r[1]):
            writer.writerow([target, f'{seconds:.1f}'])
    summary = os.path.join(HERE, 'builds.csv')
    new = not os.path.exists(summary)
    with open(summary, 'a', newline='') as f:
        writer = csv.writer(f)
        if new:
            writer.writerow(['label', 'commit', 'cores', 'program_wall_s',
                             'all_wall_s', 'units', 'unit_sum_s'])
        writer.writerow([label, commit, cores, f'{program:.0f}',
                         f'{everything:.0f}', len(rows),
                         f'{sum(s for _, s in rows):.0f}'])
    print(f'{label} ({commit}, {cores} cores): program {program:.0f} s, '
          f'everything {everything:.0f} s, {len(rows)} steps, '
          f'{sum(s for _, s in rows):.0f} s of steps')
    for target, seconds in sorted(rows, key=lambda r: -r[1])[:10]:
        print(f'  {seconds:6.1f}  {target}')
    if not keep:
        shutil.rmtree(scratch, ignore_errors=True)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

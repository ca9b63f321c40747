#!/usr/bin/env python3
"""The architecture budget (scripts/architecture_budget.py) against planted
regressions: a copy of the repository's include/, source/ and scripts/
passes as it is; each planted change below makes the script exit with 1 and
name the metric it breaks (and only that change's metric over its limit).

Usage: architecture_budget_test.py REPOSITORY_ROOT
"""
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                       os.path.join(os.path.dirname(__file__), '..'))
failures = []


def check(condition, what):
    print(('PASS ' if condition else 'FAIL ') + what)
    if not condition:
        failures.append(what)


def copy_tree(target):
    for folder in ('include', 'source', 'scripts'):
        shutil.copytree(os.path.join(ROOT, folder),
                        os.path.join(target, folder))


def run(tree):
    result = subprocess.run(
        [sys.executable, os.path.join(tree, 'scripts',
                                      'architecture_budget.py')],
        capture_output=True, text=True)
    over = re.findall(r'^(.*?)\s+\d+\s+\d+\s+OVER$', result.stdout, re.M)
    return result.returncode, [m.strip() for m in over], result.stdout


def edit(tree, path, old, new):
    full = os.path.join(tree, path)
    with open(full) as f:
        text = f.read()
    if old not in text:
        raise RuntimeError(f'{path}: the planting anchor {old!r} is gone: '
                           'update this test')
    with open(full, 'w') as f:
        f.write(text.replace(old, new, 1))


def pure_to_default(tree, path):
    """The first pure method of @p path given a body instead of '= 0;'
    (the same methods, one more default body)."""
    full = os.path.join(tree, path)
    with open(full) as f:
        text = f.read()
    planted, count = re.subn(r'=\s*0\s*;', '{ throw 0; }', text, count=1)
    if not count:
        raise RuntimeError(f'{path} has no pure method: update this test')
    with open(full, 'w') as f:
        f.write(planted)


def write(tree, path, text):
    full = os.path.join(tree, path)
    os.makedirs(os.path.dirname(full), exist_ok=True)
    with open(full, 'w') as f:
        f.write(text)


MATERIAL = 'include/hyperelastic/materials/material.h'
ANCHOR = '    virtual ~Material() = default;\n'
# (what, the metric that must go over, the planting)
PLANTS = [
    ('a pure method of Material given a default body',
     'Material default bodies', lambda t: pure_to_default(t, MATERIAL)),
    ('a pure method more on Material', 'Material methods',
     lambda t: edit(t, MATERIAL, ANCHOR, ANCHOR +
                    '    virtual void\n    planted_method() const = 0;\n')),
    ('a new interface with a default body', 'PlantedInterface default bodies',
     lambda t: write(t, 'include/hyperelastic/materials/planted.h',
                     'class PlantedInterface\n{\npublic:\n'
                     '  virtual ~PlantedInterface() = default;\n'
                     '  virtual void a() const = 0;\n'
                     '  virtual void b() const {}\n};\n')),
    ('a new interface of four methods', 'PlantedInterface methods',
     lambda t: write(t, 'include/hyperelastic/materials/planted.h',
                     'class PlantedInterface\n{\npublic:\n' +
                     ''.join(f'  virtual void m{k}() const = 0;\n'
                             for k in range(4)) + '};\n')),
    ('a loose file at the top of source/', 'source/ top-level files',
     lambda t: write(t, 'source/loose.cc', 'int loose() { return 0; }\n')),
    ('three headers at the top of include/hyperelastic/',
     'include/hyperelastic top-level headers',
     lambda t: [write(t, f'include/hyperelastic/top_{k}.h', '#pragma once\n')
                for k in range(3)]),
    ('a second GmshSession', 'GmshSession definitions',
     lambda t: write(t, 'source/inverse/planted_session.cc',
                     'namespace {\n  struct GmshSession\n  {\n'
                     '    GmshSession() {}\n  };\n}\n')),
    ('a pure method of NonlinearSystem given a default body',
     'NonlinearSystem default bodies',
     lambda t: pure_to_default(
         t, 'include/hyperelastic/solvers/nonlinear_system.h')),
    ('a physics include in solvers/', 'includes from solvers/ into physics',
     lambda t: edit(t, 'source/solvers/newton_solver.cc', '#include',
                    '#include <hyperelastic/materials/material.h>\n#include')),
]

with tempfile.TemporaryDirectory() as scratch:
    clean = os.path.join(scratch, 'clean')
    copy_tree(clean)
    code, over, out = run(clean)
    check(code == 0 and not over,
          f'the repository as it is passes (exit {code}, over: {over})')
    trees = []
    for k, (what, metric, plant) in enumerate(PLANTS):
        tree = os.path.join(scratch, f'plant{k}')
        copy_tree(tree)
        plant(tree)
        trees.append(tree)
    # Two at a time (ctest gives this test one core, the script is short).
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(run, trees))
    for (what, metric, _), (code, over, _) in zip(PLANTS, results):
        check(code == 1 and over == [metric],
              f'{what}: exit {code} (1 expected), over {over} '
              f'([{metric!r}] expected)')

print(f'{len(failures)} failure(s)')
sys.exit(1 if failures else 0)

#!/usr/bin/env bash
# Renders a result to PNG: scripts/render.py under ParaView's pvbatch, with a
# virtual X display (xvfb-run) when there is no display, since Debian's
# pvbatch renders through X. Arguments are render.py's:
#   bash scripts/render.sh output/default.pvd --field von_Mises_stress
# Exits with 77 when pvbatch is missing (install it with
# `apt-get install paraview xvfb`).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v pvbatch >/dev/null 2>&1; then
  echo "render.sh: pvbatch not found; install ParaView with" \
    "'apt-get install paraview xvfb'" >&2
  exit 77
fi
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null 2>&1; then
  exec xvfb-run -a pvbatch "$here/render.py" "$@"
fi
exec pvbatch "$here/render.py" "$@"

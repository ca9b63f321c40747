#!/usr/bin/env bash
# Renders a result to PNG: scripts/render.py under ParaView's pvbatch.
# Arguments are render.py's:
#   bash scripts/render.sh output/default.pvd --field von_Mises_stress
# Exits with 77 when pvbatch is missing (install it with
# `apt-get install paraview xvfb`).
#
# Debian's pvbatch renders through X. Without a DISPLAY (or when pvbatch
# dies on the one set) this script starts its own virtual X server (Xvfb)
# for each pvbatch run, and stops it after:
#  - -noreset: without it Xvfb resets whenever its last client disconnects;
#    pvbatch connects several times (it probes OpenGL first), and a
#    connection during such a reset fails: "bad X server connection.
#    DISPLAY=:99. Aborting." (about 1 run in 30 under xvfb-run, used
#    before; the signal Xvfb sends after each reset could also make
#    xvfb-run's clean-up fail, "problem while cleaning up temporary
#    directory", and leave the server running);
#  - -displayfd: Xvfb picks a free display number itself, so runs side by
#    side (ctest -j) and stale /tmp/.X*-lock files do not collide;
#  - a private cookie (xauth), and no TCP;
#  - a run that dies from a signal (an X failure aborts pvbatch) or whose
#    server does not start is tried again with a fresh server, up to 3 times.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v pvbatch >/dev/null 2>&1; then
  echo "render.sh: pvbatch not found; install ParaView with" \
    "'apt-get install paraview xvfb'" >&2
  exit 77
fi
if [ -n "${DISPLAY:-}" ]; then
  pvbatch "$here/render.py" "$@"
  status=$?
  if [ $status -lt 128 ] || ! command -v Xvfb >/dev/null 2>&1; then
    exit $status
  fi
  echo "render.sh: pvbatch died (status $status) on DISPLAY=$DISPLAY;" \
    "trying a virtual display" >&2
  unset DISPLAY
elif ! command -v Xvfb >/dev/null 2>&1; then
  # A ParaView built for offscreen rendering needs no X server; Debian's does.
  pvbatch "$here/render.py" "$@"
  status=$?
  if [ $status -ge 128 ]; then
    echo "render.sh: no DISPLAY and no Xvfb; install it with" \
      "'apt-get install xvfb'" >&2
  fi
  exit $status
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/render.XXXXXX") || exit 1
xvfb_pid="" pvbatch_pid=""
stop() {  # ends this script's pvbatch and Xvfb (if running) and waits for them
  local pid
  for pid in $pvbatch_pid $xvfb_pid; do
    kill "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
  done
  pvbatch_pid="" xvfb_pid=""
}
trap 'stop; rm -rf "$tmp"' EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# Starts Xvfb on a free display; sets display and XAUTHORITY (a cookie for
# this server only). Returns 1 when the server does not come up.
start_xvfb() {
  local auth=() i
  rm -f "$tmp/display" "$tmp/server.auth" "$tmp/client.auth"
  if command -v xauth >/dev/null 2>&1; then
    cookie=$(od -An -N16 -tx1 /dev/urandom | tr -d ' \n')
    # The server takes every cookie of its file, whatever display it names.
    xauth -q -f "$tmp/server.auth" add :0 . "$cookie" 2>/dev/null || return 1
    auth=(-auth "$tmp/server.auth")
  fi
  Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset \
    "${auth[@]}" 3>"$tmp/display" 2>"$tmp/xvfb.log" </dev/null &
  xvfb_pid=$!
  # Xvfb writes the display number once it accepts connections.
  for ((i = 0; i < 600; ++i)); do
    if grep -q '^[0-9][0-9]*$' "$tmp/display" 2>/dev/null; then
      display=:$(cat "$tmp/display")
      if [ ${#auth[@]} -gt 0 ]; then
        xauth -q -f "$tmp/client.auth" add "$display" . "$cookie" \
          2>/dev/null || return 1
        export XAUTHORITY=$tmp/client.auth
      fi
      return 0
    fi
    kill -0 "$xvfb_pid" 2>/dev/null || break
    sleep 0.05
  done
  echo "render.sh: Xvfb did not start:" >&2
  cat "$tmp/xvfb.log" >&2
  return 1
}

status=1
for attempt in 1 2 3; do
  if start_xvfb; then
    DISPLAY=$display pvbatch "$here/render.py" "$@" &
    pvbatch_pid=$!
    wait "$pvbatch_pid"
    status=$?
    pvbatch_pid=""
    # 0: the picture; 1-127: render.py's own errors (no such file or
    # field), which another try does not change.
    [ $status -lt 128 ] && exit $status
    echo "render.sh: pvbatch died (status $status) on the virtual display" \
      "$display (try $attempt of 3)" >&2
  else
    status=1
  fi
  stop
done
echo "render.sh: no picture after 3 tries" >&2
exit $status

#!/usr/bin/env bash
# Runs a program with an X display: the current one, else a private Xvfb through xvfb-run.
#   run_with_display.sh XVFB_RUN_PATH_OR_EMPTY PROGRAM [ARGS...]
# Exit 77 (ctest's skip) when there is neither.
set -euo pipefail
xvfb_run=$1
shift
if [[ -n ${DISPLAY:-} ]]; then
  exec "$@"
fi
if [[ -z $xvfb_run || $xvfb_run == *NOTFOUND ]]; then
  echo "run_with_display.sh: no DISPLAY and no xvfb-run (Debian: xvfb): skipped" >&2
  exit 77
fi
exec "$xvfb_run" -a -s "-screen 0 1280x1024x24" "$@"

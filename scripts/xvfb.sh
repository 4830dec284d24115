#!/usr/bin/env bash
# Runs a command under a virtual X server (VTK here renders through X/GLX on
# Mesa llvmpipe), unless a display is already there.
set -euo pipefail
if [ -n "${DISPLAY:-}" ]; then
  exec "$@"
fi
exec xvfb-run -a -s "-screen 0 1280x1024x24" "$@"

#!/usr/bin/env bash
# The README's main command: installs what is missing, builds (Release), and generates the
# paper's Example 1 and Example 2 with their figures into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
PCSG="${PCSG_BUILD_DIR:-build}/app/pcsg"
mkdir -p out
# `pcsg figures` exits with 3 when pcsg was built without the renderer: then only the graphs.
status=0
if "$PCSG" figures --help >/dev/null 2>&1; then
  "$PCSG" figures --out out || status=$?
else
  status=3
fi
if [ "$status" -eq 3 ]; then
  for ex in example1 example2; do
    "$PCSG" generate "scenes/$ex.yaml" -o "out/$ex"
  done
elif [ "$status" -ne 0 ]; then
  exit "$status"
fi
echo "main: results in out/" >&2

#!/usr/bin/env bash
# The README's main command: installs what is missing, builds (Release), and generates the
# paper's Example 1 and Example 2 with their figures into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
PCSG="${PCSG_BUILD_DIR:-build}/app/pcsg"
mkdir -p out
if "$PCSG" figures --help >/dev/null 2>&1; then
  "$PCSG" figures --out out
else
  for ex in example1 example2; do
    "$PCSG" generate "scenes/$ex.yaml" -o "out/$ex"
  done
fi
echo "main: results in out/" >&2

#!/usr/bin/env bash
# The README's test command: installs what is missing, builds, runs every test (CTest).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
cd "${PCSG_BUILD_DIR:-build}"
ctest --output-on-failure -j"$(nproc)" --timeout 1500

#!/usr/bin/env bash
# The validations (tests/validation): Example 2 generated in other frames and units, with the
# complete search, and from the lens tip, each checked against its stored signature. Hours of
# CPU, which is why they are not in the test suite (scripts/test.sh); run them after changing the
# engine's motions, events or tolerances. Extra arguments go to the gtest binary, e.g.
#   bash scripts/validate.sh --gtest_filter='Validation.LensTip*'
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
exec "${PCSG_BUILD_DIR:-build}/tests/pcsg_validation" "$@"

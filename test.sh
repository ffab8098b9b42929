#!/usr/bin/env bash
# ./test.sh: sets up and builds walkrad with its tests, then runs every test with ctest.
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
ctest --preset release "$@"

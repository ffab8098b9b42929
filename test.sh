#!/usr/bin/env bash
# ./test.sh: sets up and builds walkrad with its tests, then runs every test with ctest, then (where
# clang's libFuzzer is installed) fuzzes every loader and the mesher for 30 s each.
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
ctest --preset release "$@"
if scripts/fuzz.sh --available; then
  scripts/fuzz.sh --quick 0.5
else
  echo "test.sh: no clang++ with libFuzzer (packages clang, libclang-rt-dev): the short fuzzing run is skipped"
fi

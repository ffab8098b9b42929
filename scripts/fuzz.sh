#!/usr/bin/env bash
# scripts/fuzz.sh [--quick] MINUTES [TARGET...]: builds the fuzz preset (clang, libFuzzer,
# ASan, UBSan) into build-fuzz/ and runs every fuzz target of tests/fuzz (or those named) for
# MINUTES each (a decimal: 0.5 is 30 s), two at a time (FUZZ_JOBS=N to change). Each starts from
# its seeds (tests/fuzz/corpus/TARGET) and what earlier runs kept (build-fuzz/corpus/TARGET).
# A crash, a sanitizer report, an unexpected exception, a hang (over 10 s) or more than 2.5 GB is
# a finding: its input is saved in build-fuzz/findings/TARGET/ and the run goes on (libFuzzer's
# fork mode), so one finding does not hide the next. Prints each target's executions and
# findings; exits 1 when there is any.
# --quick (./test.sh's short run): starts from the seeds alone (what earlier runs kept may hold
# inputs that take seconds each, which would make the run's length unpredictable), and does not
# fail on targets that have reproducers of findings still open in tests/fuzz/known/TARGET.
# scripts/fuzz.sh --available: exits 0 when clang++ can build libFuzzer programs here.
set -euo pipefail
cd "$(dirname "$0")/.."

all_targets=(scene_text gltf polygon_case mesh_polygon model_check)
# Per target: its dictionary, and the longest input worth making (the decoders read no more).
declare -A dictionary=([scene_text]=scene [polygon_case]=scene [model_check]=scene [gltf]=gltf)
declare -A max_len=([mesh_polygon]=512 [model_check]=4096)
out=build-fuzz

available() {
  command -v clang++ >/dev/null || return 1
  local probe status=0
  probe=$(mktemp -d)
  echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' >"$probe/p.cpp"
  clang++ -fsanitize=fuzzer,address,undefined "$probe/p.cpp" -o "$probe/p" >/dev/null 2>&1 || status=1
  rm -rf "$probe"
  return $status
}

if [[ ${1:-} == --available ]]; then available; exit; fi
quick=0
if [[ ${1:-} == --quick ]]; then quick=1; shift; fi
if [[ $# -lt 1 || ! $1 =~ ^[0-9]*\.?[0-9]+$ ]]; then
  echo "usage: scripts/fuzz.sh [--quick] MINUTES [TARGET...] (targets: ${all_targets[*]})" >&2
  exit 2
fi
if ! available; then
  echo "fuzz: needs clang++ with libFuzzer (Debian packages clang and libclang-rt-dev)" >&2
  exit 2
fi
seconds=$(awk -v m="$1" 'BEGIN { s = int(m * 60 + 0.5); print s < 1 ? 1 : s }')
shift
targets=("$@")
((${#targets[@]})) || targets=("${all_targets[@]}")
parallel=${FUZZ_JOBS:-2}

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
cmake --preset fuzz "${launcher[@]}" >/dev/null
cmake --build --preset fuzz -j "$parallel"

run() {
  local target=$1
  local options=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1
                 -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2560 -artifact_prefix="$out/findings/$target/")
  [[ -n ${dictionary[$target]:-} ]] && options+=(-dict="tests/fuzz/dictionaries/${dictionary[$target]}.dict")
  [[ -n ${max_len[$target]:-} ]] && options+=(-max_len="${max_len[$target]}")
  local kept=$out/corpus/$target
  if ((quick)); then
    kept=$out/quick-corpus/$target
    rm -rf "$kept"
  fi
  mkdir -p "$kept" "$out/findings/$target"
  UBSAN_OPTIONS=print_stacktrace=1 "$out/tests/fuzz/fuzz_$target" "${options[@]}" \
    "$kept" "tests/fuzz/corpus/$target" >"$out/findings/$target.log" 2>&1
}

# Replays the reproducers of fixed findings (tests/fuzz/regressions/TARGET) under the sanitizers.
replay() {
  local target=$1 files
  mapfile -t files < <(find "tests/fuzz/regressions/$target" -type f 2>/dev/null | sort)
  ((${#files[@]})) || return 0
  # 30 s, not the runs' 10: the slowest reproducer (the model check's dome, 65,536 faces) takes
  # 6-7 s under the sanitizers on a free machine, so a busy one would fail it without a hang.
  if ! "$out/tests/fuzz/fuzz_$target" -timeout=30 -rss_limit_mb=2560 "${files[@]}" >"$out/findings/$target.replay.log" 2>&1; then
    echo "fuzz: $target: a reproducer of tests/fuzz/regressions/$target fails again: see $out/findings/$target.replay.log"
    return 1
  fi
}

# Prints one target's executions and findings; returns 1 when the findings fail the run.
report() {
  local target=$1 log=$out/findings/$1.log
  local last runs found known
  last=$(grep -E '^#[0-9]+: cov:' "$log" | tail -1 || true)
  if [[ -z $last ]]; then
    echo "fuzz: $target did not run: see $log"
    return 1
  fi
  runs=${last%%:*}
  runs=${runs#\#}
  mapfile -t found < <(find "$out/findings/$target" -type f -newer "$out/findings/started" | sort)
  printf 'fuzz: %-13s %9s executions (%s per second), %d findings\n' "$target" "${runs:-?}" \
    "$(awk -v n="${runs:-0}" -v s="$seconds" 'BEGIN { printf "%.0f", n / s }')" "${#found[@]}"
  ((${#found[@]})) || return 0
  grep -hE '^SUMMARY: |runtime error: |ERROR: libFuzzer: |terminate called' "$log" | sed 's/^/      /' | sort | uniq -c | head -20
  printf '      %s\n' "${found[@]:0:10}"
  known=$(find "tests/fuzz/known/$target" -type f 2>/dev/null | wc -l)
  if ((quick && known > 0)); then
    echo "      (tests/fuzz/known/$target holds $known reproducers of findings still open: not failing the run)"
    return 0
  fi
  return 1
}

mkdir -p "$out/findings"
touch "$out/findings/started"
failed=0
for target in "${targets[@]}"; do
  [[ -x $out/tests/fuzz/fuzz_$target ]] || { echo "fuzz: no target $target (targets: ${all_targets[*]})" >&2; exit 2; }
  replay "$target" || failed=1
done
echo "fuzz: ${#targets[@]} targets, ${seconds} s each, $parallel at a time; findings go to $out/findings/"
for target in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= parallel)); do wait -n || true; done
  run "$target" &
done
wait
for target in "${targets[@]}"; do report "$target" || failed=1; done
exit $failed

#!/usr/bin/env bash
# Runs every libFuzzer harness of tests/fuzz for SECONDS each (default 20) from
# its committed seeds (tests/fuzz/corpus/<harness>, plus tests/hostile/corpus
# for frames); new inputs go to BUILD/fuzz-work/<harness>/corpus, findings to
# BUILD/fuzz-work/<harness>/crash-*. Prints executions and coverage per harness
# and exits non-zero when any harness finds a crash, a leak or a time-out.
#   tests/fuzz/run_fuzzers.sh BUILD_DIR [SECONDS]
#   tests/fuzz/run_fuzzers.sh --list      (the harness names, one line)
set -uo pipefail
harnesses=(fuzz_frame fuzz_calibration fuzz_pattern fuzz_scenario fuzz_dataset_csv fuzz_dataset_binary fuzz_queries
           fuzz_spnav_protocol fuzz_options fuzz_c_options fuzz_dds_samples)
if [ "${1:-}" = --list ]; then
  echo "${harnesses[*]}"
  exit 0
fi
build=${1:?usage: run_fuzzers.sh BUILD_DIR [SECONDS]}
seconds=${2:-20}
src="$(cd "$(dirname "$0")/../.." && pwd)"
failed=0
printf "%-22s %8s %12s %10s %8s  %s\n" harness seconds executions exec/s cov result
for h in "${harnesses[@]}"; do
  # fuzz_dds_samples is built with DDS only (ONETIP_WITH_DDS, as CI's sanitizer tree is).
  if [ "$h" = fuzz_dds_samples ] && [ ! -x "$build/tests/fuzz/$h" ]; then
    echo "($h not built: the tree has no DDS)"
    continue
  fi
  work="$build/fuzz-work/$h"
  mkdir -p "$work/corpus"
  seeds=("$src/tests/fuzz/corpus/$h")
  limits=(-rss_limit_mb=2048)
  # fuzz_frame decodes under a 4-Mpx bound: the largest honest allocation is one 4-channel 64-bit
  # image of that size (128 MB), so any single malloc over 256 MB is a header check that let through
  # more than it bounds (the TIFF a second ImageLength hid, found by CI in 10 s).
  [ "$h" = fuzz_frame ] && seeds+=("$src/tests/hostile/corpus") && limits+=(-malloc_limit_mb=256)
  log="$work/log.txt"
  "$build/tests/fuzz/$h" -max_total_time="$seconds" -timeout=10 "${limits[@]}" -max_len=65536 \
    -print_final_stats=1 -artifact_prefix="$work/" "$work/corpus" "${seeds[@]}" >"$log" 2>&1
  status=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  result=ok
  if [ $status -ne 0 ]; then
    result="FAILED (exit $status): $(grep -m1 -E 'ERROR|SUMMARY|deadly signal' "$log")"
    failed=1
  fi
  printf "%-22s %8s %12s %10s %8s  %s\n" "$h" "$seconds" "${execs:-?}" "${rate:-?}" "${cov:-?}" "$result"
done
exit $failed

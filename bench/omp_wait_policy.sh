#!/usr/bin/env bash
# How the OpenMP wait policy holds up when a core is shared (issue 21, "Sharing cores"): the DEM throughput
# benchmark's seed specimen (7020 disks, 1 and 2 threads) under each policy, on a quiet machine and with one
# busy-looping process beside it, the policies alternating round by round. CSV on stdout.
#
#   bash bench/omp_wait_policy.sh [BENCH_BINARY[,BENCH_BINARY...]] [STEPS] [ROUNDS] [POLICY...] > omp_wait_policy.csv
#
# Several binaries (comma-separated: an old and a new build) alternate within each policy, for an A/B of an
# engine change under each policy and load; the binary column names each.
# Policies (default: all four): libgomp's default ("default": spin 300000 iterations at a barrier, then
# sleep), GOMP_SPINCOUNT=10000 and =1000, and OMP_WAIT_POLICY=passive (sleep at once). Any VAR=VALUE runs
# the benchmark with that environment variable. Leave the machine otherwise idle: a build beside it spoils
# both columns.
set -euo pipefail
bench="${1:-build/bench/bench_dem_throughput}"
steps="${2:-10000}"
rounds="${3:-2}"
policies=("default" "GOMP_SPINCOUNT=10000" "GOMP_SPINCOUNT=1000" "OMP_WAIT_POLICY=passive")
[ $# -gt 3 ] && policies=("${@:4}")
IFS=, read -r -a benches <<<"$bench"
echo "round,load,policy,binary,threads,particle_steps_per_s"
busy=""
trap '[ -n "$busy" ] && kill "$busy" 2>/dev/null || true' EXIT
for round in $(seq "$rounds"); do
  for load in quiet one_busy_core; do
    if [ "$load" = one_busy_core ]; then (while :; do :; done) & busy=$!; fi
    for policy in "${policies[@]}"; do
      env_args=()
      [ "$policy" != default ] && env_args=("$policy")
      for b in "${benches[@]}"; do
        env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT "${env_args[@]}" "$b" "$steps" paper |
          awk -F, -v r="$round" -v l="$load" -v p="$policy" -v b="$b" 'NR > 1 { print r "," l "," p "," b "," $4 "," $7 }'
      done
    done
    if [ -n "$busy" ]; then kill "$busy"; wait "$busy" 2>/dev/null || true; busy=""; fi
  done
done

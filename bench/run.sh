#!/usr/bin/env bash
# The Modbus benchmark (issue 3): installs the peers, builds the C programs, runs
# `bench_modbus` and prints the tables (Markdown). Not part of `cargo test` or .ci/run:
# it installs packages and takes a few minutes. Loopback and pseudo-terminals only.
#
#   bench/run.sh                      # defaults: best of 10 interleaved runs of 0.3 s per figure
#   bench/run.sh --seconds 3 --rounds 5 --runs 50
#   bench/run.sh --conditions "fuzzing at nice 10, one build"   # what else the machine is doing
#   bench/run.sh callgrind [ARGS]     # instructions per transaction (bench/callgrind.sh)
#   bench/run.sh oneshot [RUNS]       # one-shot start-up medians only (bench/oneshot.sh)
#
# The output starts with the machine (CPU model, cores, kernel), the commit, the conditions and
# the load average, and ends with each target met or missed, the echo floor, the phase it shows
# (fast or slow: this VM switches between them whatever its load) and the load again.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=full
case "${1:-}" in
    callgrind | oneshot) mode=$1; shift ;;
esac
conditions=${PLCSH_BENCH_CONDITIONS:-}
args=()
while [ $# -gt 0 ]; do
    case "$1" in
        --conditions) conditions=$2; shift 2 ;;
        *) args+=("$1"); shift ;;
    esac
done

need_apt=()
pkg-config --exists libmodbus 2>/dev/null || need_apt+=(libmodbus-dev)
command -v mbpoll >/dev/null || need_apt+=(mbpoll)
command -v cc >/dev/null || need_apt+=(gcc)
command -v pkg-config >/dev/null || need_apt+=(pkg-config)
if [ ${#need_apt[@]} -gt 0 ]; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need_apt[@]}" >/dev/null
fi
# pymodbus 3.16 (the version the figures in BENCHMARKS.md were taken with); pyserial for RTU.
python3 -c 'import pymodbus, serial' 2>/dev/null || python3 -m pip install -q "pymodbus[serial]==3.16.1"

mkdir -p target/bench
for p in mb_client mb_server echo_floor; do
    cc -O2 -Wall -o "target/bench/$p" "bench/c/$p.c" $(pkg-config --cflags --libs libmodbus) -lutil
done

cargo build --release --bin plcsh --bin bench_modbus
# plcsh as installed (`cargo install-static`, README "Install"): the server and one-shot figures
# are of this build; the one-shot table shows the default dynamically linked one beside it.
# Both run from copies, as `cargo install` puts them on the PATH (bench/oneshot.sh says why).
cp target/release/plcsh target/bench/plcsh-dynamic
plcsh_builds=(--plcsh-dynamic target/bench/plcsh-dynamic)
if [ "$(uname -m)" = x86_64 ]; then
    cargo build-static
    cp target/x86_64-unknown-linux-gnu/release/plcsh target/bench/plcsh-static
    plcsh_builds+=(--plcsh target/bench/plcsh-static)
fi
case $mode in
    callgrind) exec bench/callgrind.sh --no-build ${args[@]+"${args[@]}"} ;;
    oneshot) exec bench/oneshot.sh ${args[@]+"${args[@]}"} ;;
esac
PLCSH_BENCH_MACHINE="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores, $(uname -sr)"
PLCSH_BENCH_COMMIT="$(git rev-parse --short HEAD 2>/dev/null || echo unknown)$(git diff --quiet 2>/dev/null || echo ' (with uncommitted changes)'), $(date -u '+%Y-%m-%d %H:%M UTC')"
# What the machine was doing besides this run (given, or what is busiest now).
if [ -z "$conditions" ]; then
    conditions="not given; busiest processes at the start: $(ps -eo pcpu=,ni=,comm= --sort=-pcpu | head -3 | awk '{printf "%s%s (%s%% CPU, nice %s)", (NR>1?", ":""), $3, $1, $2}')"
fi
export PLCSH_BENCH_MACHINE PLCSH_BENCH_COMMIT PLCSH_BENCH_CONDITIONS="$conditions"
exec target/release/bench_modbus --peers target/bench --py bench/py ${plcsh_builds[@]+"${plcsh_builds[@]}"} ${args[@]+"${args[@]}"}

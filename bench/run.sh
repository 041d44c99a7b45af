#!/usr/bin/env bash
# The Modbus benchmark (issue 3): installs the peers, builds the C programs, runs
# `bench_modbus` and prints the tables (Markdown). Not part of `cargo test` or .ci/run:
# it installs packages and takes a few minutes. Loopback and pseudo-terminals only.
#
#   bench/run.sh                      # defaults: best of 10 interleaved runs of 0.3 s per figure
#   bench/run.sh --seconds 3 --rounds 5 --runs 50
set -euo pipefail
cd "$(dirname "$0")/.."

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
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(uname -sr)" >&2
echo "load before the run: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
exec target/release/bench_modbus --peers target/bench --py bench/py "$@"

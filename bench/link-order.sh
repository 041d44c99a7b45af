#!/usr/bin/env bash
# Writes .cargo/link-order.txt: the functions a one-shot runs, which `cargo build-static` asks the
# linker to place first and together (`--symbol-ordering-file`). A one-shot then touches a few
# neighbouring pages of code instead of ~40 pages spread over 6 MB, and every page it touches
# is a page fault at start (BENCHMARKS.md, "One-shot start-up, second round").
#
#   bench/link-order.sh        # needs valgrind; rerun after larger changes
#
# The names are the linker's (mangled). A function whose name changes after this was run is
# simply placed where it would have been without the list: a stale list costs speed, never
# correctness. The runs: a read over Modbus TCP (text and JSON), and a write and read on the
# default simulator.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v valgrind >/dev/null || { echo "bench/link-order.sh needs valgrind (apt-get install valgrind)" >&2; exit 1; }
cargo build --release --bin plcsh
cargo build-static
exe=target/x86_64-unknown-linux-gnu/release/plcsh
. bench/serve-sim.sh
serve_sim target/release/plcsh
run() {
    local out=$1
    shift
    valgrind --tool=callgrind --demangle=no --compress-strings=no --callgrind-out-file="$work/$out" "$@" >/dev/null 2>&1
}
run text "$exe" -c 'get VW0..VW18' -d "tcp://$addr?model=K205-16DT"
run json "$exe" --json -c 'get VW0..VW18' -d "tcp://$addr?model=K205-16DT"
run sim "$exe" --state none -c 'set VW100=5; get VW100'
cat "$work"/text "$work"/json "$work"/sim | sed -n 's/^c\{0,1\}fn=//p' | grep -v '^0x\|^(' | LC_ALL=C sort -u >.cargo/link-order.txt
echo "$(wc -l <.cargo/link-order.txt) functions in .cargo/link-order.txt"
# Cargo does not watch the list: relink so the static build uses it now.
touch src/main.rs
cargo build-static

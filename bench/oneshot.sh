#!/usr/bin/env bash
# One-shot start-up: wall time of whole processes that connect, read 10 registers (VW0..VW18,
# holding registers 100…109) and exit, against one `plcsh sim serve --tcp`, next to libmodbus's
# one-shot client and `true` (starting any process). The programs take turns, RUNS rounds;
# each figure is the median (wall time; the CPU time and minor page faults of the process),
# with the load average before and after.
#
#   bench/oneshot.sh [RUNS] [PLCSH...]    # default 40 runs, the static and the default build
#
# Several plcsh binaries may be given (e.g. builds with different release settings): each is
# measured in the same rounds. Needs target/bench/mb_client (bench/run.sh or bench/callgrind.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-40}
shift || true
bins=("$@")
if [ ${#bins[@]} -eq 0 ]; then
    [ -x target/x86_64-unknown-linux-gnu/release/plcsh ] && bins+=(target/x86_64-unknown-linux-gnu/release/plcsh)
    [ -x target/release/plcsh ] && bins+=(target/release/plcsh)
fi
[ ${#bins[@]} -gt 0 ] || { echo "no plcsh build to measure: cargo build-static (or give PLCSH)" >&2; exit 1; }
. bench/serve-sim.sh
# The server is the first program measured (any build serves the same simulator).
serve_sim "${bins[0]}"
# Each plcsh runs from a copy, as `cargo install` puts it on the PATH: a file the linker has just
# written takes ~15 more page faults per start than the same bytes copied (its page-cache pages
# are smaller), which would measure the build directory rather than the program.
copies=()
for i in "${!bins[@]}"; do
    cp "${bins[$i]}" "$work/plcsh-$i"
    copies+=("${bins[$i]}=$work/plcsh-$i")
done
python3 - "$runs" "$addr" "${copies[@]}" <<'EOF'
import os, statistics, sys, time
runs, addr, bins = int(sys.argv[1]), sys.argv[2], [b.split("=", 1) for b in sys.argv[3:]]
host, port = addr.rsplit(":", 1)
url = f"tcp://{addr}?model=K205-16DT"
progs = [(name, [copy, "-c", "get VW0..VW18", "-d", url]) for name, copy in bins]
progs += [("libmodbus client (C)", ["target/bench/mb_client", "tcp", host, port, "--once"]), ("true", ["/usr/bin/true"])]
load = lambda: " ".join(open("/proc/loadavg").read().split()[:3])
print(f"machine: {os.cpu_count()} cores, load before: {load()}; {runs} interleaved runs each")
wall = {name: [] for name, _ in progs}
cpu = {name: [] for name, _ in progs}
faults = {name: [] for name, _ in progs}
devnull = [(os.POSIX_SPAWN_OPEN, 1, "/dev/null", os.O_WRONLY, 0), (os.POSIX_SPAWN_OPEN, 2, "/dev/null", os.O_WRONLY, 0)]
for _ in range(runs):
    for name, argv in progs:
        # posix_spawn and wait4: the same small cost for every program, and the child's own
        # CPU time and minor page faults from its rusage.
        t0 = time.perf_counter()
        pid = os.posix_spawn(argv[0], argv, os.environ, file_actions=devnull)
        _, status, ru = os.wait4(pid, 0)
        wall[name].append(time.perf_counter() - t0)
        assert os.waitstatus_to_exitcode(status) == 0, f"{name} failed"
        cpu[name].append(ru.ru_utime + ru.ru_stime)
        faults[name].append(ru.ru_minflt)
med = {k: statistics.median(v) * 1e3 for k, v in wall.items()}
lib, true = med["libmodbus client (C)"], med["true"]
print(f"load after: {load()}\n")
print("| program | median | beyond `true` | vs libmodbus one-shot | CPU (median) | minor faults |")
print("|---|---:|---:|---:|---:|---:|")
for name, _ in progs:
    print(f"| {name} | {med[name]:.2f} ms | {med[name] - true:.2f} ms | {med[name] / lib:.2f}× "
          f"| {statistics.median(cpu[name]) * 1e3:.2f} ms | {statistics.median(faults[name]):.0f} |")
EOF

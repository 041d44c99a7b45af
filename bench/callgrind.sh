#!/usr/bin/env bash
# Instructions per Modbus transaction, counted by callgrind (valgrind), for plcsh's driver and
# server next to libmodbus's client and server. Instruction counts do not depend on how
# loaded the machine is, so they compare runs made on different days and machines.
#
# Each side runs twice under callgrind, with FEW and with MANY transactions (one request in
# flight); the difference of the two totals divided by MANY - FEW is the cost of one
# transaction, with start-up, connection and shutdown cancelled out. The peer on the other end
# runs natively (a client under measurement talks to libmodbus's server; a server under
# measurement is driven by libmodbus's client).
#
#   bench/callgrind.sh                  # FC 03, 100 holding registers over TCP; 1 register over RTU on a pty
#   bench/callgrind.sh --few 200 --many 2200
#   bench/callgrind.sh --no-build       # use the binaries already built
#
# Needs valgrind, libmodbus-dev (bench/run.sh installs the latter). Loopback and ptys only.
set -euo pipefail
cd "$(dirname "$0")/.."

few=200
many=2200
build=1
while [ $# -gt 0 ]; do
    case "$1" in
        --few) few=$2; shift 2 ;;
        --many) many=$2; shift 2 ;;
        --no-build) build=0; shift ;;
        *) echo "usage: bench/callgrind.sh [--few N] [--many N] [--no-build]" >&2; exit 2 ;;
    esac
done

command -v valgrind >/dev/null || { echo "valgrind is needed (apt-get install valgrind)" >&2; exit 1; }
if [ $build = 1 ]; then
    mkdir -p target/bench
    for p in mb_client mb_server; do
        cc -O2 -Wall -o "target/bench/$p" "bench/c/$p.c" $(pkg-config --cflags --libs libmodbus) -lutil
    done
    cargo build --release --bin plcsh --bin bench_modbus >&2
fi
PLCSH=target/release/plcsh
BENCH=target/release/bench_modbus
C_CLIENT=target/bench/mb_client
C_SERVER=target/bench/mb_server
work=$(mktemp -d /tmp/plcsh-callgrind.XXXXXX)
pids=()
cleanup() {
    for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
    wait 2>/dev/null || true
    rm -rf "$work"
}
trap cleanup EXIT

# Starts a server in the background (its pid in $server_pid); its readiness line (JSON) lands
# in $work/$1.ready.
start_server() {
    local name=$1
    shift
    "$@" >"$work/$name.ready" 2>"$work/$name.err" &
    server_pid=$!
    pids+=($!)
    local pid=$!
    for _ in $(seq 1 600); do
        [ -s "$work/$name.ready" ] && return
        kill -0 "$pid" 2>/dev/null || { cat "$work/$name.err" >&2; exit 1; }
        sleep 0.05
    done
    echo "$name: no readiness line" >&2
    exit 1
}
field() { python3 -c 'import json,sys; print(json.loads(open(sys.argv[1]).readline())[sys.argv[2]])' "$1" "$2"; }
# The instruction total callgrind reports ("Collected : N") in a valgrind log.
collected() { sed -n 's/.*Collected : \([0-9]*\).*/\1/p' "$1" | tail -1; }
cg() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$@"; }

# A client under callgrind against a native server: instructions for N transactions.
client_ir() {
    local log=$work/client.log
    cg --log-file="$log" "$@" >/dev/null
    collected "$log"
}

# A server under callgrind, driven by the native libmodbus client with N transactions, then
# stopped with SIGTERM: its instruction total. KIND: tcp (the readiness line's "tcp"), rtu (its
# "path") or rtu=DEVICE.
server_ir() {
    local kind=$1 n=$2 regs=$3
    shift 3
    local log=$work/server.log
    rm -f "$log" "$work/srv.ready"
    start_server srv valgrind --tool=callgrind --callgrind-out-file=/dev/null --log-file="$log" "$@"
    case "$kind" in
        tcp)
            local addr
            addr=$(field "$work/srv.ready" tcp)
            "$C_CLIENT" tcp "${addr%:*}" "${addr##*:}" "$regs" "$n" 100000 >/dev/null
            ;;
        rtu=*) "$C_CLIENT" rtu "${kind#rtu=}" 115200 "$regs" "$n" 100000 >/dev/null ;;
        rtu) "$C_CLIENT" rtu "$(field "$work/srv.ready" path)" 115200 "$regs" "$n" 100000 >/dev/null ;;
    esac
    kill -TERM "$server_pid"
    wait "$server_pid" 2>/dev/null || true
    collected "$log"
}

per_tx() { python3 -c "import sys; a,b,f,m=map(int,sys.argv[1:]); print(f'{(b-a)/(m-f):.0f}')" "$1" "$2" "$few" "$many"; }

# Native servers for the clients under measurement.
start_server libtcp "$C_SERVER" tcp 0
lib_tcp=$(field "$work/libtcp.ready" tcp)
start_server librtu "$C_SERVER" rtu
lib_rtu=$(field "$work/librtu.ready" path)

row() { printf '| %s | %s | %s |\n' "$1" "$2" "$3"; }
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(uname -sr); $(valgrind --version)"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "transactions: $many - $few (the difference of two runs under callgrind)"
echo
echo "| side | FC 03, 100 registers, TCP | FC 03, 1 register, RTU on a pty |"
echo "|---|---:|---:|"

tcp_url="tcp://$lib_tcp?model=K205-16DT&retries=0"
rtu_url="rtu:$lib_rtu?baud=115200&model=K205-16DT&retries=0"
d_tcp=$(per_tx "$(client_ir "$BENCH" transactions "$tcp_url" 100 "$few")" "$(client_ir "$BENCH" transactions "$tcp_url" 100 "$many")")
d_rtu=$(per_tx "$(client_ir "$BENCH" transactions "$rtu_url" 1 "$few")" "$(client_ir "$BENCH" transactions "$rtu_url" 1 "$many")")
row "plcsh driver → libmodbus server" "$d_tcp" "$d_rtu"
c_tcp=$(per_tx "$(client_ir "$C_CLIENT" tcp "${lib_tcp%:*}" "${lib_tcp##*:}" 100 "$few" 100000)" \
    "$(client_ir "$C_CLIENT" tcp "${lib_tcp%:*}" "${lib_tcp##*:}" 100 "$many" 100000)")
c_rtu=$(per_tx "$(client_ir "$C_CLIENT" rtu "$lib_rtu" 115200 1 "$few" 100000)" \
    "$(client_ir "$C_CLIENT" rtu "$lib_rtu" 115200 1 "$many" 100000)")
row "libmodbus client → libmodbus server" "$c_tcp" "$c_rtu"

link=$work/k2-pty
s_tcp=$(per_tx "$(server_ir tcp "$few" 100 "$PLCSH" --state none sim serve --tcp 0 --model K205-16DT)" \
    "$(server_ir tcp "$many" 100 "$PLCSH" --state none sim serve --tcp 0 --model K205-16DT)")
s_rtu=$(per_tx "$(server_ir "rtu=$link" "$few" 1 "$PLCSH" --state none sim serve --rtu-pty "$link" --model K205-16DT)" \
    "$(server_ir "rtu=$link" "$many" 1 "$PLCSH" --state none sim serve --rtu-pty "$link" --model K205-16DT)")
row "plcsh sim serve ← libmodbus client" "$s_tcp" "$s_rtu"
l_tcp=$(per_tx "$(server_ir tcp "$few" 100 "$C_SERVER" tcp 0)" "$(server_ir tcp "$many" 100 "$C_SERVER" tcp 0)")
l_rtu=$(per_tx "$(server_ir rtu "$few" 1 "$C_SERVER" rtu)" "$(server_ir rtu "$many" 1 "$C_SERVER" rtu)")
row "libmodbus server ← libmodbus client" "$l_tcp" "$l_rtu"

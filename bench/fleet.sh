#!/usr/bin/env bash
# Fleet publishing at scale: `plcsh publish -f bench` and a pymodbus + paho peer
# (bench/py/fleet_peer.py), one after the other in one run, against the same served fleet of
# simulated K2s (`plcsh sim serve --fleet N`), the same mosquitto on a free loopback port and
# an independent subscriber (bench/py/fleet_sub.py). For each case: devices, the offered rate,
# the rate the subscriber saw per device, CPU of the poller (% of one core), its peak RSS,
# poll->subscriber latency p50/p99, what went missing (by `seq`, plus plcsh's own counters), and
# the poller's CPU per published value (its CPU seconds over the window / the values the
# subscriber received in it, in µs). The subscriber checks every value message's topic against
# its payload (`misattributed`: a value published under another device's or operand's topic).
#
#   bench/fleet.sh [PLCSH] [CASE…]      CASE: DEVICES:HZ (default: 500:10 1000:10 5000:1)
#   SECS=15 WARM=4 REGS=3 PEER=1 bench/fleet.sh target/release/plcsh 1000:10
#   PROFILE=1 …: also `perf record -g` plcsh over the window (report in /tmp/plcsh-fleet-N.perf)
#
#   PROPERTY=100000 bench/fleet.sh …: first the publisher's property test (src/publish/property.rs,
#   1 000 generated runs in CI) at plant size: that many generated runs, release build
#   BROKER_PROPERTY=40 PROPERTY_FLEET=1000 bench/fleet.sh …: first the same invariant against a
#   real broker (tests/publish_property.rs, 10 cases over 3 devices in CI) at plant size: that many
#   generated cases over 3 faulted and restarted devices and PROPERTY_FLEET more, release build
#   (BROKER_PROPERTY_PROFILE=dev: the debug build, which needs no release build of the tests)
#
# Use a release build for figures. Machine load is printed before each case.
set -u
exe=${1:-target/release/plcsh}
shift || true
cases=${*:-500:10 1000:10 5000:1}
secs=${SECS:-15}
warm=${WARM:-4}
regs=${REGS:-3}
peer=${PEER:-1}
py=/usr/bin/python3
here=$(cd "$(dirname "$0")" && pwd)
mosq=$(command -v mosquitto || echo /usr/sbin/mosquitto)
work=$(mktemp -d /tmp/plcsh-fleet-bench.XXXXXX)
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done; wait 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
ulimit -n "$(ulimit -Hn)" 2>/dev/null

if [ "${PROPERTY:-0}" != 0 ]; then
    echo "# $(date -u +%FT%TZ) property test: $PROPERTY generated runs; load: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
    (cd "$here/.." && PLCSH_BENCH_PUBLISH_CASES=$PROPERTY cargo test --release --lib publish::property -- --nocapture 2>&1 |
        grep -E "cases|test result|panicked") || exit 1
fi

if [ "${BROKER_PROPERTY:-0}" != 0 ]; then
    echo "# $(date -u +%FT%TZ) property test with a broker: $BROKER_PROPERTY generated cases, 3 + ${PROPERTY_FLEET:-1000} devices; load: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
    (cd "$here/.." && PLCSH_BENCH_PUBLISH_BROKER_CASES=$BROKER_PROPERTY PLCSH_BENCH_PUBLISH_BROKER_FLEET=${PROPERTY_FLEET:-1000} \
        cargo test --profile "${BROKER_PROPERTY_PROFILE:-release}" --test publish_property -- --nocapture 2>&1 | grep -E "^case|cases over|test result|panicked") || exit 1
fi

free_port() { $py -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
ticks() { awk '{print $14+$15}' "/proc/$1/stat" 2>/dev/null || echo 0; }
# Samples VmRSS of PID every 0.5 s into FILE until it exits; the peak is the largest line.
rss_watch() { while [ -e "/proc/$1" ]; do awk '/VmRSS/{print $2}' "/proc/$1/status" 2>/dev/null >>"$2"; sleep 0.5; done; }

# measure NAME GROUP N HZ CMD…: starts the poller, lets it warm up, measures SECS, stops it.
measure() {
    local name=$1 group=$2 n=$3 hz=$4
    shift 4
    local start=$(($(date +%s) + warm))
    $py "$here/py/fleet_sub.py" "$bport" "$group" "$start" "$secs" "$n" "$regs" "$hz" >"$work/sub.$group" &
    local sub=$!
    sleep 0.3
    "$@" >"$work/out.$group" 2>"$work/err.$group" &
    local p=$!
    : >"$work/rss.$group"
    rss_watch "$p" "$work/rss.$group" &
    local w=$!
    sleep "$(($(date +%s) >= start ? 0 : start - $(date +%s)))"
    local t0 c0 t1 c1
    t0=$(date +%s.%N); c0=$(ticks "$p")
    if [ "${PROFILE:-0}" = 1 ] && [ "$name" = plcsh ]; then
        perf record -q -g -F 499 -o "/tmp/plcsh-fleet-$n.perf" -p "$p" -- sleep "$secs" 2>/dev/null
    else
        sleep "$secs"
    fi
    t1=$(date +%s.%N); c1=$(ticks "$p")
    kill -INT "$p" 2>/dev/null
    wait "$p"; local rc=$?
    wait "$sub" "$w" 2>/dev/null
    local hz_tck; hz_tck=$(getconf CLK_TCK)
    local cpu; cpu=$(echo "($c1 - $c0) / $hz_tck / ($t1 - $t0) * 100" | bc -l)
    local rss; rss=$(sort -n "$work/rss.$group" | tail -1)
    local dt; dt=$(echo "$t1 - $t0" | bc -l)
    $py - "$name" "$n" "$hz" "$cpu" "${rss:-0}" "$rc" "$work/sub.$group" "$work/out.$group" "$dt" <<'PY'
import json, sys
name, n, hz, cpu, rss, rc, subf, outf, dt = sys.argv[1:10]
s = json.loads(open(subf).read() or "{}")
lines = open(outf).read().splitlines()
summary = lines[-1] if lines else ""
try:
    own = json.loads(summary)
except ValueError:
    own = {"raw": summary[:200]}
keep = {"misattributed": s.get("misattributed"), "checked": s.get("checked")}
keep.update({k: own[k] for k in ("published", "skipped", "dropped_behind", "dropped_broker_away", "undelivered") if k in own})
lat = s.get("latency_ms", {})
values = s.get("messages") or 0
per_value = "%.1f µs" % (float(cpu) / 100 * float(dt) / values * 1e6) if values else "—"
print("| %s | %s | %s Hz | %s Hz | %.0f %% | %s | %.0f MiB | %s | %s | %s | %s | exit %s |" % (
    name, n, hz, s.get("rate_hz"), float(cpu), per_value, int(rss) / 1024, lat.get("p50"), lat.get("p99"),
    s.get("missing_by_seq"), json.dumps(keep, separators=(",", ":")), rc))
PY
}

echo "| poller | devices | offered | seen per device | CPU (one core) | CPU per value | peak RSS | p50 ms | p99 ms | missing (seq) | own counters | |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
for c in $cases; do
    n=${c%%:*}
    hz=${c##*:}
    period_ms=$((1000 / hz))
    echo "# $(date -u +%FT%TZ) $n devices at $hz Hz; load: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores" >&2
    rm -f "$work/ready" "$work/addrs" "$work/fleet.toml"
    "$exe" --state none sim serve --fleet "$n" --tcp 127.0.0.1:0 >"$work/ready" 2>"$work/serve.err" &
    srv=$!
    pids+=("$srv")
    # Ready once its whole readiness line is there (a large fleet's line is written in pieces).
    for _ in $(seq 1 600); do
        $py -c 'import json, sys; json.loads(open(sys.argv[1]).readline())' "$work/ready" 2>/dev/null && break
        sleep 0.1
    done
    $py - "$work/ready" "$work/fleet.toml" "$work/addrs" <<'PY'
import json, sys
r = json.loads(open(sys.argv[1]).readline())
open(sys.argv[2], "w").write("[fleets.bench]\ndevices = [%s]\n" % ", ".join('"tcp://%s"' % a for a in r["fleet"]))
open(sys.argv[3], "w").write(" ".join(r["fleet"]))
PY
    [ -s "$work/addrs" ] || { echo "sim serve --fleet $n did not get ready: $(cat "$work/serve.err")" >&2; exit 1; }
    bport=$(free_port)
    printf 'listener %s 127.0.0.1\nallow_anonymous true\nmax_queued_messages 100000\n%s' "$bport" \
        "$([ "$(id -u)" = 0 ] && echo 'user root')" >"$work/mosq.conf"
    "$mosq" -c "$work/mosq.conf" >/dev/null 2>&1 &
    brk=$!
    pids+=("$brk")
    for _ in $(seq 1 100); do (exec 3<>"/dev/tcp/127.0.0.1/$bport") 2>/dev/null && break; sleep 0.05; done
    ops=""
    for ((j = 0; j < regs; j++)); do ops="$ops VW$((100 + 2 * j))"; done
    # shellcheck disable=SC2086
    measure plcsh bench "$n" "$hz" "$exe" --state none --config "$work/fleet.toml" --json publish -f bench \
        --broker "mqtt://127.0.0.1:$bport" --every "${period_ms}ms" $ops
    if [ "$peer" = 1 ]; then
        # shellcheck disable=SC2046
        measure "pymodbus+paho" peer "$n" "$hz" $py "$here/py/fleet_peer.py" "$bport" peer \
            "$(echo "1 / $hz" | bc -l)" "$regs" $(cat "$work/addrs")
    fi
    kill "$brk" "$srv" 2>/dev/null
    wait "$brk" "$srv" 2>/dev/null
    pids=()
done

# Sourced by the scripts that measure or exercise one-shots (bench/oneshot.sh,
# bench/link-order.sh, .ci/static-smoke). serve_sim EXE starts `EXE sim serve --tcp 0`
# (a K205-16DT keeping no state), waits for its ready line, and sets $addr (127.0.0.1:PORT)
# and $work (a temporary folder); both the server and the folder go at exit.
serve_sim() {
    work=$(mktemp -d /tmp/plcsh-serve.XXXXXX)
    "$1" --state none sim serve --tcp 0 --model K205-16DT >"$work/ready" 2>"$work/err" &
    server=$!
    trap 'kill $server 2>/dev/null; wait $server 2>/dev/null; rm -rf "$work"' EXIT
    for _ in $(seq 1 200); do [ -s "$work/ready" ] && break; sleep 0.05; done
    addr=$(sed -n 's/.*"tcp":"\(127\.0\.0\.1:[0-9]*\)".*/\1/p' "$work/ready")
    [ -n "$addr" ] || { echo "sim serve did not get ready: $(cat "$work/ready" "$work/err")" >&2; exit 1; }
}

#!/usr/bin/env bash
# ./ripv demo — the whole system on this machine: RIPVServer, the three services on their
# embedded defaults, a simulated glider that calls in (surfaces, talks, dives, calls again), and
# the GUI logged in as the demo operator.
# With no display it prints how to connect with the CLI instead. Ctrl-C stops everything.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

demo_usage() {
  cat <<'USAGE'
Usage: ripv demo

Starts the whole system on this machine: a RIPVServer, the SerialPortServer, DatabaseServer and
DataVisServer on their embedded defaults, a simulated glider on TCP, and the GUI logged in as the
demo operator 'demo' (with no display: how to connect with the CLI). Ctrl-C stops everything.

Environment:
  RIPV_DEMO_DIR        where data, logs and the demo password go (default: .ripv-demo in the source tree)
  RIPV_PORT            client port (default 4444)
  RIPV_REGISTRY_PORT   RMI registry port (default 1099)
  RIPV_HTTP_PORT       landing page port (default 8080)
  RIPV_GLIDER_PORT     the simulated glider's TCP port (default 5555)
  RIPV_DEMO_HEADLESS=1 no GUI even with a display
USAGE
}
for a in "$@"; do
  case "$a" in
    -h|--help) demo_usage; exit 0 ;;
    -V|--version) exec "$ROOT/ripv" --version ;;
    *) echo "ripv demo: unknown option '$a'" >&2; demo_usage >&2; exit 2 ;;
  esac
done
[ "${RIPV_PARSE_ONLY:-}" = 1 ] && exit 0   # a dry run: the command line is fine
JAVA="${JAVA:-java}"
DEMO="${RIPV_DEMO_DIR:-$ROOT/.ripv-demo}"
PORT="${RIPV_PORT:-4444}"
REGISTRY="${RIPV_REGISTRY_PORT:-1099}"
HTTP="${RIPV_HTTP_PORT:-8080}"
GLIDER="${RIPV_GLIDER_PORT:-5555}"
GLIDER_NAME="${RIPV_GLIDER_NAME:-sim01}"
DIVE="${RIPV_DIVE_SECONDS:-30}"
SURFACE="${RIPV_SURFACE_SECONDS:-60}"
# Everything listens on this machine only unless told otherwise (--bind ADDRESS or RIPV_BIND;
# 0.0.0.0 for every interface). The services listen on loopback anyway: only the server calls them.
BIND="${RIPV_BIND:-127.0.0.1}"
while [ $# -gt 0 ]; do
  case "$1" in
    --bind) BIND="${2:?--bind needs an address}"; shift 2 ;;
    --bind=*) BIND="${1#--bind=}"; shift ;;
    *) echo "demo: unknown option '$1' (the demo takes --bind ADDRESS)" >&2; exit 2 ;;
  esac
done
# where this script and the services reach what listens on $BIND
case "$BIND" in
  0.0.0.0|::|127.*|localhost) HERE=localhost ;;
  *) HERE="$BIND" ;;
esac
USER_NAME=demo
PASSWORD=ripv-demo-operator
jar() { echo "$ROOT/$1/target/$1.jar"; }

mkdir -p "$DEMO/logs" "$DEMO/server"
pids=()
stop_all() {
  trap - INT TERM EXIT
  if [ ${#pids[@]} -gt 0 ]; then
    echo "demo: stopping..." >&2
    kill "${pids[@]}" 2>/dev/null || true
    wait "${pids[@]}" 2>/dev/null || true
  fi
}
trap stop_all EXIT
trap 'exit 130' INT TERM

port_free() { ! (exec 3<>"/dev/tcp/$HERE/$1") 2>/dev/null; }
wait_port() {
  local i
  for i in $(seq 1 150); do
    (exec 3<>"/dev/tcp/$HERE/$1") 2>/dev/null && return 0
    sleep 0.2
  done
  echo "demo: nothing answered on port $1; see $DEMO/logs/" >&2
  exit 1
}
for p in "$PORT" "$REGISTRY" "$HTTP" "$GLIDER"; do
  if ! port_free "$p"; then
    echo "demo: port $p is in use. Stop what uses it, or set RIPV_PORT / RIPV_REGISTRY_PORT / RIPV_HTTP_PORT / RIPV_GLIDER_PORT." >&2
    exit 1
  fi
done

permit="$DEMO/server/permit.txt"
if ! grep -q "^user $USER_NAME " "$permit" 2>/dev/null; then
  echo "$PASSWORD" | "$JAVA" -jar "$(jar ripv-server)" passwd --permit "$permit" "$USER_NAME" --roles operators >/dev/null
  echo "ripv-demo-observer" | "$JAVA" -jar "$(jar ripv-server)" passwd --permit "$permit" observer --roles observers,db-reader >/dev/null
fi
printf '%s\n' "$PASSWORD" > "$DEMO/password"
chmod 600 "$DEMO/password"

# The server makes its TLS certificate on first start; the demo's clients remember it in a file of
# the demo's own (a fresh demo directory means a new certificate, so forget the old one then).
KNOWN="$DEMO/known_hosts"
[ -f "$DEMO/server/tls/server.p12" ] || rm -f "$KNOWN"
export RIPV_KNOWN_HOSTS="$KNOWN"

echo "demo: starting the RIPVServer (logs in $DEMO/logs)" >&2
"$JAVA" -jar "$(jar ripv-server)" server --data "$DEMO/server" --port "$PORT" --registry-port "$REGISTRY" \
  --http-port "$HTTP" --bind "$BIND" >"$DEMO/logs/server.log" 2>&1 &
pids+=($!)
wait_port "$PORT"
secret="$DEMO/server/service.secret"
for s in "$ROOT"/docs/samples/*.dat; do
  [ -f "$s" ] && [ ! -f "$DEMO/server/upload/$(basename "$s")" ] && cp "$s" "$DEMO/server/upload/"
done

echo "demo: starting the SerialPortServer (glider $GLIDER_NAME calls in on port $GLIDER), DatabaseServer and DataVisServer" >&2
"$JAVA" -Dripv.host=localhost -jar "$(jar ripv-services)" serial --server "$HERE:$REGISTRY" --secret-file "$secret" \
  --link "listen://$BIND:$GLIDER,name=$GLIDER_NAME" --carrier ignore --no-enumerate >"$DEMO/logs/serial.log" 2>&1 &
pids+=($!)
# not wait_port: a connection to the glider's port would be taken for a call
for i in $(seq 1 150); do
  grep -q "MailBoxes:" "$DEMO/logs/serial.log" 2>/dev/null && break
  sleep 0.2
done

echo "demo: the simulated glider $GLIDER_NAME calls in for $SURFACE s, dives for $DIVE s, and calls again" >&2
"$JAVA" -jar "$(jar ripv-services)" simulator --call "$HERE:$GLIDER" --name "$GLIDER_NAME" \
  --dive-seconds "$DIVE" --surface-seconds "$SURFACE" --dir "$DEMO/glider" >"$DEMO/logs/simulator.log" 2>&1 &
pids+=($!)
"$JAVA" -Dripv.host=localhost -jar "$(jar ripv-services)" database --server "$HERE:$REGISTRY" --secret-file "$secret" \
  --data "$DEMO/database" >"$DEMO/logs/database.log" 2>&1 &
pids+=($!)
"$JAVA" -Dripv.host=localhost -jar "$(jar ripv-services)" datavis --server "$HERE:$REGISTRY" --secret-file "$secret" \
  --workdir "$DEMO/datavis" >"$DEMO/logs/datavis.log" 2>&1 &
pids+=($!)

cli_hint() {
  cat <<HINT

RIPV demo is running. Connect with the CLI, e.g.:

  ./ripv cli --server localhost:$PORT --known-hosts $KNOWN --user $USER_NAME --password-file $DEMO/password \\
      --exec '?services' --exec '?mailboxes' \\
      --exec '?status <SerialPortServer>::<localhost>$GLIDER_NAME' \\
      --exec 'use <SerialPortServer>::<localhost>$GLIDER_NAME' --exec 'dir'

  The glider $GLIDER_NAME is on a call for $SURFACE s, then dives for $DIVE s: ?status shows
  "on call since ..." or "dived at ...", and commands work while it is on a call.

  Database:  --exec 'use <DatabaseServer>::<localhost>TTY1' --exec 'SELECT * FROM mission'
  Plot:      --exec 'use <DataVisServer>::<localhost>TTY1' --exec 'vis:glider-temperature.dat'
  Web console: https://localhost:$HTTP/ (log in as $USER_NAME, password in $DEMO/password; the server's own certificate: your browser asks first)
  Server certificate: $(grep -o 'SHA256:[0-9A-F:]*' "$DEMO/logs/server.log" | head -1)
  Logs: $DEMO/logs/

Press Ctrl-C to stop everything.
HINT
}

if [ -n "${DISPLAY:-}" ] && [ "${RIPV_DEMO_HEADLESS:-}" != 1 ]; then
  echo "demo: opening the client as '$USER_NAME'" >&2
  "$JAVA" -jar "$(jar ripv-client)" client "localhost:$PORT" --user "$USER_NAME" --password-file "$DEMO/password" \
    >"$DEMO/logs/client.log" 2>&1 &
  pids+=($!)
  cli_hint
  wait "${pids[-1]}" || true
else
  echo "demo: no display (DISPLAY is not set), so no GUI." >&2
  cli_hint
  wait
fi

#!/usr/bin/env bash
# ./ripv demo — the whole system on this machine: RIPVServer, the three services on their
# embedded defaults, a simulated glider that calls in (surfaces, talks, dives, calls again), and
# the GUI logged in as the demo operator.
# With no display it prints how to connect with the CLI instead. Ctrl-C stops everything.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

demo_usage() {
  cat <<'USAGE'
Usage: ripv demo [--bind ADDRESS] | ripv demo --stop

Starts the whole system on this machine: a RIPVServer, the SerialPortServer, DatabaseServer and
DataVisServer on their embedded defaults, a simulated glider on TCP, and the GUI logged in as the
demo operator 'demo' (with no display: how to connect with the CLI). Ctrl-C stops everything.
Builds the jars first when they are missing. One demo per RIPV_DEMO_DIR: a second one says which
process runs the first and exits 1, touching nothing.

  --bind ADDRESS       listen on ADDRESS (default 127.0.0.1; 0.0.0.0 for every interface)
  --stop               stop the demo running from RIPV_DEMO_DIR (from another terminal)

Environment:
  RIPV_DEMO_DIR        where data, logs and the demo password go (default: .ripv-demo in the source tree)
  RIPV_PORT            client port (default 4444)
  RIPV_REGISTRY_PORT   RMI registry port (default 1099)
  RIPV_HTTP_PORT       landing page port (default 8080)
  RIPV_GLIDER_PORT     the simulated glider's TCP port (default 5555)
  RIPV_OUTBOUND_PORT   where services behind NAT connect out (default 4446; -1: none)
  RIPV_WEBHOOK_PORT    the demo's webhook receiver on 127.0.0.1, for trying notifications (default 4447)
  RIPV_GLIDER_DIALOG   picodos (default) or gliderdos: a Slocum's surface dialog, control keys and GliderDOS
  RIPV_GLIDER_LINE     unset, or iridium: the glider's calls at 2,400 baud, 1 s latency, dropped after 60 s
  RIPV_DEMO_HEADLESS=1 no GUI even with a display
USAGE
}
STOP=0
# Everything listens on this machine only unless told otherwise (--bind ADDRESS or RIPV_BIND;
# 0.0.0.0 for every interface). The services listen on loopback anyway: only the server calls them.
BIND="${RIPV_BIND:-127.0.0.1}"
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) demo_usage; exit 0 ;;
    -V|--version) exec "$ROOT/ripv" --version ;;
    --stop) STOP=1; shift ;;
    --bind) [ $# -ge 2 ] || { echo "ripv demo: --bind needs an address, e.g. --bind 0.0.0.0" >&2; exit 2; }
            BIND="$2"; shift 2 ;;
    --bind=*) BIND="${1#--bind=}"; shift ;;
    *) echo "ripv demo: unknown option '$1'" >&2; demo_usage >&2; exit 2 ;;
  esac
done
[ "${RIPV_PARSE_ONLY:-}" = 1 ] && exit 0   # a dry run: the command line is fine
JAVA="${JAVA:-java}"
DEMO="${RIPV_DEMO_DIR:-$ROOT/.ripv-demo}"
PIDFILE="$DEMO/demo.pid"
PORT="${RIPV_PORT:-4444}"
REGISTRY="${RIPV_REGISTRY_PORT:-1099}"
HTTP="${RIPV_HTTP_PORT:-8080}"
GLIDER="${RIPV_GLIDER_PORT:-5555}"
OUTBOUND="${RIPV_OUTBOUND_PORT:-4446}"
WEBHOOK="${RIPV_WEBHOOK_PORT:-4447}"
GLIDER_NAME="${RIPV_GLIDER_NAME:-sim01}"
DIVE="${RIPV_DIVE_SECONDS:-30}"
SURFACE="${RIPV_SURFACE_SECONDS:-60}"
GLIDER_DIALOG="${RIPV_GLIDER_DIALOG:-picodos}"
case "$GLIDER_DIALOG" in
  picodos) LINK_PROMPT="" ;;
  # GliderDOS's prompt and PicoDOS's; the default alert= leaves the countdown and ABORT HISTORY
  # alone, and the server reads each surface dialog for aborts, leaks, … (docs/surfacings.md)
  gliderdos) LINK_PROMPT=",prompt-regex=Glider[Dd][Oo][Ss] [A-Z] -?[0-9]+ >|C:\\\\>" ;;
  *) echo "demo: RIPV_GLIDER_DIALOG '$GLIDER_DIALOG' is neither picodos nor gliderdos" >&2; exit 2 ;;
esac
case "${RIPV_GLIDER_LINE:-}" in
  "") GLIDER_LINE=() ;;
  iridium) GLIDER_LINE=(--baud 2400 --latency 1s --drop-after 60s) ;;
  *) echo "demo: RIPV_GLIDER_LINE '$RIPV_GLIDER_LINE' is not iridium (or unset)" >&2; exit 2 ;;
esac
# Per-user files (the clients' known_hosts and preferences) go under $HOME, as with ./ripv.
USER_HOME=()
[ -n "${HOME:-}" ] && USER_HOME=(-Duser.home="$HOME")

if [ -n "${RIPV_DEMO_DIR:-}" ]; then STOP_HINT="RIPV_DEMO_DIR=$DEMO ./ripv demo --stop"; else STOP_HINT="./ripv demo --stop"; fi

# The demo running from $DEMO, if any: its pid (the pid file names a live demo script).
running_demo() {
  local pid
  pid=$(head -1 "$PIDFILE" 2>/dev/null) || return 1
  [[ "$pid" =~ ^[0-9]+$ ]] && [ -r "/proc/$pid/cmdline" ] && tr '\0' ' ' <"/proc/$pid/cmdline" | grep -q 'demo\.sh' \
    && echo "$pid"
}

if [ "$STOP" = 1 ]; then
  if ! pid=$(running_demo); then
    echo "ripv demo --stop: no demo is running from $DEMO" >&2
    exit 0
  fi
  echo "ripv demo --stop: stopping the demo (process $pid) running from $DEMO" >&2
  kill -TERM "$pid"
  # tail --pid returns when the process ends: no polling here
  timeout 60 tail --pid="$pid" -f /dev/null || { echo "ripv demo --stop: process $pid still runs after 60 s" >&2; exit 1; }
  exit 0
fi

# One demo per folder: the pid file is made with O_EXCL (noclobber), so of two demos started at
# once only one gets it; a stale one (its process gone) is taken over. Nothing in $DEMO is touched
# before this.
mkdir -p "$DEMO"
take_pidfile() { (set -C; echo "$$" >"$PIDFILE") 2>/dev/null; }
if ! take_pidfile; then
  if pid=$(running_demo); then
    echo "ripv demo: $DEMO is in use by the demo running as process $pid (since $(ps -o lstart= -p "$pid" 2>/dev/null || echo '?'))." >&2
    echo "  Stop it with $STOP_HINT (or Ctrl-C where it runs), or give this one another folder: RIPV_DEMO_DIR=DIR ./ripv demo" >&2
    exit 1
  fi
  rm -f "$PIDFILE"
  take_pidfile || { echo "ripv demo: another demo took $DEMO just now; see $PIDFILE" >&2; exit 1; }
fi
own_pidfile() { [ "$(head -1 "$PIDFILE" 2>/dev/null)" = "$$" ] && rm -f "$PIDFILE"; }
trap own_pidfile EXIT

# Like every ./ripv command: build the jars when one is missing.
jar() { echo "$ROOT/$1/target/$1.jar"; }
for m in ripv-server ripv-services ripv-client; do
  if [ ! -f "$(jar "$m")" ]; then
    "$ROOT/ripv" build
    break
  fi
done
# where this script and the services reach what listens on $BIND
case "$BIND" in
  0.0.0.0|::|127.*|localhost) HERE=localhost ;;
  *) HERE="$BIND" ;;
esac
USER_NAME=demo
PASSWORD=ripv-demo-operator

mkdir -p "$DEMO/logs" "$DEMO/server"
pids=()
stop_all() {
  trap - INT TERM EXIT
  if [ ${#pids[@]} -gt 0 ]; then
    echo "demo: stopping..." >&2
    kill "${pids[@]}" 2>/dev/null || true
    wait "${pids[@]}" 2>/dev/null || true
  fi
  own_pidfile || true
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
for p in "$PORT" "$REGISTRY" "$HTTP" "$GLIDER" "$WEBHOOK"; do
  if ! port_free "$p"; then
    echo "demo: port $p is in use. Stop what uses it, or set RIPV_PORT / RIPV_REGISTRY_PORT / RIPV_HTTP_PORT / RIPV_GLIDER_PORT / RIPV_WEBHOOK_PORT." >&2
    exit 1
  fi
done

permit="$DEMO/server/permit.txt"
if ! grep -q "^user $USER_NAME " "$permit" 2>/dev/null; then
  echo "$PASSWORD" | "$JAVA" "${USER_HOME[@]}" -jar "$(jar ripv-server)" passwd --permit "$permit" "$USER_NAME" --roles operators >/dev/null
  echo "ripv-demo-observer" | "$JAVA" "${USER_HOME[@]}" -jar "$(jar ripv-server)" passwd --permit "$permit" observer --roles observers,db-reader >/dev/null
fi
printf '%s\n' "$PASSWORD" > "$DEMO/password"
chmod 600 "$DEMO/password"

# The server makes its TLS certificate on first start; the demo's clients remember it in a file of
# the demo's own (a fresh demo directory means a new certificate, so forget the old one then).
KNOWN="$DEMO/known_hosts"
[ -f "$DEMO/server/tls/server.p12" ] || rm -f "$KNOWN"
export RIPV_KNOWN_HOSTS="$KNOWN"

# Notifications can be tried on this machine: a webhook receiver on loopback, which the server may
# send to while the demo listens on this machine only (opened to the network, it may not: anyone
# who can log in could then make the server call this host's other local services).
echo "demo: starting the webhook receiver on 127.0.0.1:$WEBHOOK (what it gets goes to $DEMO/logs/webhooks.log)" >&2
"$JAVA" "${USER_HOME[@]}" -jar "$(jar ripv-server)" webhook-sink --port "$WEBHOOK" >"$DEMO/logs/webhooks.log" 2>&1 &
pids+=($!)
WEBHOOK_ALLOW=()
[ "$HERE" = localhost ] && [ "$BIND" != 0.0.0.0 ] && [ "$BIND" != "::" ] && WEBHOOK_ALLOW=(--webhook-allow 127.0.0.1/32)

echo "demo: starting the RIPVServer (logs in $DEMO/logs)" >&2
# -XX:+UseParallelGC: as ./ripv server launches it (ServerMain.JVM_OPTIONS, docs/performance.md).
"$JAVA" "${USER_HOME[@]}" -XX:+UseParallelGC -jar "$(jar ripv-server)" server --data "$DEMO/server" --port "$PORT" --registry-port "$REGISTRY" \
  --http-port "$HTTP" --outbound-port "$OUTBOUND" --bind "$BIND" ${WEBHOOK_ALLOW[@]+"${WEBHOOK_ALLOW[@]}"} \
  >"$DEMO/logs/server.log" 2>&1 &
pids+=($!)
wait_port "$PORT"
secret="$DEMO/server/service.secret"
for s in "$ROOT"/docs/samples/*.dat "$ROOT"/docs/samples/*.wf "$ROOT"/docs/samples/*.ma "$ROOT"/scripts/demo-data/*.wf; do
  [ -f "$s" ] && [ ! -f "$DEMO/server/upload/$(basename "$s")" ] && cp "$s" "$DEMO/server/upload/"
done

echo "demo: starting the SerialPortServer (glider $GLIDER_NAME calls in on port $GLIDER), DatabaseServer and DataVisServer" >&2
"$JAVA" "${USER_HOME[@]}" -Dripv.host=localhost -jar "$(jar ripv-services)" serial --server "$HERE:$REGISTRY" --secret-file "$secret" \
  --link "listen://$BIND:$GLIDER,name=$GLIDER_NAME$LINK_PROMPT" --carrier ignore --no-enumerate >"$DEMO/logs/serial.log" 2>&1 &
pids+=($!)
# not wait_port: a connection to the glider's port would be taken for a call
for i in $(seq 1 150); do
  grep -q "MailBoxes:" "$DEMO/logs/serial.log" 2>/dev/null && break
  sleep 0.2
done

"$JAVA" "${USER_HOME[@]}" -Dripv.host=localhost -jar "$(jar ripv-services)" database --server "$HERE:$REGISTRY" --secret-file "$secret" \
  --data "$DEMO/database" >"$DEMO/logs/database.log" 2>&1 &
pids+=($!)
"$JAVA" "${USER_HOME[@]}" -Dripv.host=localhost -jar "$(jar ripv-services)" datavis --server "$HERE:$REGISTRY" --secret-file "$secret" \
  --workdir "$DEMO/datavis" >"$DEMO/logs/datavis.log" 2>&1 &
pids+=($!)

# "Running" only once the three services have registered: a service that died (its log says why)
# stops the demo instead.
for i in $(seq 1 600); do
  missing=()
  for s in SerialPortServer DatabaseServer DataVisServer; do
    grep -q "<$s>::<localhost> (SID [0-9]*) registered" "$DEMO/logs/server.log" || missing+=("$s")
  done
  [ ${#missing[@]} -eq 0 ] && break
  for p in "${pids[@]}"; do
    if ! kill -0 "$p" 2>/dev/null; then
      echo "demo: a process of the demo ended before ${missing[*]} registered; see $DEMO/logs/ (serial.log, database.log, datavis.log):" >&2
      tail -n 5 "$DEMO"/logs/*.log >&2
      exit 1
    fi
  done
  [ "$i" = 600 ] && { echo "demo: ${missing[*]} did not register within 120 s; see $DEMO/logs/" >&2; exit 1; }
  sleep 0.2
done

# The glider's first call fetches its Slocum files (the server ingests them): queued once, before
# the glider first calls.
BOX="<SerialPortServer>::<localhost>$GLIDER_NAME"
if [ ! -f "$DEMO/server/.demo-fetch-queued" ]; then
  if "$JAVA" "${USER_HOME[@]}" -jar "$(jar ripv-client)" cli --server "localhost:$PORT" --user "$USER_NAME" \
       --password-file "$DEMO/password" --exec "?queue add $BOX fetch-slocum-data.wf" >"$DEMO/logs/queue.log" 2>&1; then
    touch "$DEMO/server/.demo-fetch-queued"
    echo "demo: queued fetch-slocum-data.wf for $GLIDER_NAME's first call (its Slocum files, ingested as they land)" >&2
  else
    echo "demo: could not queue fetch-slocum-data.wf (see $DEMO/logs/queue.log); the glider's files are there to fetch by hand" >&2
  fi
fi

# The glider carries its sample logs (made in an empty folder) and, from --files, real Slocum files with
# their sensor-list caches (scripts/demo-data/README.md): copying those into the folder first left it
# without the logs the sample workflows fetch.
echo "demo: the simulated glider $GLIDER_NAME calls in for $SURFACE s, dives for $DIVE s, and calls again" >&2
"$JAVA" "${USER_HOME[@]}" -jar "$(jar ripv-services)" simulator --call "$HERE:$GLIDER" --name "$GLIDER_NAME" \
  --dive-seconds "$DIVE" --surface-seconds "$SURFACE" --dir "$DEMO/glider" --dialog "$GLIDER_DIALOG" \
  --files "$ROOT/scripts/demo-data/glider" \
  ${GLIDER_LINE[@]+"${GLIDER_LINE[@]}"} >"$DEMO/logs/simulator.log" 2>&1 &
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
  Glider data: the first call runs the queued fetch-slocum-data.wf (?receipts $BOX); then
             --exec 'use <DatabaseServer>::<localhost>TTY1' --exec 'SELECT * FROM positions', vis:track rosie_713
  Notifications: --exec '?notify add webhook http://127.0.0.1:$WEBHOOK/ SURFACED,DIVED,WORKFLOW_DONE'
             the demo's webhook receiver writes what it gets to $DEMO/logs/webhooks.log
  Plot:      --exec 'use <DataVisServer>::<localhost>TTY1' --exec 'vis:glider-temperature.dat'
  Web console: https://localhost:$HTTP/ (log in as $USER_NAME, password in $DEMO/password; the server's own certificate: your browser asks first)
  Server certificate: $(grep -o 'SHA256:[0-9A-F:]*' "$DEMO/logs/server.log" | head -1)
  Logs: $DEMO/logs/

Press Ctrl-C to stop everything (or, from another terminal: $STOP_HINT).
HINT
}

if [ -n "${DISPLAY:-}" ] && [ "${RIPV_DEMO_HEADLESS:-}" != 1 ]; then
  echo "demo: opening the client as '$USER_NAME'" >&2
  "$JAVA" "${USER_HOME[@]}" -jar "$(jar ripv-client)" client "localhost:$PORT" --user "$USER_NAME" --password-file "$DEMO/password" \
    >"$DEMO/logs/client.log" 2>&1 &
  pids+=($!)
  cli_hint
  wait "${pids[-1]}" || true
else
  echo "demo: no display (DISPLAY is not set), so no GUI." >&2
  cli_hint
  wait
fi

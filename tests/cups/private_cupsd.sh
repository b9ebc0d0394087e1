#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A private cupsd for tests: its own ServerRoot, spool, logs and binaries under
# one folder, listening on loopback only. Nothing under /etc/cups is read or
# written (docs/cups.md, "Testing with a private cupsd").
#
#   private_cupsd.sh start DIR BACKEND FILTER PPD TYPES [ENV=VALUE...]
#       Writes the configuration into DIR, installs BACKEND as
#       DIR/bin/backend/tactus and FILTER as DIR/bin/filter/tactus-layout,
#       starts cupsd in the background and waits until it answers. Prints the
#       environment lines a client needs (CUPS_SERVER=..., one per line).
#       ENV=VALUE pairs become SetEnv lines: the backend's and filter's
#       environment (e.g. TACTUS_SPOOL_DB).
#   private_cupsd.sh stop DIR      Stops the cupsd started for DIR (SIGTERM, then SIGKILL).
#   private_cupsd.sh kill DIR      SIGKILLs it (its children, the backends, live on).
#   private_cupsd.sh restart DIR   Starts it again with the configuration already in DIR.
#
# As root, cupsd runs backends and filters as `lp` (cups-files.conf: User lp),
# exactly as the packaged CUPS does. As another user it runs them as that user.
set -euo pipefail

die() { echo "private_cupsd: $*" >&2; exit 1; }

free_port() {
    python3 - <<'PY'
import socket
s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()
PY
}

env_lines() {
    local dir=$1
    echo "CUPS_SERVER=127.0.0.1:$(cat "$dir/port")"
    echo "CUPS_SERVERROOT=$dir"
    echo "CUPS_DATADIR=$dir/share"
    echo "CUPS_STATEDIR=$dir"
}

wait_running() {
    local dir=$1
    local i
    for i in $(seq 1 200); do
        if env $(env_lines "$dir") lpstat -r 2>/dev/null | grep -q "is running"; then return 0; fi
        if ! kill -0 "$(cat "$dir/private-cupsd.pid")" 2>/dev/null; then
            cat "$dir/log/error_log" >&2 2>/dev/null || true
            die "cupsd exited while starting (see $dir/log/error_log)"
        fi
        sleep 0.05
    done
    die "cupsd did not answer within 10 s"
}

launch() {
    local dir=$1
    # -f: foreground (we keep its pid); -c/-s: our configuration only.
    cupsd -f -c "$dir/cupsd.conf" -s "$dir/cups-files.conf" >>"$dir/log/cupsd.out" 2>&1 &
    echo $! >"$dir/private-cupsd.pid"
    wait_running "$dir"
}

start() {
    local dir=$1 backend=$2 filter=$3 ppd=$4 types=$5
    shift 5
    command -v cupsd >/dev/null || die "cupsd not found (apt-get install cups-daemon cups-client cups-bsd)"
    mkdir -p "$dir"
    dir=$(cd "$dir" && pwd)
    local port
    port=$(free_port)
    echo "$port" >"$dir/port"
    mkdir -p "$dir/bin/backend" "$dir/bin/filter" "$dir/bin/daemon" "$dir/share/model" \
             "$dir/share/mime" "$dir/spool/temp" "$dir/cache" "$dir/log" "$dir/ppd" "$dir/ssl"
    ln -sf /usr/lib/cups/daemon/cups-exec "$dir/bin/daemon/cups-exec"
    # The system's MIME rules plus ours (a folder of links, so ours can sit beside them).
    local f
    for f in /usr/share/cups/mime/*; do ln -sf "$f" "$dir/share/mime/"; done
    cp "$types" "$dir/share/mime/tactus.types"
    # Mode 0755: cupsd runs the backend as the unprivileged User (0700 would mean root).
    install -m 0755 "$backend" "$dir/bin/backend/tactus"
    install -m 0755 "$filter" "$dir/bin/filter/tactus-layout"
    cp "$ppd" "$dir/share/model/"
    local setenv=""
    local kv
    for kv in "$@"; do setenv+="SetEnv ${kv%%=*} ${kv#*=}"$'\n'; done
    cat >"$dir/cupsd.conf" <<CONF
LogLevel debug
MaxLogSize 0
Listen 127.0.0.1:$port
Listen $dir/sock
Browsing Off
WebInterface No
DefaultAuthType None
JobRetryInterval 1
JobKillDelay 20
PreserveJobHistory Yes
# Write job files at once (the default waits up to 30 s): a job sent just
# before cupsd is killed is still there after the restart, as on a server
# that has been up a while.
DirtyCleanInterval 0
<Location />
  Order allow,deny
  Allow 127.0.0.1
  Allow @LOCAL
</Location>
<Policy default>
  JobPrivateAccess default
  JobPrivateValues default
  SubscriptionPrivateAccess default
  SubscriptionPrivateValues default
  <Limit All>
    Order deny,allow
    Allow 127.0.0.1
  </Limit>
</Policy>
CONF
    local user=lp group=lp
    if [ "$(id -u)" -ne 0 ]; then user=$(id -un); group=$(id -gn); fi
    cat >"$dir/cups-files.conf" <<CONF
User $user
Group $group
SystemGroup root $(id -gn)
ServerRoot $dir
StateDir $dir
CacheDir $dir/cache
ServerBin $dir/bin
DataDir $dir/share
RequestRoot $dir/spool
TempDir $dir/spool/temp
AccessLog $dir/log/access_log
ErrorLog $dir/log/error_log
PageLog $dir/log/page_log
FileDevice No
Printcap $dir/printcap
${setenv}
CONF
    if [ "$(id -u)" -eq 0 ]; then
        chown lp:lp "$dir/spool" "$dir/cache"
        chmod 0710 "$dir/spool"
    fi
    chmod 1777 "$dir/spool/temp"
    launch "$dir"
    env_lines "$dir"
}

# Backends of this cupsd left running (a test that failed half-way, or one
# orphaned by `kill`), found by their exact program path, never by name.
kill_backends() {
    local dir=$1 p exe
    for p in /proc/[0-9]*; do
        exe=$(readlink "$p/exe" 2>/dev/null) || continue
        case "$exe" in "$dir/bin/backend/"*|"$dir/bin/filter/"*) kill -KILL "${p#/proc/}" 2>/dev/null || true ;; esac
    done
}

stop() {
    local dir=$1 pid
    [ -f "$dir/private-cupsd.pid" ] || return 0
    pid=$(cat "$dir/private-cupsd.pid")
    if kill -TERM "$pid" 2>/dev/null; then
        local i
        for i in $(seq 1 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.05; done
        kill -KILL "$pid" 2>/dev/null || true
    fi
    kill_backends "$dir"
}

case "${1:-}" in
    start) shift; [ $# -ge 5 ] || die "usage: start DIR BACKEND FILTER PPD TYPES [ENV=VALUE...]"; start "$@" ;;
    stop) stop "$(cd "$2" && pwd)" ;;
    kill) kill -KILL "$(cat "$2/private-cupsd.pid")" ;;
    restart) launch "$(cd "$2" && pwd)"; env_lines "$(cd "$2" && pwd)" ;;
    env) env_lines "$(cd "$2" && pwd)" ;;
    *) die "usage: private_cupsd.sh start|stop|kill|restart|env DIR ..." ;;
esac

#!/usr/bin/env bash
# Private MariaDB instance for fleetmap: own data dir, unix socket, loopback port.
#
#   scripts/db.sh start     create (first time) and start; load sql/; write fleetmap.conf
#   scripts/db.sh stop      clean shutdown
#   scripts/db.sh status    running or not, where
#   scripts/db.sh sql ARGS  mariadb client as the instance administrator on the project database
#
# Settings (environment):
#   FLEETMAP_HOME   instance folder (default: <checkout>/.fleetmap)
#   FLEETMAP_PORT   loopback TCP port (default: 33306)
#   FLEETMAP_DB     database name (default: fleetmap)
#   FLEETMAP_MYSQLD_ARGS  extra mariadbd options (scripts/cluster.sh: the wsrep settings)
#   FLEETMAP_JOINER       1: a Galera node that receives its data from the cluster
#                         (scripts/cluster.sh): no mariadb-install-db, no sql/ loading
set -euo pipefail

ROOT="$(cd "$(dirname "$0")/.." && pwd)"
HOME_DIR="${FLEETMAP_HOME:-$ROOT/.fleetmap}"
PORT="${FLEETMAP_PORT:-33306}"
DB="${FLEETMAP_DB:-fleetmap}"
DATA="$HOME_DIR/data"
SOCK="$HOME_DIR/mysqld.sock"
PIDF="$HOME_DIR/mysqld.pid"
LOG="$HOME_DIR/mysqld.log"
CONF="$HOME_DIR/fleetmap.conf"
ME="$(id -un)"

die() { echo "db.sh: $*" >&2; exit 1; }

free_mib() { df -Pm "$HOME_DIR" | awk 'NR==2 {print $4}'; }

# A start that failed says why as far as it can: the log's last lines and the free disk
# (a full disk stops mariadb-install-db and InnoDB's redo log creation).
start_failed() {
  { echo "db.sh: last lines of $LOG:"; tail -n 15 "$LOG" 2>/dev/null | sed 's/^/  /'
    echo "db.sh: $(free_mib) MiB free on $(df -P "$HOME_DIR" | awk 'NR==2 {print $6}')"; } >&2 || true
  die "$@"
}

# The administrator logs in over the socket as the OS user (unix_socket auth, no password).
admin() { mariadb --no-defaults --socket="$SOCK" -u "$ME" "$@"; }

running() { [ -S "$SOCK" ] && mariadb-admin --no-defaults --socket="$SOCK" -u "$ME" ping >/dev/null 2>&1; }

# A Galera node (scripts/cluster.sh) answers pings before it serves: until it has synced
# with its group, statements fail with 1047 (a bootstrap's CREATE DATABASE did, once).
wsrep_wait_ready() {
  case " ${FLEETMAP_MYSQLD_ARGS:-} " in *" --wsrep-on=ON "*) ;; *) return 0 ;; esac
  local i
  for i in $(seq 1 480); do
    [ "$(admin -N -e "SHOW GLOBAL STATUS LIKE 'wsrep_ready'" 2>/dev/null | awk '{print $2}')" = ON ] && return 0
    sleep 0.25
  done
  start_failed "the Galera node did not become ready (wsrep_ready) within 120 s, see $LOG"
}

# One random password per account, generated once and kept in fleetmap.conf.
password_for() {
  local role="$1" pw=""
  [ -f "$CONF" ] && pw="$(awk -v s="[$role]" '$0==s{f=1;next} /^\[/{f=0} f&&$1=="password"{print $3}' "$CONF")"
  [ -n "$pw" ] || pw="$(head -c 18 /dev/urandom | base64 | tr -d '/+=')"
  echo "$pw"
}

write_conf() {
  local spw opw ipw wpw
  spw="$(password_for server)"; opw="$(password_for operator)"; ipw="$(password_for inspector)"; wpw="$(password_for web)"
  umask 077
  cat > "$CONF.tmp" <<CONF
# fleetmap connection settings for the private instance (written by scripts/db.sh).
# Every program reads this file; FLEETMAP_* variables and flags override it.
[database]
host = 127.0.0.1
port = $PORT
socket = $SOCK
name = $DB

[server]
user = fleetmap_server
password = $spw

[operator]
user = fleetmap_operator
password = $opw

[inspector]
user = fleetmap_inspector
password = $ipw

[web]
user = fleetmap_web
password = $wpw
CONF
  mv "$CONF.tmp" "$CONF"
}

load_sql() {
  admin -e "CREATE DATABASE IF NOT EXISTS \`$DB\` CHARACTER SET utf8mb4 COLLATE utf8mb4_unicode_ci" \
    || start_failed "creating the database $DB failed"
  for f in "$ROOT"/sql/[0-9]*.sql; do
    admin "$DB" < "$f" || start_failed "loading $f failed"
  done
  write_conf
  local role
  for role in server operator inspector web; do
    local pw; pw="$(password_for "$role")"
    admin "$DB" <<SQL || start_failed "creating the account fleetmap_$role failed"
CREATE USER IF NOT EXISTS 'fleetmap_$role'@'%';
ALTER USER 'fleetmap_$role'@'%' IDENTIFIED BY '$pw';
GRANT fleetmap_${role}_role TO 'fleetmap_$role'@'%';
SET DEFAULT ROLE fleetmap_${role}_role FOR 'fleetmap_$role'@'%';
SQL
  done
}

start() {
  mkdir -p "$HOME_DIR"
  # sun_path holds 107 bytes and a NUL; a longer path fails deep in mariadbd's log.
  [ "${#SOCK}" -le 107 ] || die "socket path $SOCK is ${#SOCK} bytes, unix sockets allow 107: set FLEETMAP_HOME to a shorter folder"
  if running; then
    [ "${FLEETMAP_JOINER:-0}" = 1 ] || load_sql
    echo "db.sh: already running (socket $SOCK, port $PORT)"
    return
  fi
  if [ "${FLEETMAP_JOINER:-0}" = 1 ]; then
    mkdir -p "$DATA"
    # rsync's state transfer daemon, started by root, writes as nobody, and must be able
    # to replace what mariadbd (root) wrote before a crash.
    [ "$(id -u)" = 0 ] && chown -R nobody:nogroup "$DATA"
  elif [ ! -d "$DATA/mysql" ]; then
    echo "db.sh: creating data directory $DATA"
    # The system tables, the schema and the redo log (256 MiB unless FLEETMAP_MYSQLD_ARGS
    # says less) need about 400 MiB.
    local free; free="$(free_mib)"
    [ "$free" -ge 400 ] || die "only $free MiB free for $DATA, a new instance needs about 400 MiB"
    rm -rf "$DATA"
    # --skip-test-db: no anonymous accounts (SPEC 9).
    # A private tmpdir: instances started at once (the test fixtures) shared /tmp, and one
    # bootstrap failed on a temporary table another removed ("Unknown table
    # mysql.tmp_user_sys").
    mkdir -p "$HOME_DIR/tmp"
    mariadb-install-db --no-defaults --datadir="$DATA" --user="$ME" --tmpdir="$HOME_DIR/tmp" \
      --auth-root-authentication-method=socket --skip-test-db >"$HOME_DIR/install.log" 2>&1 \
      || { LOG="$HOME_DIR/install.log" start_failed "mariadb-install-db failed, see $HOME_DIR/install.log"; }
  fi
  local mariadbd; mariadbd="$(command -v mariadbd || echo /usr/sbin/mariadbd)"
  # --max-connections: every robot holds its own connection (SPEC 4), so the default 151
  # refuses the 152nd robot; 1100 leaves room for a fleet of 1000 plus servers, operators
  # and tools.
  mkdir -p "$HOME_DIR/tmp"
  "$mariadbd" --no-defaults --user="$ME" --datadir="$DATA" --socket="$SOCK" --tmpdir="$HOME_DIR/tmp" \
    --port="$PORT" --bind-address=127.0.0.1 --skip-name-resolve \
    --pid-file="$PIDF" --log-error="$LOG" \
    --character-set-server=utf8mb4 --collation-server=utf8mb4_unicode_ci \
    --max-connections=1100 \
    --max-allowed-packet=64M --innodb-buffer-pool-size=512M --innodb-log-file-size=256M \
    ${FLEETMAP_MYSQLD_ARGS:-} >/dev/null 2>&1 &
  local pid=$! i
  # Two minutes: a fresh, loaded machine creates the redo log and the system tables slowly.
  for i in $(seq 1 480); do
    running && break
    kill -0 "$pid" 2>/dev/null || start_failed "server exited at start (port $PORT taken? set FLEETMAP_PORT), see $LOG"
    sleep 0.25
  done
  running || start_failed "server did not answer within 120 s, see $LOG"
  [ "${FLEETMAP_JOINER:-0}" = 1 ] || { wsrep_wait_ready; load_sql; }
  echo "db.sh: running (socket $SOCK, port $PORT, database $DB, config $CONF)"
}

stop() {
  if ! running; then echo "db.sh: not running"; return; fi
  local pid=""; [ -f "$PIDF" ] && pid="$(cat "$PIDF")"
  mariadb-admin --no-defaults --socket="$SOCK" -u "$ME" shutdown
  if [ -n "$pid" ]; then
    local i; for i in $(seq 1 120); do kill -0 "$pid" 2>/dev/null || break; sleep 0.25; done
  fi
  echo "db.sh: stopped"
}

status() {
  if running; then
    echo "running: socket $SOCK, port $PORT, database $DB, data $DATA, config $CONF"
  else
    echo "not running (data $DATA)"; return 3
  fi
}

case "${1:-}" in
  start) start ;;
  stop) stop ;;
  status) status ;;
  sql) shift; running || die "not running; use: $0 start"; admin "$DB" "$@" ;;
  conf) echo "$CONF" ;;
  -h|--help|help|"") sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//' ;;
  *) die "unknown command '$1' (start|stop|status|sql|conf)" ;;
esac

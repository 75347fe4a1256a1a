#!/usr/bin/env bash
# A three-node MariaDB Galera cluster on this machine, for tests and demos: each node is a
# private instance of scripts/db.sh (own data directory, socket and loopback port) with
# wsrep on loopback. For a real three-machine deployment see docs/galera.md.
#
#   scripts/cluster.sh start [N]    start every node (the first one bootstraps the cluster
#                                   when none runs), or only node N (it rejoins: IST or SST)
#   scripts/cluster.sh stop [N]     clean shutdown of every node, or of node N
#   scripts/cluster.sh status       per node: running, cluster size, state, ready
#   scripts/cluster.sh kill N       kill -9 node N (a crash; start N brings it back)
#   scripts/cluster.sh sql N ARGS   mariadb client as the administrator on node N
#   scripts/cluster.sh conf [N]     the fleetmap.conf of node N (default 1)
#
# Settings (environment):
#   FLEETMAP_CLUSTER_HOME  folder of the nodes (default: <checkout>/.fleetmap-cluster)
#   FLEETMAP_CLUSTER_PORT  SQL port of node 1 (default 33406); node N uses PORT+N-1,
#                          Galera replication PORT+100+N-1, IST PORT+200+N-1, SST PORT+300+N-1
#   FLEETMAP_DB            database name (default: fleetmap)
#   FLEETMAP_CLUSTER_MYSQLD_ARGS  more mariadbd options for every node (the tests: smaller
#                          buffers, so that three nodes start fast)
#
# Every node's fleetmap.conf holds the same accounts and passwords (the bootstrap node
# creates them, the cluster replicates them), with the node's own port and socket.
set -euo pipefail

ROOT="$(cd "$(dirname "$0")/.." && pwd)"
CHOME="${FLEETMAP_CLUSTER_HOME:-$ROOT/.fleetmap-cluster}"
BASE="${FLEETMAP_CLUSTER_PORT:-33406}"
NODES=3
ME="$(id -un)"
PROVIDER="${FLEETMAP_GALERA_PROVIDER:-/usr/lib/galera/libgalera_smm.so}"

die() { echo "cluster.sh: $*" >&2; exit 1; }
node_home() { echo "$CHOME/node$1"; }
sql_port() { echo $((BASE + $1 - 1)); }
repl_port() { echo $((BASE + 100 + $1 - 1)); }
check_node() { [[ "$1" =~ ^[1-9][0-9]*$ ]] && [ "$1" -le "$NODES" ] || die "no node '$1' (1..$NODES)"; }

db() {  # db N ARGS...: scripts/db.sh on node N
  local n="$1"; shift
  FLEETMAP_HOME="$(node_home "$n")" FLEETMAP_PORT="$(sql_port "$n")" bash "$ROOT/scripts/db.sh" "$@"
}
running() { db "$1" status >/dev/null 2>&1; }
any_running() { local n; for n in $(seq 1 $NODES); do running "$n" && return 0; done; return 1; }

wsrep_args() {  # wsrep_args N BOOTSTRAP
  local n="$1" boot="$2" peers="" m
  for m in $(seq 1 $NODES); do peers+="${peers:+,}127.0.0.1:$(repl_port "$m")"; done
  local a=(
    --wsrep-on=ON --wsrep-provider="$PROVIDER" --wsrep-cluster-name=fleetmap
    --wsrep-node-name="node$n" --wsrep-node-address="127.0.0.1:$(repl_port "$n")"
    --wsrep-cluster-address="gcomm://$peers"
    "--wsrep-provider-options=gmcast.listen_addr=tcp://127.0.0.1:$(repl_port "$n");ist.recv_addr=127.0.0.1:$((BASE + 200 + n - 1));gcache.size=128M"
    --wsrep-sst-method=rsync --wsrep-sst-receive-address="127.0.0.1:$((BASE + 300 + n - 1))"
    # Galera replicates rows: row binlog format, interleaved auto-increment locks.
    --binlog-format=ROW --innodb-autoinc-lock-mode=2 --default-storage-engine=InnoDB
    # No session waits on a row lock for InnoDB's default 50 s: behind a waiting session a
    # replicated write can hold up every node (docs/galera.md, "A robot's lock wait").
    --innodb-lock-wait-timeout=5
  )
  [ "$boot" = 1 ] && a+=(--wsrep-new-cluster)
  printf '%s ' "${a[@]}" ${FLEETMAP_CLUSTER_MYSQLD_ARGS:-}
}

# A clean bootstrap after every node stopped: Galera refuses to bootstrap from a node
# whose grastate.dat says safe_to_bootstrap: 0 (it may have missed writes). On this
# test cluster the node that stopped last is node 1's peer set's best guess; we take
# the node with the highest committed seqno, as Galera's docs advise.
bootstrap_node() {
  local best=1 bestseq=-2 n seq
  for n in $(seq 1 $NODES); do
    local g; g="$(node_home "$n")/data/grastate.dat"
    [ -f "$g" ] || continue
    seq="$(awk '$1=="seqno:"{print $2}' "$g")"
    [ -n "$seq" ] || continue
    if [ "$seq" -gt "$bestseq" ]; then best="$n"; bestseq="$seq"; fi
  done
  echo "$best"
}

conf_of() { echo "$(node_home "$1")/fleetmap.conf"; }

# Node N's fleetmap.conf: the bootstrap node's accounts, N's own port and socket.
write_node_conf() {
  local n="$1" src="$2"
  mkdir -p "$(node_home "$n")"
  umask 077
  awk -v port="$(sql_port "$n")" -v sock="$(node_home "$n")/mysqld.sock" '
    $1=="port" && !done_p {print "port = " port; done_p=1; next}
    $1=="socket" && !done_s {print "socket = " sock; done_s=1; next}
    {print}' "$src" > "$(conf_of "$n").tmp"
  mv "$(conf_of "$n").tmp" "$(conf_of "$n")"
}

# After a crash (kill -9) grastate.dat says seqno -1: the node does not know where it
# stopped and asks for a full state transfer (rsync: the whole data directory, tens of
# seconds, the donor blocked meanwhile). Its position is in InnoDB: mariadbd
# --wsrep-recover prints it, and with it in grastate.dat the node asks for the missing
# transactions only (IST, from a donor's gcache), as Galera's own start scripts do.
recover_position() {
  local n="$1" g; g="$(node_home "$n")/data/grastate.dat"
  [ -f "$g" ] && [ "$(awk '$1=="seqno:"{print $2}' "$g")" = -1 ] || return 0
  local log; log="$(node_home "$n")/recover.log"
  local mariadbd; mariadbd="$(command -v mariadbd || echo /usr/sbin/mariadbd)"
  # shellcheck disable=SC2046  # wsrep_args: the node's options, one word each
  "$mariadbd" --no-defaults --user="$ME" --datadir="$(node_home "$n")/data" --log-error="$log" \
    $(wsrep_args "$n" 0) --wsrep-recover >/dev/null 2>&1 || true
  local pos; pos="$( { grep -o 'Recovered position: [^ ]*' "$log" 2>/dev/null || true; } | tail -n 1 | awk '{print $3}')"
  rm -f "$log"
  case "$pos" in
    *:[0-9]*) sed -i "s/^seqno:.*/seqno:   ${pos##*:}/" "$g"
              [ "$(id -u)" = 0 ] && chown -R nobody:nogroup "$(node_home "$n")/data"
              echo "cluster.sh: node $n recovered its position ${pos##*:} after a crash" ;;
  esac
}

start_node() {  # start_node N BOOTSTRAP
  local n="$1" boot="$2"
  if running "$n"; then echo "cluster.sh: node $n already running (port $(sql_port "$n"))"; return; fi
  local g; g="$(node_home "$n")/data/grastate.dat"
  [ "$boot" = 1 ] && [ -f "$g" ] && sed -i 's/^safe_to_bootstrap: 0/safe_to_bootstrap: 1/' "$g"
  local load=0
  # The bootstrap node loads the schema and creates the accounts once; joiners get them
  # by state transfer. A node's conf must exist before, so that it keeps the passwords.
  [ "$boot" = 1 ] && load=1
  if [ "$boot" != 1 ]; then
    local src=""; local m
    for m in $(seq 1 $NODES); do [ -f "$(conf_of "$m")" ] && [ "$m" != "$n" ] && { src="$(conf_of "$m")"; break; }; done
    [ -n "$src" ] && [ ! -f "$(conf_of "$n")" ] && write_node_conf "$n" "$src"
  fi
  [ "$boot" = 1 ] || recover_position "$n"
  echo "cluster.sh: starting node $n (port $(sql_port "$n"))$([ "$boot" = 1 ] && echo ', bootstrapping the cluster')"
  local joiner=1; [ "$load" = 1 ] && joiner=0
  FLEETMAP_MYSQLD_ARGS="$(wsrep_args "$n" "$boot")" FLEETMAP_JOINER="$joiner" db "$n" start >/dev/null
  if [ "$load" = 1 ]; then
    local m; for m in $(seq 1 $NODES); do [ "$m" != "$n" ] && write_node_conf "$m" "$(conf_of "$n")"; done
    write_node_conf "$n" "$(conf_of "$n")"
  fi
  wait_synced "$n"
}

wsrep_status() {  # wsrep_status N VAR
  db "$1" sql -N -e "SHOW GLOBAL STATUS LIKE '$2'" 2>/dev/null | awk '{print $2}'
}

# A joiner applies what the others commit meanwhile before it is Synced: under heavy
# writes on a loaded machine that takes minutes (FLEETMAP_CLUSTER_SYNC_S, default 180).
wait_synced() {
  local n="$1" i limit="${FLEETMAP_CLUSTER_SYNC_S:-180}"
  for i in $(seq 1 $((limit * 4))); do
    [ "$(wsrep_status "$n" wsrep_local_state_comment)" = Synced ] && return 0
    sleep 0.25
  done
  die "node $n did not reach Synced within $limit s, see $(node_home "$n")/mysqld.log"
}

start_all() {
  mkdir -p "$CHOME"
  if any_running; then
    local n; for n in $(seq 1 $NODES); do start_node "$n" 0; done
  else
    local b; b="$(bootstrap_node)"
    start_node "$b" 1
    local n; for n in $(seq 1 $NODES); do [ "$n" != "$b" ] && start_node "$n" 0; done
  fi
  status
}

stop_node() { running "$1" && db "$1" stop >/dev/null; echo "cluster.sh: node $1 stopped"; }

kill_node() {
  local n="$1" pidf; pidf="$(node_home "$n")/mysqld.pid"
  [ -f "$pidf" ] && running "$n" || die "node $n is not running"
  kill -9 "$(cat "$pidf")"
  local i; for i in $(seq 1 40); do running "$n" || break; sleep 0.25; done
  echo "cluster.sh: node $n killed"
}

status() {
  local n rc=0
  for n in $(seq 1 $NODES); do
    if running "$n"; then
      echo "node $n: running, port $(sql_port "$n"), cluster size $(wsrep_status "$n" wsrep_cluster_size)," \
           "$(wsrep_status "$n" wsrep_local_state_comment), ready $(wsrep_status "$n" wsrep_ready)"
    else
      echo "node $n: not running"; rc=3
    fi
  done
  return $rc
}

case "${1:-}" in
  start) if [ -n "${2:-}" ]; then check_node "$2"; if any_running; then start_node "$2" 0; else start_node "$2" 1; fi
         else start_all; fi ;;
  stop) if [ -n "${2:-}" ]; then check_node "$2"; stop_node "$2"
        else for n in $(seq $NODES -1 1); do stop_node "$n"; done; fi ;;
  status) status ;;
  kill) [ -n "${2:-}" ] || die "kill needs a node number"; check_node "$2"; kill_node "$2" ;;
  sql) [ -n "${2:-}" ] || die "sql needs a node number"; check_node "$2"; n="$2"; shift 2; db "$n" sql "$@" ;;
  conf) n="${2:-1}"; check_node "$n"; conf_of "$n" ;;
  -h|--help|help|"") sed -n '2,23p' "$0" | sed 's/^# \{0,1\}//' ;;
  *) die "unknown command '$1' (start|stop|status|kill|sql|conf)" ;;
esac

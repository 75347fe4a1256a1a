# Sourced by the benchmark drivers: robot accounts PREFIX0001..PREFIXNNNN made once with
# `fleetmap robot add`, each with its password in DIR/NAME.pw, and reused by later runs
# (an account whose password file is gone is made again with a new password).
#   ensure_robot_accounts FLEETMAP PREFIX COUNT MAP DIR WHO
ensure_robot_accounts() {
  local fm="$1" prefix="$2" count="$3" map="$4" dir="$5" who="$6" i name
  mkdir -p "$dir"; chmod 700 "$dir"
  local -A exists=()
  for name in $("$fm" robot list | awk 'NR > 1 { print $2 }'); do exists[$name]=1; done
  local missing=()
  for i in $(seq 1 "$count"); do
    printf -v name '%s%04d' "$prefix" "$i"
    if [ -n "${exists[$name]:-}" ]; then
      [ -s "$dir/$name.pw" ] && continue
      "$fm" robot remove "$name" >/dev/null
    fi
    (umask 077; head -c 18 /dev/urandom | base64 | tr -d '/+=' > "$dir/$name.pw")
    missing+=("$name")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "$who: creating ${#missing[@]} robot accounts with fleetmap robot add (once; reused later) ..."
    printf '%s\n' "${missing[@]}" | xargs -P 4 -I{} "$fm" robot add {} --map "$map" \
      --password-file "$dir/{}.pw" >/dev/null
  fi
  ROBOT_ACCOUNTS_ADDED=${#missing[@]}
}

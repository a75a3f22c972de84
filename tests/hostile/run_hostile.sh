#!/usr/bin/env bash
# Runs the hostile-input corpus: each row of the tables (tests/hostile/*.tsv)
# is one case, run in its own fresh directory under WORKDIR with a time and a
# memory limit, then checked. Prints one line per failing (FAIL) or skipped
# (SKIP) case with the reason, and at the end exactly one line
#   hostile: N passed, N failed, N skipped
# Exit status: 0 when no case failed, 1 otherwise, 2 on bad usage.
#
#   tests/hostile/run_hostile.sh SWEETSPOT WORKDIR [TABLE.tsv ...] [--only GLOB] [--verbose]
#
# SWEETSPOT is the sweetspot executable, WORKDIR a scratch folder (emptied
# first). Without tables, every tests/hostile/*.tsv is run. --only runs the
# cases whose id matches the shell pattern GLOB; --verbose also prints passes
# and keeps each failing case's folder (stdout, stderr, files) for a look.
#
# The table format, the setup and check directives and the rules applied to
# every case are described in tests/hostile/README.md.
set -uo pipefail

# Found once and handed to every case's process (each case is a new bash).
if [ -z "${HOSTILE_SELF:-}" ]; then
  HOSTILE_SELF=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/$(basename "${BASH_SOURCE[0]}")
  HOSTILE_ROOT=$(cd "${HOSTILE_SELF%/*}/../.." && pwd)
  export HOSTILE_SELF HOSTILE_ROOT
fi
self=$HOSTILE_SELF
here=${self%/*}
root=$HOSTILE_ROOT

# ---------------------------------------------------------------------------
# One case, in a child process (inside a private mount namespace when the
# case needs one). Prints "PASS id", "FAIL id: reasons" or "SKIP id: reason".
# ---------------------------------------------------------------------------
run_one() {
  local work=$1 id=$2 setup=$3 command=$4 expect=$5 fragment=$6 checks=$7
  local case_dir run
  case_dir=$work/cases/${id//\//_}
  run=$case_dir/run
  # WORKDIR is emptied before the first case, so a case's folder is new
  # unless two ids map to one name.
  if [ -e "$case_dir" ]; then rm -rf "$case_dir"; fi
  mkdir -p "$run" || { echo "FAIL $id: cannot make $case_dir"; return; }
  cd "$run" || return
  source "$work/lib.sh"
  local limit=20 mem_mb=3072 skip="" nan_ok=""

  # --- setup --------------------------------------------------------------
  local directive verb name rest
  local -a directives=()
  split_directives "$setup" directives
  for directive in "${directives[@]}"; do
    verb=${directive%% *}
    rest=${directive#"$verb"}; rest=${rest# }
    case "$verb" in
      write|add|writeb|repeat)
        name=${rest%% *}; rest=${rest#"$name"}; rest=${rest# }
        eval "name=$name"  # a quoted name: $'a\nb.json'
        case "$verb" in
          write) printf '%s\n' "$rest" >"$name" ;;
          add) printf '%s' "$rest" >>"$name" ;;
          writeb) printf '%b' "$rest" >>"$name" ;;
          repeat)
            local count=${rest%% *} unit
            unit=$(printf '%b_' "${rest#* }")
            UNIT=${unit%_} awk -v n="$count" 'BEGIN { u = ENVIRON["UNIT"]; for (i = 0; i < n; ++i) printf "%s", u }' >>"$name" ;;
        esac ;;
      *)
        local -a a=()
        eval "a=($rest)" || { echo "FAIL $id: harness: bad setup directive: $directive"; return; }
        case "$verb" in
          copy) cp -r -- "$root/${a[1]}" "${a[0]}" || skip="cannot copy ${a[1]}" ;;
          bytes) head -c "${a[1]}" /dev/zero | tr '\0' "${a[2]}" >>"${a[0]}" ;;
          fifo) mkfifo -- "${a[0]}" ;;
          mkdir) mkdir -p -- "${a[0]}" ;;
          ln) ln -s -- "${a[1]}" "${a[0]}" ;;
          touch) : >"${a[0]}" ;;
          chmod) chmod "${a[0]}" -- "${a[1]}" ;;
          timeout) limit=${a[0]} ;;
          mem) mem_mb=${a[0]} ;;
          sections) make_sections "${a[@]}" ;;
          nan-ok) nan_ok=1 ;;
          needroot) ((EUID == 0)) || skip="needs root" ;;
          mknod)
            if ((EUID != 0)); then skip="creating a device node needs root"
            elif ! mknod -- "${a[0]}" c "${a[1]}" "${a[2]}" 2>/dev/null; then skip="mknod failed"
            fi ;;
          fakedev) fake_dev || skip="cannot mount a private /dev (needs root and unshare -m)" ;;
          tinyfs) tiny_fs "${a[0]}" "${a[1]}" || skip="cannot mount a small tmpfs (needs root and unshare -m)" ;;
          fill) fill_fs "${a[0]}" ;;
          *) echo "FAIL $id: harness: unknown setup directive '$verb'"; return ;;
        esac ;;
    esac
    [ -n "$skip" ] && break
  done
  if [ -n "$skip" ]; then echo "SKIP $id: $skip"; return; fi

  # What is there before the command: every regular file's size, time and
  # inode (what a write changes), and where a check asks for a file to be
  # left unchanged, every file's checksum.
  stamps >"$case_dir/before.stamps"
  [[ "$checks" == *unchanged* ]] && snapshot >"$case_dir/before.sums"

  # --- the command ----------------------------------------------------------
  local started ended status
  started=${EPOCHREALTIME/./}
  (
    ulimit -v $((mem_mb * 1024)) 2>/dev/null
    export HOSTILE_CASE_DIR=$case_dir
    exec timeout -k 5 "$limit" bash -c 'source "$1"; eval "$2"' _ "$work/lib.sh" "$command"
  ) >"$case_dir/stdout" 2>"$case_dir/stderr" </dev/null
  status=$?
  ended=${EPOCHREALTIME/./}
  local elapsed_ms=$(((ended - started) / 1000))

  # --- the checks -----------------------------------------------------------
  local -a why=()
  # stderr as read, its first 240 bytes with line breaks as '|' for messages.
  local stderr_all="" stderr_text
  LC_ALL=C IFS= read -r -d '' stderr_all <"$case_dir/stderr"
  stderr_text=${stderr_all:0:240}
  stderr_text=${stderr_text//$'\n'/|}
  local allowed="|$expect|" fatal=""
  if ((status == 124)) && [[ "$allowed" != *"|124|"* ]]; then
    why+=("timed out after ${limit} s (expected exit $expect)")
    fatal=1
  elif [[ "$allowed" != *"|$status|"* ]]; then
    local what="exit $status"
    ((status > 128 && status < 160)) && what="exit $status (signal $((status - 128)))" && fatal=1
    why+=("$what, expected $expect${stderr_text:+ [stderr: $stderr_text]}")
  fi
  local raw='terminate called|what\(\): |\[json\.exception|AddressSanitizer|runtime error:|Segmentation fault|std::bad_alloc'
  if ((status <= 128 || status >= 160)) && [[ "$stderr_all" =~ $raw ]]; then
    why+=("raw failure on stderr [$stderr_text]")
  fi
  # A refusal or a failure: one line on stderr naming what is wrong.
  if ((status >= 1 && status < 124)) && [[ "$allowed" == *"|$status|"* ]]; then
    # Its lines as grep -c, tail -n 1 and wc -l count them (by those tools
    # past 64 KiB, where a loop in the shell would crawl).
    local lines=0 count=0 message="" line rest=$stderr_all
    if ((${#stderr_all} > 65536)); then
      lines=$(grep -c '^sweetspot: ' "$case_dir/stderr")
      message=$(tail -n 1 "$case_dir/stderr")
      count=$(wc -l <"$case_dir/stderr")
      rest=""
    fi
    while [ -n "$rest" ]; do
      if [[ "$rest" == *$'\n'* ]]; then
        line=${rest%%$'\n'*}
        rest=${rest#*$'\n'}
        count=$((count + 1))
      else
        line=$rest
        rest=""
      fi
      [[ "$line" == "sweetspot: "* ]] && lines=$((lines + 1))
      message=$line
    done
    if [ "$lines" != 1 ] || [[ "$message" != "sweetspot: "* ]]; then
      why+=("stderr must end in exactly one line 'sweetspot: ...' [stderr: $stderr_text]")
    elif ((status == 2)) && [ "$count" != 1 ]; then
      why+=("stderr must be exactly one line for bad input [stderr: $stderr_text]")
    fi
    if [ "$fragment" != - ] && [[ "$message" != *"$fragment"* ]]; then
      why+=("message lacks '$fragment' [stderr: $stderr_text]")
    fi
  fi
  # A crash or a hang says it all: the checks below would only repeat it.
  if [ -n "$fatal" ]; then
    [ -n "${HOSTILE_KEEP:-}" ] || { cd / && rm -rf "$case_dir"; }
    printf 'FAIL %s: %s\n' "$id" "${why[0]//$'\n'/\\n}" | sed -E 's/(.)\1{15,}/\1\1\1.../g'
    return
  fi
  # No NaN or infinity in what the command wrote: stdout and new or changed files.
  local nan='(^|[^A-Za-z0-9_])[-+]?(nan|inf|infinity)([^A-Za-z0-9_]|$)'
  [ -n "$nan_ok" ] && nan='(^|[,:|[( \t])[-+]?(nan|inf|infinity)([],|) \t]|$)'
  if grep -qaiE "$nan" "$case_dir/stdout"; then
    why+=("stdout holds nan/inf: $(grep -m1 -aioE ".{0,30}$nan" "$case_dir/stdout" | head -c 80)")
  fi
  # Every file written by the command: a new size, time or inode.
  local -A before=()
  local stamp changed
  while IFS= read -r stamp; do before[$stamp]=1; done <"$case_dir/before.stamps"
  while IFS= read -r stamp; do
    [ -n "${before[$stamp]:-}" ] && continue
    changed=${stamp#*$'\t'}
    case "$changed" in *.png) continue ;; esac
    if grep -qaiE "$nan" -- "$changed" 2>/dev/null; then why+=("$changed holds nan/inf"); fi
  done < <(stamps)

  local -a list=()
  split_directives "$checks" list
  for directive in "${list[@]}"; do
    local -a c=()
    eval "c=($directive)" 2>/dev/null || { why+=("harness: bad check: $directive"); continue; }
    check_one "$case_dir" "$elapsed_ms" "${c[@]}"
  done

  [ -n "${HOSTILE_KEEP:-}" ] || { cd / && rm -rf "$case_dir"; }
  if ((${#why[@]} == 0)); then
    echo "PASS $id"
  else
    local joined
    joined=$(printf '%s; ' "${why[@]}")
    joined=${joined//$'\n'/\\n}
    # Long runs of one character (a 250-byte file name) are shortened.
    printf 'FAIL %s: %s\n' "$id" "${joined%; }" | sed -E 's/(.)\1{15,}/\1\1\1.../g' 
  fi
}

split_directives() {  # TEXT ARRAY-NAME: "a ;; b ;; c" -> (a b c); "-" -> ()
  local text=$1
  local -n out=$2
  out=()
  [ "$text" = - ] && return
  while [[ "$text" == *' ;; '* ]]; do
    out+=("${text%% ;; *}")
    text=${text#* ;; }
  done
  out+=("$text")
}

# Path of a check's subject: stdout and stderr are the command's own.
subject() {
  case "$2" in
    stdout|stderr) echo "$1/$2" ;;
    *) echo "$2" ;;
  esac
}

# Regular files (no devices, FIFOs or directories followed) with their size,
# modification time and inode, one "size time inode<TAB>name" line each, in
# find's order (they are compared as a set).
stamps() {
  find . -mindepth 1 -type f -printf '%s %T@ %i\t%P\n' 2>/dev/null
}

# Regular files (no devices, FIFOs or directories followed) with their checksums.
snapshot() {
  find . -mindepth 1 -type f -printf '%P\n' 2>/dev/null | LC_ALL=C sort | while IFS= read -r f; do
    printf '%s\t%s\n' "$(cksum <"$f" | cut -d' ' -f1,2)" "$f"
  done | LC_ALL=C sort
}

json_number() {  # FILE KEY: the first "KEY": number in a JSON file
  grep -aoE "\"$2\" *: *[-+0-9.eE]+" "$1" | head -n 1 | sed 's/.*: *//'
}

check_one() {
  local case_dir=$1 elapsed_ms=$2 what=$3
  shift 3
  local p
  [ $# -ge 1 ] && p=$(subject "$case_dir" "$1")
  case "$what" in
    exists) [ -e "$p" ] || [ -L "$p" ] || why+=("$1 does not exist") ;;
    absent) { [ -e "$p" ] || [ -L "$p" ]; } && why+=("$1 exists, it should not") ;;
    regular) { [ -f "$p" ] && [ ! -L "$p" ]; } || why+=("$1 is not a regular file") ;;
    chardev) [ -c "$p" ] || why+=("$1 is no longer a character device ($(stat -c %F -- "$p" 2>&1))") ;;
    fifo) [ -p "$p" ] || why+=("$1 is no longer a FIFO ($(stat -c %F -- "$p" 2>&1))") ;;
    symlink) [ -L "$p" ] || why+=("$1 is no longer a symbolic link ($(stat -c %F -- "$p" 2>&1))") ;;
    isdir) [ -d "$p" ] || why+=("$1 is not a directory") ;;
    nonempty) [ -s "$p" ] || why+=("$1 is empty or missing") ;;
    empty) { [ -e "$p" ] && [ ! -s "$p" ]; } || why+=("$1 is not empty") ;;
    mode)
      local m
      m=$(stat -c %a -- "$p" 2>/dev/null)
      [ "$m" = "$2" ] || why+=("$1 has mode ${m:-?}, expected $2") ;;
    unchanged)
      local now
      now=$(printf '%s\t%s\n' "$(cksum <"$p" 2>/dev/null | cut -d' ' -f1,2)" "$1")
      grep -qxF -- "$now" "$case_dir/before.sums" || why+=("$1 was changed") ;;
    only)
      local want have
      want=$(printf '%s\n' "$@" | LC_ALL=C sort)
      have=$(find . -mindepth 1 -maxdepth 1 -printf '%P\n' | LC_ALL=C sort)
      if [ "$want" != "$have" ]; then
        why+=("the folder holds [$(printf '%q ' $have | head -c 200)] expected [$*]")
      fi ;;
    only-in)
      local dir=$1 want have
      shift
      want=$(printf '%s\n' "$@" | LC_ALL=C sort)
      have=$(find "$dir" -mindepth 1 -maxdepth 1 -printf '%P\n' | LC_ALL=C sort)
      [ "$want" = "$have" ] || why+=("$dir holds [$(echo $have | head -c 200)] expected [$*]") ;;
    # The text is every word after the file (quoted or not), joined by one
    # space: an unquoted phrase is the whole phrase, not its first word.
    'has~') local t="${*:2}"; grep -qaF -- "$t" "$p" || why+=("$1 lacks '$t'") ;;
    'has~i') local t="${*:2}"; grep -qaiF -- "$t" "$p" || why+=("$1 lacks '$t' (in any case)") ;;
    'has!~') local t="${*:2}"; grep -qaF -- "$t" "$p" && why+=("$1 holds '$t': $(grep -m1 -aF -- "$t" "$p" | head -c 120)") ;;
    has-re) grep -qaE -- "$2" "$p" || why+=("$1 does not match /$2/") ;;
    lines)
      local n
      n=$(wc -l <"$p")
      [ "$n" = "$2" ] || why+=("$1 has $n lines, expected $2") ;;
    png)
      [ "$(head -c 8 "$p" 2>/dev/null | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] ||
        why+=("$1 is not a PNG") ;;
    faster)
      ((elapsed_ms < $1 * 1000)) || why+=("took $((elapsed_ms / 1000)).$(printf '%03d' $((elapsed_ms % 1000))) s, expected < $1 s") ;;
    csv)  # csv FILE COLUMN OP VALUE: every non-empty value of the named column
      local bad
      bad=$(awk -F, -v col="$2" -v op="$3" -v b="$4" '
        NR == 1 { for (i = 1; i <= NF; ++i) if ($i == col) k = i; if (!k) { print "no column " col; exit } next }
        $k != "" { a = $k + 0
          ok = (op == "lt" && a < b) || (op == "le" && a <= b) || (op == "gt" && a > b) || (op == "ge" && a >= b)
          if (!ok) { print "line " NR ": " col " = " $k; exit } }' "$p")
      [ -z "$bad" ] || why+=("$1: $bad, expected $3 $4") ;;
    csvshape)
      local bad
      # Records as RFC 4180 reads them: a quoted field may hold line breaks.
      bad=$(awk '{
          if (!more) { n = 1; q = 0; start = NR; first = $0 }
          for (i = 1; i <= length($0); ++i) { c = substr($0, i, 1); if (c == "\"") q = !q; else if (c == "," && !q) ++n }
          more = q
          if (more) next
          if (start == 1) h = n; else if (n != h) { print start ": " substr(first, 1, 60); exit } }
          END { if (more) print start ": a quoted field left open: " substr(first, 1, 60) }' "$p")
      [ -z "$bad" ] || why+=("$1 is not one CSV table: line $bad") ;;
    num)  # num FILE KEY OP VALUE (OP: lt le gt ge)
      local v
      v=$(json_number "$p" "$2")
      if [ -z "$v" ]; then
        ((status != 0)) || why+=("$1 has no number \"$2\"")
      elif ! awk -v a="$v" -v b="$4" -v op="$3" 'BEGIN {
          ok = (op == "lt" && a + 0 < b + 0) || (op == "le" && a + 0 <= b + 0) ||
               (op == "gt" && a + 0 > b + 0) || (op == "ge" && a + 0 >= b + 0)
          exit !ok }'; then
        why+=("$1: $2 = $v, expected $3 $4")
      fi ;;
    close)  # close FILE1 FILE2 KEY REL
      local q=$(subject "$case_dir" "$2") v1 v2
      v1=$(json_number "$p" "$3")
      v2=$(json_number "$q" "$3")
      if [ -z "$v1" ] || [ -z "$v2" ]; then
        ((status != 0)) ||
        why+=("\"$3\" missing (${v1:-none} in $1, ${v2:-none} in $2)")
      elif ! awk -v a="$v1" -v b="$v2" -v r="$4" 'BEGIN { d = a - b; if (d < 0) d = -d;
          m = b < 0 ? -b : b; exit !(d <= r * m) }'; then
        why+=("$3 differs: $v1 in $1, $v2 in $2 (relative tolerance $4)")
      fi ;;
    peak-mb)  # peak-mb N: the command run under peak_rss used at most N MB
      local kb
      kb=$(cat "$case_dir/peak_kb" 2>/dev/null)
      if [ -z "$kb" ]; then why+=("no peak memory measured (run the command under peak_rss)")
      elif ((kb > $1 * 1024)); then why+=("peak memory $((kb / 1024)) MB, expected at most $1 MB")
      fi ;;
    *) why+=("harness: unknown check '$what'") ;;
  esac
}

# sections NAME N [FRAME|-] [LENGTH_m] [MASS_kg] [uniform|alt|ei=EI_N_m2]: a beam of
# LENGTH and MASS (0.7 m, 0.25 kg) as N equal sections, with FRAME as its
# "frame" object; alt alternates the sections' masses (x0.9, x1.1) so that no
# two neighbours are alike; ei= gives every section its own stiffness.
make_sections() {
  local name=$1 n=$2 frame=${3:--} length=${4:-0.7} mass=${5:-0.25} mode=${6:-uniform}
  FRAME=$frame awk -v n="$n" -v L="$length" -v M="$mass" -v mode="$mode" 'BEGIN {
    frame = ENVIRON["FRAME"]
    printf "{\"implement\": {\"sections\": ["
    for (i = 0; i < n; ++i) {
      m = M / n
      if (mode == "alt") m *= (i % 2 ? 1.1 : 0.9)
      printf "%s{\"length_m\": %.17g, \"mass_kg\": %.17g", (i ? ", " : ""), L / n, m
      if (mode ~ /^ei=/) printf ", \"EI_N_m2\": %s", substr(mode, 4)
      printf "}"
    }
    printf "]}"
    if (frame != "-") printf ", \"frame\": %s", frame
    printf ", \"impact\": {\"from_tip_m\": 0.16}}\n"
  }' >"$name"
}

# A private /dev for this case (the case runs in its own mount namespace):
# devices and /dev/std* as on a real system, so that a program that replaces
# them harms nothing outside.
fake_dev() {
  ((EUID == 0)) || return 1
  [ -n "${HOSTILE_IN_NAMESPACE:-}" ] || return 1
  local d=$case_dir/dev
  mkdir -p "$d" || return 1
  mknod "$d/null" c 1 3 && mknod "$d/zero" c 1 5 && mknod "$d/full" c 1 7 &&
    mknod "$d/urandom" c 1 9 && mknod "$d/random" c 1 8 || return 1
  chmod 666 "$d"/null "$d"/zero "$d"/full "$d"/urandom "$d"/random
  ln -s /proc/self/fd "$d/fd" && ln -s /proc/self/fd/0 "$d/stdin" &&
    ln -s /proc/self/fd/1 "$d/stdout" && ln -s /proc/self/fd/2 "$d/stderr" || return 1
  mkdir -p "$d/shm" "$d/pts"
  mount --bind "$d" /dev 2>/dev/null
}

# tinyfs DIR KB: a tmpfs of KB kilobytes at DIR (in this case's namespace).
tiny_fs() {
  ((EUID == 0)) || return 1
  [ -n "${HOSTILE_IN_NAMESPACE:-}" ] || return 1
  mkdir -p "$1" && mount -t tmpfs -o "size=${2}k,mode=0755" hostile-tinyfs "$1" 2>/dev/null
}

# fill DIR: write DIR/fill until the file system is full.
fill_fs() {
  dd if=/dev/zero of="$1/fill" bs=4096 2>/dev/null
  : >"$1/fill-inode-probe" 2>/dev/null && rm -f "$1/fill-inode-probe"
  return 0
}

needs_namespace() {
  [[ "$1" =~ (^|' ;; ')(fakedev|tinyfs)( |$) ]]
}

# ---------------------------------------------------------------------------
if [ "${1:-}" = --case ]; then
  shift
  run_one "$@"
  exit 0
fi

usage() { sed -n '2,17p' "$self" | sed 's/^# \{0,1\}//' >&2; exit 2; }
(($# >= 2)) || usage
sweetspot=$1
work=$2
shift 2
only="*"
verbose=""
tables=()
while (($#)); do
  case "$1" in
    --only) only=$2; shift ;;
    --verbose) verbose=1 ;;
    -*) usage ;;
    *) tables+=("$1") ;;
  esac
  shift
done
((${#tables[@]})) || tables=("$here"/*.tsv)
[ -x "$sweetspot" ] || { echo "hostile: $sweetspot is not an executable" >&2; exit 2; }
sweetspot=$(cd "$(dirname "$sweetspot")" && pwd)/$(basename "$sweetspot")

rm -rf "$work" && mkdir -p "$work/bin" "$work/cases" || exit 2
work=$(cd "$work" && pwd)
ln -s "$sweetspot" "$work/bin/sweetspot"
# What every command sees: sweetspot on the PATH, and small helpers.
cat >"$work/lib.sh" <<LIB
export PATH="$work/bin:\$PATH"
export LC_ALL=C.UTF-8
# longname N SUFFIX: a file name of exactly N bytes ending in SUFFIX.
longname() { local n=\$((\$1 - \${#2})); printf '%*s%s' "\$n" '' "\$2" | tr ' ' n; }
# signal_after SECONDS SIGNAL COMMAND...: run COMMAND, send it SIGNAL after
# SECONDS (as a terminal or a supervisor would), return its exit status.
signal_after() {
  set -m
  "\${@:3}" &
  local p=\$!
  sleep "\$1"
  kill -s "\$2" "\$p" 2>/dev/null
  ( sleep 15; kill -KILL "\$p" 2>/dev/null ) &
  local w=\$!
  wait "\$p"
  local s=\$?
  kill -- -"\$w" 2>/dev/null
  return "\$s"
}
# peak_rss COMMAND...: run COMMAND, note its peak resident memory (VmHWM) for
# the peak-mb check, return its exit status.
peak_rss() {
  "\$@" &
  local p=\$! kb=0 now
  while kill -0 "\$p" 2>/dev/null; do
    now=\$(awk '/^VmHWM:/ { print \$2 }' "/proc/\$p/status" 2>/dev/null)
    [ -n "\$now" ] && ((now > kb)) && kb=\$now
    sleep 0.02
  done
  wait "\$p"
  local s=\$?
  echo "\$kb" >"\$HOSTILE_CASE_DIR/peak_kb"
  return "\$s"
}
LIB
export HOSTILE_KEEP=$verbose

passed=0 failed=0 skipped=0
for table in "${tables[@]}"; do
  while IFS=$'\t' read -r id setup command expect fragment checks extra; do
    [[ -z "$id" || "$id" == \#* ]] && continue
    [[ "$id" == $only ]] || continue
    if [ -z "${checks:-}" ] || [ -n "${extra:-}" ]; then
      echo "FAIL $id: harness: the row needs exactly 6 tab-separated fields"
      failed=$((failed + 1))
      continue
    fi
    if needs_namespace "$setup"; then
      result=$(HOSTILE_IN_NAMESPACE=1 unshare -m --propagation private \
        bash "$self" --case "$work" "$id" "$setup" "$command" "$expect" "$fragment" "$checks" 2>&1) ||
        result="SKIP $id: unshare -m failed (needs root): ${result//$'\n'/ }"
    else
      result=$(bash "$self" --case "$work" "$id" "$setup" "$command" "$expect" "$fragment" "$checks" 2>&1)
    fi
    # The case's last PASS, FAIL or SKIP line (a case may print more).
    last=""
    while IFS= read -r line; do
      [[ "$line" =~ ^(PASS|FAIL|SKIP)\  ]] && last=$line
    done <<<"$result"
    result=${last:-"FAIL $id: harness: the case printed no result"}
    case "$result" in
      PASS*) passed=$((passed + 1)); [ -n "$verbose" ] && echo "$result" ;;
      SKIP*) skipped=$((skipped + 1)); echo "$result" ;;
      *) failed=$((failed + 1)); echo "$result" ;;
    esac
  done <"$table"
done
echo "hostile: $passed passed, $failed failed, $skipped skipped"
((failed == 0))

# Shell helpers shared by the benchmark scripts (sourced, not run).

# value KEY FILE: the first value of KEY in a summary.json (strings without
# their quotes).
value() { grep "\"$1\"" "$2" | head -1 | sed 's/.*: \([^,]*\),*/\1/' | tr -d '"'; }

# text_value KEY FILE: the whole string value of KEY in a summary.json
# (value() stops at its first comma).
text_value() { grep "\"$1\"" "$2" | head -1 | sed 's/^ *"[^"]*": "//; s/",\{0,1\}$//'; }

# machine: "N cores, CPU model" of this machine.
machine() { echo "$(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"; }

# start_table CSV CSV_HEADER MARKDOWN_COLUMN...: write the CSV's header line
# and print a blank line and a markdown table header with these columns.
start_table() {
  local csv=$1 header=$2 line='|' rule='|' column
  shift 2
  echo "$header" >"$csv"
  for column in "$@"; do
    line+=" $column |"
    rule+=" --- |"
  done
  printf '\n%s\n%s\n' "$line" "$rule"
}

# timer_share SECTION LOG: the share of wall time ("35%") of a TimerOutput
# section in a run's screen output.
timer_share() { grep "^| $1 " "$2" | awk -F'|' '{ gsub(/ /, "", $5); print $5 }'; }

# timer_seconds SECTION LOG: the wall seconds of a TimerOutput section in a
# run's screen output.
timer_seconds() { grep "^| $1 " "$2" | awk -F'|' '{ gsub(/[ s]/, "", $4); print $4 }'; }

# timer_calls SECTION LOG: the number of calls of a TimerOutput section in a
# run's screen output (0 if the section did not run).
timer_calls() {
  local calls
  calls=$(grep "^| $1 " "$2" | awk -F'|' '{ gsub(/ /, "", $3); print $3 }')
  echo "${calls:-0}"
}

# seconds COMMAND...: run it, print its wall seconds (fails if it fails).
seconds() {
  local start end
  start=$(date +%s.%N)
  "$@" || return 1
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f\n", b - a }'
}

# timed_run LOG COMMAND...: run it with its output into LOG; sets
# run_code (its exit code) and run_seconds (its wall seconds, "%.1f"), and
# does not fail when it fails.
timed_run() {
  local log=$1 start end
  shift
  start=$(date +%s.%N)
  "$@" >"$log" 2>&1
  run_code=$?
  end=$(date +%s.%N)
  run_seconds=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f\n", b - a }')
}

# solve_cells DIR: the table cells "Newton steps | direct inverse: Newton
# steps / Jacobian products | CG iterations per Newton step" of a run's
# DIR/summary.json.
solve_cells() {
  local s=$1/summary.json
  printf '%s | %s / %s | %s' "$(value newton_iterations "$s")" \
    "$(value direct_inverse_newton_steps "$s")" \
    "$(value direct_inverse_jacobian_products "$s")" \
    "$(value linear_iterations_per_newton_step "$s")"
}

# median: the median of the numbers on stdin (one line, space-separated).
median() { tr ' ' '\n' | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

# require_valgrind: exit 77 (skipped) with a line if valgrind is missing.
require_valgrind() {
  if ! command -v valgrind >/dev/null; then
    echo "valgrind is not installed (apt-get install valgrind): nothing measured"
    exit 77
  fi
}

# bulk_modulus MU NU: the bulk modulus (Pa) of a law of shear modulus MU
# (Pa) and Poisson's ratio NU.
bulk_modulus() { echo "2 * $1 * (1 + $2) / (3 * (1 - 2 * $2))" | bc -l; }

# The --set arguments that switch every scenario of a brain scene off.
scenario_off=(--set "Scenario prone/Enabled=false" --set "Scenario drained/Enabled=false"
  --set "Scenario craniotomy/Enabled=false" --set "Scenario/Enabled=false")

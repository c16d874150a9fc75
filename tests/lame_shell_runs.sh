# Sourced by the Lame shell tests (run_lame_rates.sh, run_lame_hex.sh):
# the figures of one run and the rate between two. Needs $out and $here.

# lame_figure NAME NU: "RMS_PERCENT NODES" of the run in $out/NAME
# (tests/check_lame_shell.py on its nodes.csv; 1 Pa, E = 3 kPa, support 1e3).
lame_figure() {
  local figure
  figure=$(/usr/bin/python3 "$here/check_lame_shell.py" "$out/$1/nodes.csv" --E 3000 \
    --nu "$2" --p-inner 1 --support 1e3 --label "$1" |
    sed -E 's/.*displacement ([0-9.]+) %.*/\1/')
  echo "$figure $(grep -o '"n_nodes": [0-9]*' "$out/$1/summary.json" | grep -o '[0-9]*$')"
}

# lame_rate "E1 N1" "E2 N2": the rate in h ~ nodes^(-1/3),
# log(e1/e2) / log(h1/h2).
lame_rate() {
  awk -v a="$1" -v b="$2" 'BEGIN { split(a, p, " "); split(b, q, " ")
    printf "%.2f", log(p[1] / q[1]) / (log(q[2] / p[2]) / 3) }'
}

#!/bin/bash
# Inputs that are not regular files (a FIFO nobody writes to) are refused
# with one line before they are opened: a reader that opened them would
# block forever. Each parameter that names an input file of the scene.
# (timeout only detects a hang; it is no time limit on the work.)
#
# usage: run_fifo_inputs.sh RUN_ERROR RESTSHAPE OUTPUT_DIRECTORY
set -u
run_error=$1
exe=$2
out=$3
rm -rf "$out"
mkdir -p "$out"
fifo="$out/fifo.msh"
mkfifo "$fifo" || { echo "FAIL: cannot make a FIFO"; exit 1; }
names="$out/names.txt"
mkfifo "$names"
status=0
check() {
  local name=$1 regex=$2
  shift 2
  timeout 120 "$run_error" "$exe" "$out/$name" 1 "$regex" "$@" tests/scenes/column_p2_tet.prm
  local code=$?
  [ "$code" -eq 124 ] && echo "FAIL: $name blocks on the FIFO"
  [ "$code" -eq 0 ] || status=1
}
check mesh "fifo.msh: Mesh/File: not a readable file" --set "Mesh/File=$fifo"
check label_names "names.txt: Mesh/Label names: not a regular file .a directory, FIFO or device." \
  --set "Mesh/Label names=$names"
check rest_shape "fifo.msh: Mesh/Rest shape file: not a readable file" --set "Mesh/Rest shape file=$fifo"
obstacle="$out/skull.off"
mkfifo "$obstacle"
check obstacle "skull.off: Contact/Obstacle file: no such readable file" --set "Contact/Obstacle file=$obstacle"
exit $status

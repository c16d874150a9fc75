#!/bin/bash
# summary.json stays valid JSON (UTF-8) whatever the tissues are called:
# label names with a backslash, a control character and a byte that is
# not UTF-8 (Latin-1 e acute) on prm/brain.prm, whose summary has a key
# per tissue (contact_force_NAME_N). Read back with Python's strict parser.
#
# usage: run_json_names.sh RESTSHAPE OUTPUT_DIRECTORY
set -u
exe=$1
out=$2
rm -rf "$out"
mkdir -p "$out"
printf '1 cere\\brum\n2 tu\001mour\n3 cereb\351llum\n4 brain\177stem\n' >"$out/names.txt"
"$exe" --set "Mesh/Label names=$out/names.txt" --set "Output/Directory=$out/run" \
  --set "Output/Write VTU=false" --set "Scenario/Enabled=false" prm/brain.prm >"$out/log" 2>&1 ||
  { echo "FAIL: the run failed"; tail -n 5 "$out/log"; exit 1; }
python3 - "$out/run/summary.json" <<'PY'
import json, sys
text = open(sys.argv[1], 'rb').read().decode('utf-8')  # strict
s = json.loads(text)
keys = [k for k in s if k.startswith('contact_force_') and k != 'contact_force_N']
want = {'contact_force_cere\\brum_N', 'contact_force_tu\x01mour_N',
        'contact_force_cereb\u00e9llum_N', 'contact_force_brain\x7fstem_N'}
if not want <= set(keys):
    sys.exit(f"FAIL: keys {keys}, expected {sorted(want)}")
print("ok: summary.json parses; tissue keys", keys)
PY

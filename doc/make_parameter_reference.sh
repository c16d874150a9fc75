#!/bin/bash
# Writes the parameter reference (markdown) from restshape --print-parameters:
# one section per subsection, one table row per parameter with its default
# and its help text; then the load terms of the registry, each with its
# description, its loads and its scenario entries (restshape
# --print-load-terms). Every build runs it into doc/parameters.md; the test
# doc/parameter_reference checks that the committed file is current.
#
# usage: doc/make_parameter_reference.sh RESTSHAPE > doc/parameters.md
set -euo pipefail
"$1" --print-parameters | awk '
  function flush_path(   p, i) {
    p = ""
    for (i = 1; i <= depth; ++i) p = p (i > 1 ? "/" : "") stack[i]
    return p
  }
  function cell(text) { gsub(/\|/, "\\|", text); return text }
  BEGIN {
    print "# Parameter reference"
    print ""
    print "Generated from `build/restshape --print-parameters` by"
    print "`cmake --build build --target parameter_reference`; do not edit."
    print "Every parameter of a scene file (`.prm`), by subsection, with its"
    print "default and what it does. `--set '\''Subsection/Parameter=value'\''`"
    print "changes one on the command line."
    depth = 0; help = ""
  }
  /^# Listing of Parameters/ || /^# -+$/ { next }
  /^[ \t]*subsection / {
    sub(/^[ \t]*subsection /, ""); stack[++depth] = $0; printed[depth] = 0
    help = ""; next
  }
  /^[ \t]*end[ \t]*$/ { --depth; help = ""; next }
  /^[ \t]*#/ {
    line = $0; sub(/^[ \t]*# ?/, "", line)
    help = help (help == "" ? "" : " ") line; next
  }
  /^[ \t]*set / {
    line = $0; sub(/^[ \t]*set /, "", line)
    eq = index(line, "=")
    name = substr(line, 1, eq - 1); value = substr(line, eq + 1)
    sub(/[ \t]+$/, "", name); sub(/^[ \t]+/, "", value); sub(/[ \t]+$/, "", value)
    if (!printed[depth]) {
      print ""; print "## " flush_path(); print ""
      print "| parameter | default | meaning |"; print "| --- | --- | --- |"
      printed[depth] = 1
    }
    print "| `" cell(name) "` | " (value == "" ? "(empty)" : "`" cell(value) "`") " | " cell(help) " |"
    help = ""; next
  }
  /^[ \t]*$/ { help = ""; next }
'
echo
echo "## Load terms"
echo
echo "Every load a scene can apply, from the registry"
echo "(\`source/loads/load_registry.cc\`): what it does, the names of its"
echo "loads (which \`Scenario/Load scale\` takes) and its scenario entries."
echo
"$1" --print-load-terms

#!/usr/bin/env python3
"""Calls and inclusive instructions of one function in a callgrind profile,
split by its caller.

usage: calls.py CALLGRIND_OUT FUNCTION
Prints one line per caller: "calls instructions caller". FUNCTION is the
start of the callee's name (e.g. "RestShape::TangentScatter::locate("), or
its whole name when it ends in ")" (then its lambdas, whose names start
with it, do not count).
"""
import re
import sys


def main(path, function):
    names = {"fn": {}, "cfn": {}}
    caller = callee = None
    totals = {}
    pending = None
    name_line = re.compile(r"^(c?fn)=\((\d+)\)(?: (.*))?$")
    with open(path, errors="replace") as f:
        for line in f:
            line = line.rstrip("\n")
            if pending is not None:
                cost = int(line.split()[1]) if len(line.split()) > 1 else 0
                if callee and (
                    callee == function
                    if function.endswith(")")
                    else callee.startswith(function)
                ):
                    calls, ir = totals.get(caller, (0, 0))
                    totals[caller] = (calls + pending, ir + cost)
                pending = None
                continue
            m = name_line.match(line)
            if m:
                kind, key, name = m.groups()
                # fn and cfn share one table of compressed names.
                if name:
                    names["fn"][key] = name
                name = names["fn"].get(key, "?")
                if kind == "fn":
                    caller = name
                else:
                    callee = name
                continue
            if line.startswith("calls="):
                pending = int(line[6:].split()[0])
    for name, (calls, ir) in sorted(totals.items()):
        print(calls, ir, name)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])

#!/usr/bin/env python3
"""The layering of the house, checked: every #include <restshape/PART/...>
in source/PART/ and include/restshape/PART/ must name PART itself or a part
that the table of doc/developer.md ("| `part` | what it holds | may include
|") allows PART to include. Prints each edge the table does not allow, with
the file and line, and exits 1 if there is one; also fails on a part of the
code that the table does not list, and on a table row whose part has no
folder.

usage: check_layering.py [REPOSITORY]"""
import os
import re
import sys

ROW = re.compile(r"^\|\s*`(\w+)`\s*\|[^|]*\|([^|]*)\|\s*$")
INCLUDE = re.compile(r"^\s*#\s*include\s*<restshape/(\w+)/[^>]+>")


def allowed_edges(manual):
    """{part: set of parts it may include} from the table's rows."""
    table = {}
    with open(manual, encoding="utf-8") as f:
        for line in f:
            m = ROW.match(line)
            if m:
                table[m.group(1)] = set(re.findall(r"`(\w+)`", m.group(2)))
    return table


def part_files(repo):
    """(part, path) for every C++ file of source/PART and include/restshape/PART."""
    for top, depth in (("source", 1), (os.path.join("include", "restshape"), 2)):
        root = os.path.join(repo, top)
        for part in sorted(os.listdir(root)):
            folder = os.path.join(root, part)
            if not os.path.isdir(folder):
                continue
            for base, _, files in os.walk(folder):
                for name in sorted(files):
                    if name.endswith((".h", ".cc")):
                        yield part, os.path.join(base, name)


def main():
    repo = sys.argv[1] if len(sys.argv) > 1 else "."
    table = allowed_edges(os.path.join(repo, "doc", "developer.md"))
    if not table:
        print("doc/developer.md: no layering table found")
        return 1
    problems = []
    parts = set()
    for part, path in part_files(repo):
        parts.add(part)
        if part not in table:
            problems.append(f"{os.path.relpath(path, repo)}: part '{part}' "
                            "is not in the table of doc/developer.md")
            continue
        with open(path, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if m and m.group(1) != part and m.group(1) not in table[part]:
                    problems.append(
                        f"{os.path.relpath(path, repo)}:{number}: {part} "
                        f"includes {m.group(1)}, which doc/developer.md "
                        f"does not allow ({part} may include: "
                        f"{', '.join(sorted(table[part])) or 'nothing'})")
    for part in sorted(set(table) - parts):
        problems.append(f"doc/developer.md: part '{part}' has no folder "
                        "source/ or include/restshape/")
    for p in problems:
        print(p)
    if problems:
        return 1
    print(f"layering holds: {len(parts)} parts")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Where the Newton steps of contact solves go: each step of the converged
forward solves in the logs of benchmarks/contact_stress/run.sh, by what it
follows.

  set change   the step's active-set update added or released nodes
  release      a release of nodes that pull (no set change since)
  strict       a round of the strict check of a converged state
  converge     none of these yet: Newton converging on its first set
  halved       a step of an attempt given back (its increment halved)

usage: step_profile.py LOG...   (DIR.log of run.sh's cases; run.sh
passes those of each degree it ran)
Prints one line per category and the total.
"""
import re
import sys

CATEGORIES = ("set change", "release", "strict", "converge", "halved")
STEP = re.compile(r"Newton +(\d+):.*\(\+(\d+) new, -(\d+) released\)")


def profile(log):
    """The categories of the steps of one converged solve, or None."""
    lines = open(log).read().splitlines()
    if not any("Forward solve: converged" in l for l in lines):
        return None
    counts = dict.fromkeys(CATEGORIES, 0)
    attempt, follows = [], "converge"
    for line in lines:
        if "Newton failed" in line:
            counts["halved"] += len(attempt)
            attempt, follows = [], "converge"
        elif "corrected" in line:
            follows = "strict"
        elif "pull on the obstacle: released" in line and follows != "strict":
            follows = "release"
        else:
            m = STEP.search(line)
            if m:
                if m.group(1) == "1":  # a new load step
                    follows = "converge"
                changed = int(m.group(2)) + int(m.group(3)) > 0
                attempt.append("set change" if changed else follows)
    for c in attempt:
        counts[c] += 1
    return counts


def main():
    total = dict.fromkeys(CATEGORIES, 0)
    solves = 0
    for log in sys.argv[1:]:
        counts = profile(log)
        if counts is None:
            continue
        solves += 1
        for k, v in counts.items():
            total[k] += v
    for k, v in total.items():
        print(f"{k:10s} {v:5d}")
    print(f"{'all':10s} {sum(total.values()):5d} Newton steps in {solves} converged solves")


if __name__ == "__main__":
    main()

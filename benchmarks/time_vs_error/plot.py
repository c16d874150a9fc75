#!/usr/bin/env python3
# Log-log plot of wall time against the rest shape's relative L2 error, one
# line per element, from benchmarks/time_vs_error/run.sh's CSV.
#
# usage: python3 benchmarks/time_vs_error/plot.py [CSV] [PNG]
#   defaults: output/benchmarks/time_vs_error/time_vs_error.csv,
#             doc/figures/time_vs_error.png
import csv
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

source = sys.argv[1] if len(sys.argv) > 1 else 'output/benchmarks/time_vs_error/time_vs_error.csv'
target = sys.argv[2] if len(sys.argv) > 2 else 'doc/figures/time_vs_error.png'
rows = list(csv.DictReader(open(source)))
plt.figure(figsize=(6.5, 4.2))
for element, style in (('P1', '-o'), ('P2', '-s'), ('Q1', '--o'), ('Q2', '--s')):
    r = [x for x in rows if x['element'] == element]
    if not r:
        continue
    plt.loglog([float(x['rest_l2_error_relative']) for x in r], [float(x['seconds']) for x in r],
               style, label=element)
    for x in r:
        plt.annotate(x['n_dofs'], (float(x['rest_l2_error_relative']), float(x['seconds'])),
                     fontsize=6, xytext=(3, 3), textcoords='offset points')
plt.gca().invert_xaxis()
plt.xlabel('relative L2 error of the rest shape (inverse column)')
plt.ylabel('wall time of the whole inverse solve (s)')
plt.grid(True, which='both', alpha=0.3)
plt.legend()
plt.tight_layout()
plt.savefig(target, dpi=120)
print('wrote', target)

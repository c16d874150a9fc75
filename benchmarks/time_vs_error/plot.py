#!/usr/bin/env python3
# Log-log plots of wall time against error, one line per element, from the
# CSV files of benchmarks/time_vs_error/{run,brain,hertz}.sh:
#   time_vs_error.csv -> doc/figures/time_vs_error.png (inverse column, rest
#                        shape's relative L2 error)
#   brain/brain.csv   -> doc/figures/time_vs_error_brain.png (brain forward,
#                        relative RMS nodal error against the reference)
#   hertz.csv         -> doc/figures/time_vs_error_hertz.png (Hertz, peak
#                        contact pressure error)
# A missing CSV is skipped.
#
# usage: python3 benchmarks/time_vs_error/plot.py [DIRECTORY]
#   default DIRECTORY: output/benchmarks/time_vs_error
import csv
import os
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

directory = sys.argv[1] if len(sys.argv) > 1 else 'output/benchmarks/time_vs_error'
STYLES = (('P1', '-o'), ('P2', '-s'), ('Q1', '--o'), ('Q2', '--s'))


def plot(source, target, error_key, xlabel, ylabel, absolute=False):
    if not os.path.exists(source):
        print('skipped', source)
        return
    rows = list(csv.DictReader(open(source)))
    plt.figure(figsize=(6.5, 4.2))
    for element, style in STYLES:
        r = [x for x in rows if x['element'] == element]
        if not r:
            continue
        errors = [abs(float(x[error_key])) if absolute else float(x[error_key]) for x in r]
        plt.loglog(errors, [float(x['seconds']) for x in r], style, label=element)
        for x, e in zip(r, errors):
            plt.annotate(x['n_dofs'], (e, float(x['seconds'])), fontsize=6, xytext=(3, 3),
                         textcoords='offset points')
    plt.gca().invert_xaxis()
    plt.xlabel(xlabel)
    plt.ylabel(ylabel)
    plt.grid(True, which='both', alpha=0.3)
    plt.legend()
    plt.tight_layout()
    plt.savefig(target, dpi=120)
    print('wrote', target)


plot(f'{directory}/time_vs_error.csv', 'doc/figures/time_vs_error.png', 'rest_l2_error_relative',
     'relative L2 error of the rest shape (inverse column)', 'wall time of the whole inverse solve (s)')
plot(f'{directory}/brain/brain.csv', 'doc/figures/time_vs_error_brain.png', 'relative_rms_error',
     'relative RMS nodal error against the reference (brain, forward)',
     'wall time of the forward solve (s)')
plot(f'{directory}/hertz.csv', 'doc/figures/time_vs_error_hertz.png', 'pressure_error',
     '|peak contact pressure - Hertz p0| / p0', 'wall time of the solve (s)', absolute=True)

#!/usr/bin/env python3
"""The robustness campaign of doc/benchmarks.md ("Robustness campaign"):
semantically odd parameters, the run's environment, MPI, the mesher's
images and the study, each case against the contract of README.md
("Exit codes"): the expected exit code, one line on stderr for a failure,
no crash, no hang, a summary.json that parses, and the case's own check.

  benchmarks/robustness/run.py [BUILD_DIR] [OUTPUT_DIR] [--quick]

Prints one line per case and a table of the classes (cases, held, broke);
exits 1 if a case broke. --quick runs the cases without MPI or a study.
"""
import csv
import json
import os
import shutil
import signal
import subprocess
import sys
import time

args = [a for a in sys.argv[1:] if not a.startswith("--")]
QUICK = "--quick" in sys.argv
BUILD = os.path.abspath(args[0] if args else "build")
OUT = os.path.abspath(args[1] if len(args) > 1 else "output/robustness")
RESTSHAPE = os.path.join(BUILD, "restshape")
MESHER = os.path.join(BUILD, "restshape-mesh")
MPIRUN = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--quiet", "-np", "2"]
HANG = 300  # s: a case still running then counts as a hang

CLASSES = {
    1: "stability check without mass or free DoF",
    2: "an error on one MPI rank",
    3: "FIFOs as input files",
    4: "the output directory",
    5: "label names in summary.json",
    6: "the run-size estimate",
    7: "disk and stdout",
    8: "the study",
    9: "an obstacle inside the body",
    10: "restshape-mesh on bad images",
    11: "the thread count in the environment",
    12: "overflowing values",
}
results = []


def run(cmd, env=None, timeout=HANG, stdin=None, shell=False):
    e = dict(os.environ, **(env or {}))
    try:
        p = subprocess.run(cmd, env=e, capture_output=True, text=True, errors="replace",
                           timeout=timeout, shell=shell, stdin=stdin,
                           executable="/bin/bash" if shell else None)
        return p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired:
        return None, "", "hang"


def out_dir(name):
    d = os.path.join(OUT, name)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    return d


def lock_is_held(directory):
    """True while some process holds a flock on directory/.restshape.lock,
    read from /proc/locks (probing with flock ourselves could make the run
    find its directory taken)."""
    try:
        inode = os.stat(os.path.join(directory, ".restshape.lock")).st_ino
    except FileNotFoundError:
        return False
    with open("/proc/locks") as locks:
        for line in locks:
            fields = line.split()
            if "FLOCK" in fields and any(f.endswith(f":{inode}") for f in fields):
                return True
    return False


def wait_for_lock(directory, process):
    """Waits until process holds the lock on directory (or has ended): a
    fixed sleep raced with a loaded machine, where the second run took the
    directory first and both, rightly, exited 0 one after the other."""
    while process.poll() is None and not lock_is_held(directory):
        time.sleep(0.05)


def judge(cls, name, code, err, want, extra=None):
    """want: the expected exit code; extra: a check returning '' or why."""
    why = ""
    if code is None:
        why = "hangs"
    elif code != want:
        why = f"exit {code}, expected {want}"
    elif code != 0 and len(err.strip().splitlines()) != 1:
        why = f"{len(err.strip().splitlines())} lines on stderr"
    elif extra:
        why = extra()
    results.append((cls, name, why))
    print(f"[{cls:2}] {name}: {'held' if not why else 'BROKE: ' + why}", flush=True)


def summary_ok(directory, **want):
    def check():
        path = os.path.join(directory, "summary.json")
        try:
            s = json.loads(open(path, "rb").read().decode("utf-8"))
        except Exception as e:  # noqa: BLE001
            return f"summary.json: {e}"
        for k, v in want.items():
            if s.get(k) != v:
                return f"summary.json {k} = {s.get(k)!r}, expected {v!r}"
        return ""
    return check


def restshape(name, cls, want, *sets, prm="prm/column.prm", env=None, mpi=False,
              extra=None):
    d = out_dir(name)
    cmd = (MPIRUN if mpi else []) + [RESTSHAPE, "--set", f"Output/Directory={d}"]
    for s in sets:
        cmd += ["--set", s]
    code, out, err = run(cmd + [prm], env=env)
    judge(cls, name, code, err, want, extra(d) if extra else None)
    return d


def mesher(name, image, want, *options, extra=None):
    d = out_dir(name)
    code, out, err = run([MESHER, "--image", image, "--out", f"{d}/mesh.msh", *options])
    judge(10, name, code, err, want, extra)


# 1: the stability check with no mass, or no free DoF.
restshape("density_0_column", 1, 0, "Materials/Density=0", "Solver/Check stability=true",
          "Verification/Exact displacement=", extra=lambda d: summary_ok(d, converged=True))
restshape("density_0_brain", 1, 0, "Materials/Density=0", "Scenario/Enabled=false",
          "Output/Write VTU=false", prm="prm/brain.prm",
          extra=lambda d: summary_ok(d, converged=True))
restshape("density_0_one_label", 1, 0, "Materials/Density=1:0, 2:1000",
          "Solver/Check stability=true", "Verification/Exact displacement=")
restshape("every_label_fixed", 1, 1, "Boundary conditions/Fixed labels=1, 2")
if not QUICK:
    restshape("density_0_column_mpi", 1, 0, "Materials/Density=0", "Solver/Check stability=true",
              "Verification/Exact displacement=", mpi=True)

# 2: errors on one rank end every rank alike.
if not QUICK:
    d = out_dir("output_removed_mpi")
    p = subprocess.Popen(MPIRUN + [RESTSHAPE, "--set", f"Output/Directory={d}/run",
                                   "--set", "Mesh/Global refinements=1", "prm/brain.prm"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    time.sleep(4)
    shutil.rmtree(d, ignore_errors=True)
    try:
        _, err = p.communicate(timeout=HANG)
        code = p.returncode
    except subprocess.TimeoutExpired:
        p.kill()
        code, err = None, ""
    # Either it finished before (0) or it failed to write on every rank (5).
    judge(2, "output_removed_mpi", code, err, 5 if code not in (0,) else 0)
    # SIGTERM to mpirun: every rank ends, summary.json says so; mpirun's own
    # exit code is Open MPI's (1), the ranks' is 143.
    d = out_dir("sigterm_mpi")
    p = subprocess.Popen(MPIRUN + [RESTSHAPE, "--set", f"Output/Directory={d}/run",
                                   "--set", "Discretization/Polynomial degree=2",
                                   "prm/brain.prm"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    time.sleep(6)
    p.send_signal(signal.SIGTERM)
    _, err = p.communicate(timeout=HANG)
    time.sleep(2)
    ranks = run(["pgrep", "-f", f"^{RESTSHAPE} --set Output/Directory={d}/run"])[1].strip()
    judge(2, "sigterm_mpi", 0 if p.returncode in (1, 143) else p.returncode, "", 0,
          lambda: f"ranks left running: {ranks}" if ranks else
          summary_ok(f"{d}/run", failure="interrupted by SIGTERM (signal 15)")())

# 3: FIFOs.
d = out_dir("fifos")
for what, param in (("mesh", "Mesh/File"), ("names", "Mesh/Label names"),
                    ("rest", "Mesh/Rest shape file"), ("obstacle", "Contact/Obstacle file")):
    fifo = os.path.join(d, f"{what}.fifo")
    os.mkfifo(fifo)
    code, out, err = run([RESTSHAPE, "--set", f"Output/Directory={d}/{what}", "--set",
                          f"{param}={fifo}", "tests/scenes/column_p2_tet.prm"], timeout=60)
    judge(3, f"fifo_{what}", code, err, 1)

# 4: the output directory.
d = restshape("scenario_files_removed", 4, 0, "Scenario/Enabled=false", "Output/Write VTU=false",
              prm="prm/brain.prm")
open(os.path.join(d, "scenario_prone.csv"), "w").write("stale\n")
restshape("scenario_files_removed", 4, 0, "Scenario/Enabled=false", "Output/Write VTU=false",
          prm="prm/brain.prm")
d = out_dir("scenario_files_removed_again")
open(os.path.join(d, "scenario_prone.csv"), "w").write("stale\n")
open(os.path.join(d, "scenario_prone.vtu"), "w").write("stale\n")
code, _, err = run([RESTSHAPE, "--set", f"Output/Directory={d}", "prm/column.prm"])
judge(4, "named_scenario_files_of_an_earlier_run", code, err, 0,
      lambda: "" if not os.path.exists(os.path.join(d, "scenario_prone.csv")) else
      "scenario_prone.csv survived")
d = out_dir("two_runs_one_directory")
# The first run lasts about 10 s (the brain refined once), so that the second
# one, 0.3 s on an idle machine, starts and ends while the first holds the
# directory even on a loaded one; the first is then stopped with SIGTERM.
first = subprocess.Popen([RESTSHAPE, "--set", f"Output/Directory={d}",
                          "--set", "Mesh/Global refinements=1", "prm/brain.prm"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
wait_for_lock(d, first)
first_running = first.poll() is None
code, _, err = run([RESTSHAPE, "--set", f"Output/Directory={d}", "prm/column.prm"])
first_still_running = first.poll() is None
first.terminate()
first_err = first.communicate()[1]
first_code = first.returncode
judge(4, "two_runs_one_directory", code, err, 1,
      lambda: "the first run ended before the second started" if not first_running else
      "the first run ended before the second did" if not first_still_running else
      "" if "another run" in err else "no word of the other run")
judge(4, "two_runs_one_directory_first_stopped", first_code, first_err,
      143 if first_still_running else 0)

# 5: label names.
d = out_dir("json_names")
open(f"{d}/names.txt", "wb").write(b"1 a\\b\n2 c\x01d\n3 e\xe9f\n4 g\x7fh\n")
restshape("json_names_run", 5, 0, f"Mesh/Label names={d}/names.txt", "Scenario/Enabled=false",
          "Output/Write VTU=false", prm="prm/brain.prm", extra=lambda d2: summary_ok(d2))

# 6: the run-size estimate.
restshape("cycles_beyond_memory", 6, 1, "Adaptive refinement/Cycles=7",
          "Adaptive refinement/Strategy=global")
restshape("refinements_beyond_memory", 6, 1, "Mesh/Global refinements=7")
d = out_dir("ulimit")
code, _, err = run(f"ulimit -v 3000000; exec {RESTSHAPE} --set Output/Directory={d} "
                   "--set 'Mesh/Global refinements=3' prm/brain.prm", shell=True)
judge(6, "ulimit_v", code, err, 1, lambda: "" if "ulimit" in err else "the limit is not named")

# 7: a closed stdout.
d = out_dir("closed_stdout")
code, _, err = run(f"{RESTSHAPE} --set Output/Directory={d} prm/brain.prm | head -1 >/dev/null;"
                   " exit ${PIPESTATUS[0]}", shell=True)
judge(7, "closed_stdout", code, err, 5, summary_ok(d, converged=True))

# 8: the study.
if not QUICK:
    d = out_dir("study_reasons")
    code, out, err = run([RESTSHAPE, "--study", "Solver/Maximum Newton iterations=50,1",
                          "--set", "Solver/Maximum load step halvings=0",
                          "--set", f"Output/Directory={d}", "prm/cantilever.prm"])
    def study_table():
        rows = list(csv.reader(open(f"{d}/study/study.csv")))
        head = rows[0]
        if "exit_code" not in head or "reason" not in head:
            return "no exit_code or reason column"
        e, r = head.index("exit_code"), head.index("reason")
        if rows[1][e] != "0" or rows[1][r] != "-":
            return f"the converged run's row: {rows[1]}"
        if rows[2][e] != "2" or rows[2][r] in ("-", ""):
            return f"the failed run's row: {rows[2]}"
        return ""
    judge(8, "study_exit_codes_and_reasons", code, "one line", 2, study_table)
    d = out_dir("study_sigterm")
    p = subprocess.Popen([RESTSHAPE, "--study", "Discretization/Polynomial degree=2,2",
                          "--set", f"Output/Directory={d}", "prm/brain.prm"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    time.sleep(3)
    p.send_signal(signal.SIGTERM)
    _, err = p.communicate(timeout=HANG)
    time.sleep(1)
    orphans = run(["pgrep", "-f", f"Output/Directory={d}/study"])[1].strip()
    # An interrupted run owes no error line (README: 128 + the signal).
    judge(8, "study_sigterm", p.returncode, "interrupted", 143,
          lambda: "" if not orphans else f"orphan runs {orphans}")

# 9: an obstacle inside the body.
restshape("obstacle_inside_body", 9, 1, "Contact/Obstacle file=tests/data/cube_in_block.off",
          prm="tests/scenes/block_on_floor.prm")

# 10: the mesher's images.
mesher("zero_voxel_size", "tests/data/zero_voxel.nii", 1)
mesher("nan_voxel_size", "tests/data/nan_voxel_size.nii", 1)
mesher("nan_label", "tests/data/nan_label.nii", 1)
mesher("fractional_label", "tests/data/fractional_label.nii", 1)
d = os.path.join(OUT, "border_cube")
mesher("border_cube", "tests/data/border_cube.nii", 0, "--cell-size", "2")
mesher("enclosed_void_and_ball", "tests/data/enclosed.nii.gz", 0, "--cell-size", "4")

# 11: the thread count.
for value in ("0", "abc", "", "-3"):
    d = out_dir(f"threads_{value or 'empty'}")
    code, _, err = run([RESTSHAPE, "--set", f"Output/Directory={d}", "prm/column.prm"],
                       env={"DEAL_II_NUM_THREADS": value})
    judge(11, f"DEAL_II_NUM_THREADS='{value}'", code, err, 1)

# 12: overflowing values.
restshape("exact_displacement_overflows", 12, 1, "Verification/Exact displacement=-1e308; 0; 0")
restshape("gravity_overflows", 12, 1, "Loads/Gravity=1e300, 0, 0")

print("\n| class | what | cases | held | broke |\n| --- | --- | --- | --- | --- |")
broke = 0
for cls, what in CLASSES.items():
    mine = [r for r in results if r[0] == cls]
    bad = [r for r in mine if r[2]]
    broke += len(bad)
    if mine:
        print(f"| {cls} | {what} | {len(mine)} | {len(mine) - len(bad)} | {len(bad)} |")
print(f"\n{len(results)} cases, {len(results) - broke} held, {broke} broke")
sys.exit(1 if broke else 0)

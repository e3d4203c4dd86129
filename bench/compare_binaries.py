#!/usr/bin/env python3
"""Two mdrsim binaries side by side on the same scenes, interleaved: the JSON's wall_time_s of
the rtol pull-offs and the reversible JKR cycle, and the wall time of a sweep at 1 and 2 threads;
each run's CPU time beside them (on a loaded machine the wall times measure the load as well).

A shared machine's load drifts over minutes: each repeat runs every case once per binary,
alternating which binary goes first, so that a load from elsewhere hits both alike; the medians
over the repeats are compared. Writes one CSV row per run (standard output, or --out), then a
table of medians and ratios (old / new) on standard error.

    /usr/bin/python3 bench/compare_binaries.py OLD NEW [--repeats 7] [--out runs.csv]
        [--cases fig2_fixed_load,cycle_1e6,...] [--scenes DIR]
"""

import argparse
import csv
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RTOL = "discretization={rtol=1e-6}"
SWEEP_VARY = "loading.tangential.displacement=0:9.04593930777979e-06:2000"
SWEEP_SETS = ["discretization.springs=1000", "discretization.extrapolation=richardson"]
# The cycle of target 9 in bench/accuracy_driver.cpp (cycle_text): to 2e-5 m and back.
DRIVER_CYCLE = """[material]
effective_modulus = 1e6
work_of_adhesion = 0.05
approach_work_of_adhesion = 0.05
[profile]
type = "parabolic"
radius = 0.01
[[loading.stage]]
normal = { control = "fixed-grips", to = 2e-5 }
[[loading.stage]]
normal = { by = -2e-5 }
until = "separation"
[discretization]
springs = 1000000
"""


def cases(scenes, scratch):
    """name -> (kind, arguments after the subcommand), in the order they run."""
    out = {}
    driver_cycle = os.path.join(scratch, "driver_cycle.toml")
    with open(driver_cycle, "w") as f:
        f.write(DRIVER_CYCLE)
    for name in ("fig2_fixed_load", "fig2_fixed_grips", "sphere_fixed_load", "sphere_fixed_grips"):
        out[name] = ("run", [os.path.join(scenes, name + ".toml"), "--set", RTOL])
    cycle = os.path.join(scenes, "programs", "jkr_cycle_reversible.toml")
    for label, springs in (("1e6", 1_000_000), ("1e7", 10_000_000)):
        springs_set = ["--set", f"discretization.springs={springs}"]
        out["cycle_" + label] = ("run", [cycle, *springs_set])
        out["driver_cycle_" + label] = ("run", [driver_cycle, *springs_set])
    sweep = [os.path.join(scenes, "fig3a_fixed_grips.toml"), "--vary", SWEEP_VARY]
    for s in SWEEP_SETS:
        sweep += ["--set", s]
    for threads in (1, 2):
        out[f"sweep_{threads}_thread"] = ("sweep", sweep + ["--threads", str(threads)])
    return out


def children_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run_once(binary, kind, args, scratch):
    """(JSON wall_time_s or None, the process's wall time, its CPU time) of one run."""
    if kind == "run":
        out = os.path.join(scratch, "result.json")
        command = [binary, "run", *args, "--json", out, "--log-level", "error"]
    else:
        out = os.path.join(scratch, "sweep.csv")
        command = [binary, "sweep", *args, "--csv", out, "--log-level", "error"]
        if os.path.exists(out):
            os.remove(out)
    cpu = children_cpu()
    start = time.perf_counter()
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    process = time.perf_counter() - start
    cpu = children_cpu() - cpu
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed ({done.returncode}):\n{done.stderr}")
    if kind != "run":
        return None, process, cpu
    with open(out) as f:
        return json.load(f)["wall_time_s"], process, cpu


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--out", default="-")
    parser.add_argument("--cases", default="", help="comma-separated subset (default: all)")
    parser.add_argument("--scenes", default=os.path.join(ROOT, "scenes"))
    a = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        compare(a, cases(a.scenes, scratch), scratch)


def compare(a, all_cases, scratch):
    names = [n for n in a.cases.split(",") if n] or list(all_cases)
    unknown = [n for n in names if n not in all_cases]
    if unknown:
        sys.exit(f"unknown case(s) {unknown} (known: {', '.join(all_cases)})")
    binaries = {"old": os.path.abspath(a.old), "new": os.path.abspath(a.new)}
    sink = sys.stdout if a.out == "-" else open(a.out, "w", newline="")
    writer = csv.writer(sink)
    writer.writerow(["case", "binary", "repeat", "json_wall_s", "process_wall_s", "process_cpu_s"])
    times = {(n, b): [] for n in names for b in binaries}
    for repeat in range(a.repeats):
        for i, name in enumerate(names):
            kind, args = all_cases[name]
            order = ["old", "new"] if (repeat + i) % 2 == 0 else ["new", "old"]
            for b in order:
                json_wall, process, cpu = run_once(binaries[b], kind, args, scratch)
                writer.writerow([name, b, repeat, "" if json_wall is None else f"{json_wall:.6g}",
                                 f"{process:.6g}", f"{cpu:.6g}"])
                sink.flush()
                times[(name, b)].append(json_wall if json_wall is not None else process)
    if sink is not sys.stdout:
        sink.close()
    print(f"{'case':<20} {'old median s':>13} {'new median s':>13} {'old/new':>8}  "
          f"(JSON wall_time_s; a sweep's process time; {a.repeats} interleaved repeats)",
          file=sys.stderr)
    for name in names:
        old = statistics.median(times[(name, "old")])
        new = statistics.median(times[(name, "new")])
        print(f"{name:<20} {old:13.4g} {new:13.4g} {old / new:8.2f}", file=sys.stderr)
    for b in binaries:
        if (("sweep_1_thread", b) in times and ("sweep_2_thread", b) in times):
            one = statistics.median(times[("sweep_1_thread", b)])
            two = statistics.median(times[("sweep_2_thread", b)])
            print(f"sweep speedup 2 threads vs 1, {b}: {one / two:.2f}x", file=sys.stderr)


if __name__ == "__main__":
    main()

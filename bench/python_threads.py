#!/usr/bin/env python3
"""Two Python threads against one, as a user runs scenes: ThreadPoolExecutor.map(mdrsim.run,
...) over a batch of the same scene (scenes/fig2_fixed_load.toml at several spring counts),
with the default trajectory and without. Writes CSV (standard output, or the file given) with
a row per case, and MET/MISS lines on standard error for the target: 2 threads >= 1.8x one
thread for runs of a millisecond or more.

One and two threads alternate within each repeat and the best of `--repeats` is kept for each,
so that a load from elsewhere hits both alike; the same batch over two processes (no shared
GIL, no shared address space) is measured too: on a busy host it is the ceiling, and
`vs_processes` (threads' speedup / processes' speedup) says how much of it the threads get.

    PYTHONPATH=build-py/python /usr/bin/python3 bench/python_threads.py [out.csv]
"""

import argparse
import csv
import multiprocessing
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import mdrsim

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIG2 = os.path.join(ROOT, "scenes", "fig2_fixed_load.toml")
COLUMNS = ["springs", "trajectory", "runs", "run_ms", "one_thread_s", "two_threads_s",
           "threads_speedup", "one_process_s", "two_processes_s", "processes_speedup",
           "vs_processes"]


def scene_of(springs):
    return mdrsim.Scene.from_file(FIG2).with_values({"discretization.springs": springs})


def run_one(job):
    scene, trajectory = job
    return mdrsim.run(scene, trajectory=trajectory).wall_time_s


def _process_batch(args):
    springs, trajectory, runs = args
    scene = scene_of(springs)
    start = time.perf_counter()
    for _ in range(runs):
        mdrsim.run(scene, trajectory=trajectory)
    return time.perf_counter() - start


def case(springs, trajectory, runs, repeats, process_pool):
    scene = scene_of(springs)
    jobs = [(scene, trajectory)] * runs
    engine = min(run_one(jobs[0]) for _ in range(3))
    ones, twos, p_ones, p_twos = [], [], [], []
    with ThreadPoolExecutor(1) as one, ThreadPoolExecutor(2) as two:
        for _ in range(repeats):
            for pool, times in ((one, ones), (two, twos)):
                start = time.perf_counter()
                list(pool.map(run_one, jobs))
                times.append(time.perf_counter() - start)
            p_ones.append(process_pool.submit(_process_batch, (springs, trajectory, runs))
                          .result())
            p_twos.append(max(process_pool.map(_process_batch,
                                               [(springs, trajectory, runs // 2)] * 2)))
    one_s, two_s, p_one, p_two = min(ones), min(twos), min(p_ones), min(p_twos)
    return {"springs": springs, "trajectory": trajectory, "runs": runs,
            "run_ms": round(engine * 1e3, 3), "one_thread_s": round(one_s, 4),
            "two_threads_s": round(two_s, 4), "threads_speedup": round(one_s / two_s, 3),
            "one_process_s": round(p_one, 4), "two_processes_s": round(p_two, 4),
            "processes_speedup": round(p_one / p_two, 3),
            "vs_processes": round((one_s / two_s) / (p_one / p_two), 3)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", nargs="?", help="CSV file (default: standard output)")
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    cases = [(10_000, True, 24), (10_000, False, 96), (30_000, True, 24), (30_000, False, 48),
             (100_000, True, 12), (100_000, False, 24)]
    missed = []
    out = open(args.out, "w", newline="") if args.out else sys.stdout
    writer = csv.DictWriter(out, COLUMNS)
    writer.writeheader()
    with ProcessPoolExecutor(2, mp_context=multiprocessing.get_context("fork")) as processes:
        for springs, trajectory, runs in cases:
            row = case(springs, trajectory, runs, args.repeats, processes)
            writer.writerow(row)
            out.flush()
            if row["run_ms"] >= 1.0:
                met = row["threads_speedup"] >= 1.8
                line = (f"{'MET ' if met else 'MISS'} {springs} springs, trajectory="
                        f"{trajectory}: {row['run_ms']:.2f} ms per run, 2 threads "
                        f"{row['threads_speedup']:.2f}x (target >= 1.8x; two processes "
                        f"{row['processes_speedup']:.2f}x now)")
                print(line, file=sys.stderr)
                if not met:
                    missed.append(line)
    if args.out:
        out.close()
    return 1 if missed else 0


if __name__ == "__main__":
    sys.exit(main())

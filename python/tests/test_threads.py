"""The GIL is released while the engine runs: Python threads go on, and runs overlap."""

import threading
import time

import mdrsim

# About 30-60 ms of engine time: 1e6 springs at ~30-60 ns each.
LONG = mdrsim.Scene.from_file("scenes/fig2_fixed_load.toml").with_values(
    {"discretization.springs": 1_000_000})


def test_python_runs_while_the_engine_does():
    span = {}

    def worker():
        span["start"] = time.perf_counter()
        mdrsim.run(LONG, trajectory=False)
        span["end"] = time.perf_counter()

    ticks = []
    thread = threading.Thread(target=worker)
    thread.start()
    while thread.is_alive():
        ticks.append(time.perf_counter())
    thread.join()
    inside = [t for t in ticks if span["start"] < t < span["end"]]
    # With the GIL held through the run this thread could not tick inside it at all (the
    # interpreter switches threads every 5 ms only between bytecodes).
    assert span["end"] - span["start"] > 0.01
    assert len(inside) > 1000


def test_two_runs_overlap_in_time():
    spans = [None, None]
    barrier = threading.Barrier(2)

    def worker(i):
        barrier.wait()
        result = mdrsim.run(LONG, trajectory=False)
        end = time.perf_counter()
        spans[i] = (end - result.wall_time_s, end)  # when the engine itself ran

    threads = [threading.Thread(target=worker, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    overlap = min(spans[0][1], spans[1][1]) - max(spans[0][0], spans[1][0])
    shorter = min(end - start for start, end in spans)
    # Serialised by the GIL, the two runs could not overlap at all.
    assert overlap > 0.5 * shorter

"""Ctrl-C (SIGINT) stops mdrsim.run within milliseconds with KeyboardInterrupt."""

import os
import signal
import threading
import time

import pytest

import mdrsim

# About a second of engine time each on an idle machine, little memory without a trajectory.
LONG = {"scenes/fig2_fixed_load.toml": 20_000_000,
        "scenes/programs/jkr_cycle_glue_on_touch.toml": 10_000_000}


@pytest.mark.parametrize("path", sorted(LONG))
def test_sigint_stops_a_run(path):
    scene = mdrsim.Scene.from_file(path).with_values({"discretization.springs": LONG[path]})
    start = time.perf_counter()
    mdrsim.run(scene, trajectory=False)
    whole = time.perf_counter() - start
    sent = {}

    def interrupt():
        sent["at"] = time.perf_counter()
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(whole / 4, interrupt)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        mdrsim.run(scene, trajectory=False)
    late = time.perf_counter() - sent["at"]
    # Checked every 65536 events (a few ms at ~60 ns each). Without the check the interrupt
    # came when the run ended, 3/4 of the run later; a loaded machine slows both alike.
    assert late < whole / 4
    # The next run is not interrupted.
    assert mdrsim.run("scenes/fig2_fixed_load.toml", trajectory=False).status == "instability"

"""Ctrl-C (SIGINT) stops mdrsim.run within milliseconds with KeyboardInterrupt."""

import os
import signal
import threading
import time

import pytest

import mdrsim

# 1e8 springs: seconds of engine time (about 60 ns per event), little memory without a
# trajectory.
LONG = {"scenes/fig2_fixed_load.toml": 100_000_000,
        "scenes/programs/jkr_cycle_glue_on_touch.toml": 20_000_000}


@pytest.mark.parametrize("path", sorted(LONG))
def test_sigint_stops_a_run(path):
    scene = mdrsim.Scene.from_file(path).with_values({"discretization.springs": LONG[path]})
    sent = {}

    def interrupt():
        sent["at"] = time.perf_counter()
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(0.5, interrupt)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        mdrsim.run(scene, trajectory=False)
    late = time.perf_counter() - sent["at"]
    # Checked every 65536 events (a few ms), or after the rows' set-up for 1e8 springs; the
    # whole run takes seconds more, and the interrupt came only when it ended.
    assert late < 1.0
    # The next run is not interrupted.
    assert mdrsim.run("scenes/fig2_fixed_load.toml", trajectory=False).status == "instability"

"""mdrsim: adhesive contact under normal and tangential loading (MDR spring model), in Python.

    import mdrsim
    scene = mdrsim.Scene.from_file("scenes/fig2_fixed_load.toml")
    result = mdrsim.run(scene.with_values({"discretization.springs": 4000}))
    result.critical.normal_force, result.dimensionless["normal_force"]
    result.trajectory["normal_force"]          # NumPy, no copy
    rows = mdrsim.sweep(scene, {"loading.tangential.displacement": "0:9e-6:41"}).rows

Measured force curves (AFM files) read and fitted: mdrsim.afm (docs/afm.md).
Bad input raises mdrsim.SceneError (a ValueError) with the message `mdrsim run` prints.
mdrsim.run releases the GIL while the engine runs: threads run scenes in parallel.
"""

import numbers
import warnings

from . import _core, afm
from ._core import Material, SceneError, set_log_level
from ._parts import Parameter, parts, register_criterion, register_profile
from ._result import Jump, Result, StageEnd, State, Work
from ._scene import Scene, as_scene
from ._sweep import SweepResult, sweep

__version__ = "0.1.0"
__all__ = ["Jump", "Material", "Parameter", "Result", "RunWarning", "Scene", "SceneError",
           "StageEnd", "State", "SweepResult", "Work", "parts", "register_criterion",
           "register_profile", "run", "SAMPLES", "TRAJECTORY_ROWS", "set_log_level", "sweep"]


class RunWarning(UserWarning):
    """What a run cannot vouch for (too few springs at the critical point, rtol not met...);
    the same lines are in Result.warnings."""


#: The rows mdrsim.run(scene) keeps of the trajectory by default (about 7 MB).
TRAJECTORY_ROWS = 100_000


def _row_budget(trajectory):
    if trajectory is None or trajectory is False:
        return None
    if trajectory is True:
        return TRAJECTORY_ROWS
    if isinstance(trajectory, numbers.Integral) and trajectory >= 1:
        return int(trajectory)
    raise ValueError(f"trajectory={trajectory!r}: expected True, False or a number of rows >= 1")


#: The points of the continuum route's branch a trajectory holds by default (--samples).
SAMPLES = 1000


def _sample_count(samples, budget):
    if samples is None:
        return SAMPLES if budget is not None else 0
    if isinstance(samples, numbers.Integral) and not isinstance(samples, bool) and samples >= 0:
        return int(samples)
    raise ValueError(f"samples={samples!r}: expected a number of points >= 0")


def run(scene, trajectory=True, method=None, samples=None):
    """Runs a Scene (or a scene file path, or a dict) and returns its Result.

    method: None runs the scene as it is; "event", "stepping" or "continuum" runs
    scene.with_method(method) (the continuum route: no springs, to rtol, default 1e-10; see
    docs/continuum.md). A Scene made once with with_method saves the build on every run.
    samples: on the continuum route, the points of the followed branch in the trajectory,
    evenly in the contact radius (`sample` rows; default SAMPLES = 1000 with a trajectory,
    as `mdrsim run --samples`); ignored on the spring rows.

    trajectory: the rows of Result.trajectory to keep at most (True: TRAJECTORY_ROWS,
    100,000; an int: that many; False: none, Result.trajectory is then None). A longer run
    keeps every row of the preload, the tangential load, each stage end and the instability,
    and the first and last row; the rows on either side of a cascade and the jump rows while
    they fit; and of the ordinary rows (detached, glued, step ...) every k-th, k a power of two
    (Result.trajectory_stride), so that memory stays within the budget however many springs
    the run has.

    The GIL is released while the engine runs; criteria and profiles written in Python take
    it back for each call, so they run one thread at a time. Ctrl-C stops the run
    (KeyboardInterrupt) within milliseconds.
    """
    scene = as_scene(scene, "run")
    if method is not None:
        scene = scene.with_method(method)
    budget = _row_budget(trajectory)
    raw = _core.run(scene._doc, budget, _sample_count(samples, budget))
    if raw.has_warnings:
        for line in raw.warnings:
            warnings.warn(line, RunWarning, stacklevel=2)
    return Result(raw)

"""mdrsim: adhesive contact under normal and tangential loading (MDR spring model), in Python.

    import mdrsim
    scene = mdrsim.Scene.from_file("scenes/fig2_fixed_load.toml")
    result = mdrsim.run(scene.with_values({"discretization.springs": 4000}))
    result.critical.normal_force, result.dimensionless["normal_force"]
    result.trajectory["normal_force"]          # NumPy, no copy
    rows = mdrsim.sweep(scene, {"loading.tangential.displacement": "0:9e-6:41"}).rows

Bad input raises mdrsim.SceneError (a ValueError) with the message `mdrsim run` prints.
mdrsim.run releases the GIL while the engine runs: threads run scenes in parallel.
"""

import warnings

from . import _core
from ._core import Material, SceneError, set_log_level
from ._parts import Parameter, parts, register_criterion, register_profile
from ._result import Jump, Result, StageEnd, State, Work
from ._scene import Scene, as_scene
from ._sweep import SweepResult, sweep

__version__ = "0.1.0"
__all__ = ["Jump", "Material", "Parameter", "Result", "RunWarning", "Scene", "SceneError",
           "StageEnd", "State", "SweepResult", "Work", "parts", "register_criterion",
           "register_profile", "run", "set_log_level", "sweep"]


class RunWarning(UserWarning):
    """What a run cannot vouch for (too few springs at the critical point, rtol not met...);
    the same lines are in Result.warnings."""


def run(scene, trajectory=True):
    """Runs a Scene (or a scene file path, or a dict) and returns its Result.

    trajectory=False keeps no per-event rows (Result.trajectory is then None). The GIL is
    released while the engine runs; criteria and profiles written in Python take it back
    for each call, so they run one thread at a time.
    """
    scene = as_scene(scene, "run")
    raw = _core.run(scene._doc, trajectory)
    if raw.has_warnings:
        for line in raw.warnings:
            warnings.warn(line, RunWarning, stacklevel=2)
    return Result(raw)

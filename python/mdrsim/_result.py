"""The result of a run: status, critical point, stages, jumps, work and the trajectory."""

import json
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from . import _core

# The dimensionless fields (docs, paper eq. 16) and the JKR scale each is divided by: the
# engine's list (engine/model/snapshot_fields.hpp), as the JSON's `dimensionless` has them.
_SCALED = _core.SNAPSHOT_FIELDS


@dataclass(frozen=True)
class State:
    """An equilibrium of the contact in SI units; `dimensionless` has F/F0, a/a0, d/d0 and
    ux/d0 where the scales exist (parabolic and sphere profiles: eq. 17; cone, power law with
    n > 1/2 and flat punch: their fixed-load pull-off), else None."""

    normal_force: float  # F [N], negative when adhesion holds the indenter
    tangential_force: float  # Fx [N]
    contact_radius: float  # a [m]
    indentation: float  # d [m]
    tangential_displacement: float  # ux [m]
    springs_in_contact: int
    normal_control: float  # the value the normal controller holds [m or N]
    dimensionless: dict = None
    disk_valid: bool = True  # the state is one contact disk (docs/model.md "One contact disk")
    # With [friction] (docs/friction.md), else None: the springs of one half sliding, and the
    # radius inside which every spring in contact sticks (the contact radius when none slides).
    springs_sliding: int = None
    stick_radius: float = None  # [m]
    # With adhesive_stress or maugis_parameter (docs/maugis.md), else None: the outer radius of
    # the cohesive zone, out to which the Dugdale stress pulls [m].
    cohesive_radius: float = None
    # In a timed program (every stage has duration or speed: docs/programs.md "Time"), else
    # None: the time since the program started [s].
    time: float = None

    @classmethod
    def _of(cls, snapshot, scales):
        if snapshot is None:
            return None
        scaled = None if scales is None else {
            name: snapshot[name] / scales[scale] for name, scale in _SCALED}
        return cls(dimensionless=scaled, **snapshot)


@dataclass(frozen=True)
class Work:
    """Work done by the machine on each axis [J] and the parts of it dissipated, each where the
    scene has its cause (as the JSON's `work` names it), else None: with [friction],
    `dissipated_by_friction` (the slip limit times each slip distance, summed: part of
    `tangential`); with detachment.front_speed_law, `dissipated_at_front` (int (G - dgamma) 2 pi
    a |da|, docs/rate_law.md); with material.relaxation, `dissipated_by_bulk` (what the
    dashpots dissipated, docs/viscoelastic.md)."""

    normal: float
    tangential: float
    dissipated_by_friction: float = None
    dissipated_at_front: float = None
    dissipated_by_bulk: float = None


@dataclass(frozen=True)
class StageEnd:
    """A stage's end state and work; in a timed program its start and end time [s], else
    None."""

    name: str
    end: State
    work: Work
    start_time: float = None
    end_time: float = None


@dataclass(frozen=True)
class Jump:
    """A cascade at one value of a stage's parameter: `kind` "in" or "out", from the last
    equilibrium before it (`critical`) to the one after it; `after` is None where a fixed
    load lost what held it and the indenter separated or slid away, or (the shorthand only)
    where the glue let go under a held compression, which the shorthand does not follow."""

    stage: str
    kind: str
    critical: State
    after: State
    springs: int
    glued_springs: int
    by_shear: bool


# What a pickled Result keeps of the engine's result (the attributes of _core.RunResult).
_RAW_FIELDS = ("status", "stop_reason", "title", "critical", "peak", "tangential_strength", "stages", "jumps",
               "work", "sliding", "warnings", "has_warnings", "disk_valid", "counts", "springs",
               "wall_time_s", "scales", "maugis_parameter", "trajectory_rows_seen",
               "trajectory_stride")


class _StoredRun:
    """A run's values without the engine: what a Result unpickles to, in any process (a
    ProcessPoolExecutor's), whether or not the parts its scene used are registered there."""

    def __init__(self, values, json_text, trajectory):
        self.__dict__.update(values)
        self._json = json_text
        self._trajectory = trajectory
        if trajectory is not None:  # read-only, as the engine's own buffers are
            for value in trajectory.values():
                if hasattr(value, "flags"):
                    value.flags.writeable = False

    def json(self):
        return self._json

    def trajectory(self):
        return self._trajectory


def _result_from_values(values, json_text, trajectory):
    return Result(_StoredRun(values, json_text, trajectory))


class Result:
    """What mdrsim.run returns. Every attribute is computed on first access. Picklable (with
    its trajectory), so that ProcessPoolExecutor().map(mdrsim.run, scenes) works."""

    def __init__(self, raw):
        self._raw = raw

    def __reduce__(self):
        values = {name: getattr(self._raw, name) for name in _RAW_FIELDS}
        return (_result_from_values, (values, self._raw.json(), self._raw.trajectory()))

    @property
    def status(self):
        """instability, shear-off, no-instability, step-limit or completed (docs)."""
        return self._raw.status

    @property
    def stop_reason(self):
        """Why a step-limit run stopped (max-steps, max-events, max-events-per-spring,
        outgrew-row, no-end, overflow, unending-cascade: docs/outputs.md); None for any other
        status."""
        return self._raw.stop_reason

    @property
    def title(self):
        """The scene's title ("" without one)."""
        return self._raw.title

    @cached_property
    def scales(self):
        """The scales {"force": F0 [N], "radius": a0 [m], "depth": d0 [m], "basis": the closed
        form}, or None."""
        return self._raw.scales

    @cached_property
    def critical(self):
        """The last equilibrium before the contact was lost (a State), or None."""
        return State._of(self._raw.critical, self.scales)

    @property
    def dimensionless(self):
        """The critical point's dimensionless values (the JSON's `dimensionless`), with Maugis'
        lambda as `maugis_parameter` for a parabolic or spherical tip with finite-range
        adhesion; or None."""
        values = None if self.critical is None else self.critical.dimensionless
        if self.maugis_parameter is None:
            return values
        return {**(values or {}), "maugis_parameter": self.maugis_parameter}

    @property
    def maugis_parameter(self):
        """Maugis' lambda of a parabolic or spherical tip with finite-range adhesion
        (docs/maugis.md), else None."""
        return self._raw.maugis_parameter

    @cached_property
    def peak(self):
        """The most tensile equilibrium up to the critical point (`peak_adhesion`), or None."""
        return State._of(self._raw.peak, self.scales)

    @property
    def tangential_strength(self):
        """A shear-off as the tangential load is applied: the largest Fx [N]; else None."""
        return self._raw.tangential_strength

    @cached_property
    def stages(self):
        return [StageEnd(s["name"], State._of(s["end"], self.scales), Work(**s["work"]),
                         s.get("start_time"), s.get("end_time"))
                for s in self._raw.stages]

    @cached_property
    def jumps(self):
        return [Jump(j["stage"], j["kind"], State._of(j["critical"], self.scales),
                     State._of(j["after"], self.scales), j["springs"], j["glued_springs"],
                     j["by_shear"]) for j in self._raw.jumps]

    @cached_property
    def work(self):
        """The total work (a Work), or None where the run did not follow the whole path."""
        w = self._raw.work
        return None if w is None else Work(**w)

    @property
    def sliding(self):
        """True where the run ended with a held Fx that nothing held any more, so that the
        indenter slides away: with [friction], every spring in contact sliding (status
        shear-off, docs/friction.md "Statuses"); without it, the glue gone (the JSON's
        top-level "sliding")."""
        return self._raw.sliding

    @property
    def dissipated_by_friction(self):
        """The work friction dissipated over the whole run [J] (work.dissipated_by_friction;
        each stage's is stages[i].work.dissipated_by_friction); None without [friction] or
        where the run did not follow the whole path."""
        w = self.work
        return None if w is None else w.dissipated_by_friction

    @property
    def dissipated_at_front(self):
        """The work the rate law's receding front dissipated over the whole run [J]
        (work.dissipated_at_front; each stage's is stages[i].work.dissipated_at_front); None
        without detachment.front_speed_law or where the run did not follow the whole path."""
        w = self.work
        return None if w is None else w.dissipated_at_front

    @property
    def dissipated_by_bulk(self):
        """The work a relaxing bulk's dashpots dissipated over the whole run [J]
        (work.dissipated_by_bulk; each stage's is stages[i].work.dissipated_by_bulk); None
        without material.relaxation or where the run did not follow the whole path."""
        w = self.work
        return None if w is None else w.dissipated_by_bulk

    @cached_property
    def warnings(self):
        return self._raw.warnings

    @property
    def disk_valid(self):
        """Whether every reported state is one contact disk, as the MDR needs (the JSON's
        `disk_valid`; each State has its own)."""
        return self._raw.disk_valid

    @cached_property
    def accuracy(self):
        """What the run vouches for (the JSON's `accuracy`, docs/accuracy.md): route, rows,
        the error estimates [N, J] and `covers`; None for a plain row, which estimates
        nothing."""
        return json.loads(self._raw.json()).get("accuracy")

    @cached_property
    def counts(self):
        """{"events", "steps", "halvings", "root_iterations"}."""
        return self._raw.counts

    @property
    def springs(self):
        """The springs of the finest row run (one half of the foundation)."""
        return self._raw.springs

    @property
    def wall_time_s(self):
        """The engine's own time for the run [s]."""
        return self._raw.wall_time_s

    @property
    def trajectory(self):
        """One row per event, as `mdrsim run --trajectory` writes them: a dict of NumPy
        arrays (read-only views of the engine's own buffers, no copy), and the lists
        "stage" and "event"; None for mdrsim.run(scene, trajectory=False). Within the row
        budget of mdrsim.run (trajectory_stride > 1 when rows were thinned). As the CSV's
        columns: "sliding" with friction, "cohesive_radius" [m] with finite-range adhesion."""
        return self._raw.trajectory()

    def curve(self, stage=None):
        """The trajectory's rows of one stage (all rows for stage=None), as a dict of NumPy
        arrays and the lists "stage" and "event", like Result.trajectory.

        A stage's own rows begin at its first event; the state it starts from is the previous
        stage's last row (its `stage-end`). curve(stage=...) puts that row first, unchanged
        (its "stage" still names the stage it ended), so that the curve holds the whole path
        of the stage: a retract that starts pinned (no spring lets go until the front's
        criterion is met) has no event along the pinned part, and without its starting state
        its curve would begin at the first let-go, the pinned unloading missing. The first
        stage starts from the untouched state, which has no row. Raises KeyError for a stage
        the run has no row of, ValueError without a trajectory."""
        trajectory = self.trajectory
        if trajectory is None:
            raise ValueError("the run kept no trajectory: use mdrsim.run(scene, trajectory=True)")
        stages = trajectory["stage"]
        if stage is None:
            rows = np.arange(len(stages))
        else:
            rows = np.flatnonzero(np.fromiter((s == stage for s in stages), bool, len(stages)))
            if rows.size == 0:
                known = ", ".join(dict.fromkeys(stages)) or "none"
                raise KeyError(f"stage {stage!r}: no rows (the trajectory's stages: {known})")
            if rows[0] > 0:
                rows = np.r_[rows[0] - 1, rows]
        return {key: ([value[i] for i in rows] if isinstance(value, list) else value[rows])
                for key, value in trajectory.items()}

    @property
    def trajectory_rows_seen(self):
        """The rows the run gave (0 without a trajectory); more than len(trajectory["event"])
        when the budget thinned them."""
        return self._raw.trajectory_rows_seen

    @property
    def trajectory_stride(self):
        """1 when the trajectory holds every row; else every k-th ordinary row is held."""
        return self._raw.trajectory_stride

    def to_dict(self):
        """The JSON of `mdrsim run --json`, as Python objects."""
        return json.loads(self._raw.json())

    def to_dataframe(self):
        """The trajectory as a pandas DataFrame (pandas is optional)."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError("Result.to_dataframe needs pandas, which is not installed "
                              "(Debian: apt-get install python3-pandas)") from e
        trajectory = self.trajectory
        if trajectory is None:
            raise ValueError("the run kept no trajectory: use mdrsim.run(scene, trajectory=True)")
        return pandas.DataFrame(trajectory)

    def plot(self, ax=None, view="normal"):
        """The force-displacement path with its jumps dashed and the critical point marked:
        view "normal" draws F against d, "tangential" F_x against u_x (F/F0 against d/d0 where
        the scene has scales). Needs matplotlib; returns the Axes."""
        from ._plot import plot_result
        return plot_result(self, ax, view)

    def __repr__(self):
        critical = "" if self.critical is None else f", F={self.critical.normal_force:.6g} N"
        return f"<mdrsim.Result {self.status}{critical}, {self.springs} springs>"

# Type stubs of the package mdrsim (PEP 561: py.typed beside them): the public API of __init__.py.
import os
from collections.abc import Callable, Mapping, Sequence
from concurrent.futures import Executor
from typing import Any, Literal, TypedDict, Union, overload

from typing_extensions import NotRequired

import numpy as np
import numpy.typing as npt

import mdrsim.afm as afm  # the submodule, loaded with the package (afm.pyi)

__version__: str
TRAJECTORY_ROWS: int
SAMPLES: int

SceneValue = Union[bool, int, float, str, Sequence[Any], npt.NDArray[Any], Mapping[str, Any]]
ScenePath = Union[str, os.PathLike[str]]
Status = Literal["instability", "shear-off", "no-instability", "step-limit", "completed"]
StopReason = Literal["max-steps", "max-events", "max-events-per-spring", "outgrew-row", "no-end",
                     "overflow", "unending-cascade"]
Method = Literal["event", "stepping", "continuum"]

class SceneError(ValueError): ...
class RunWarning(UserWarning): ...

class Material:
    @property
    def effective_modulus(self) -> float: ...
    @property
    def effective_shear_modulus(self) -> float: ...
    @property
    def work_of_adhesion(self) -> float: ...
    @property
    def approach_work_of_adhesion(self) -> float: ...
    @overload
    def work_of_adhesion_at(self, r: float) -> float: ...
    @overload
    def work_of_adhesion_at(self, r: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
    @overload
    def approach_work_of_adhesion_at(self, r: float) -> float: ...
    @overload
    def approach_work_of_adhesion_at(self, r: npt.ArrayLike) -> npt.NDArray[np.float64]: ...

class Scene:
    @classmethod
    def from_file(cls, path: ScenePath) -> Scene: ...
    @classmethod
    def from_toml(cls, text: Union[str, bytes], name: str = ..., base_dir: ScenePath = ...) -> Scene: ...
    @classmethod
    def from_dict(cls, table: Mapping[str, Any], name: str = ..., base_dir: ScenePath = ...) -> Scene: ...
    def with_values(self, values: Mapping[str, SceneValue]) -> Scene: ...
    def set(self, key: str, value: SceneValue) -> Scene: ...
    def with_method(self, method: Method, rtol: float | None = ...) -> Scene: ...
    def to_dict(self) -> dict[str, Any]: ...
    def to_toml(self) -> str: ...
    def save(self, path: ScenePath) -> None: ...
    @property
    def source(self) -> str: ...
    @property
    def overrides(self) -> tuple[tuple[str, str], ...]: ...
    @property
    def title(self) -> str: ...
    @property
    def springs(self) -> int: ...
    @property
    def method(self) -> Method: ...
    @property
    def material(self) -> Material: ...
    @property
    def profile(self) -> str: ...
    @property
    def criterion(self) -> str: ...
    @property
    def control(self) -> tuple[str, str]: ...

class State:
    normal_force: float
    tangential_force: float
    contact_radius: float
    indentation: float
    tangential_displacement: float
    springs_in_contact: int
    normal_control: float
    dimensionless: dict[str, float] | None
    disk_valid: bool
    springs_sliding: int | None
    stick_radius: float | None
    cohesive_radius: float | None
    time: float | None  # [s] in a timed program (every stage has duration or speed), else None

class Work:
    normal: float
    tangential: float
    dissipated_by_friction: float | None  # with [friction], else None
    dissipated_at_front: float | None  # with detachment.front_speed_law, else None
    dissipated_by_bulk: float | None  # with material.relaxation, else None

class StageEnd:
    name: str
    end: State
    work: Work
    start_time: float | None  # [s] in a timed program, else None
    end_time: float | None

class Jump:
    stage: str
    kind: Literal["in", "out"]
    critical: State
    after: State | None  # None where the indenter separated, slid away or stayed pressed in
    springs: int
    glued_springs: int
    by_shear: bool

class Trajectory(TypedDict):
    stage: list[str]
    event: list[str]
    in_cascade: npt.NDArray[np.bool_]
    indentation: npt.NDArray[np.float64]
    normal_force: npt.NDArray[np.float64]
    contact_radius: npt.NDArray[np.float64]
    tangential_displacement: npt.NDArray[np.float64]
    tangential_force: npt.NDArray[np.float64]
    springs_in_contact: npt.NDArray[np.int64]
    normal_control: npt.NDArray[np.float64]
    sliding: NotRequired[npt.NDArray[np.int64]]  # with [friction] only, as the CSV's column
    time: NotRequired[npt.NDArray[np.float64]]  # in a timed program only [s]

class Result:
    @property
    def status(self) -> Status: ...
    @property
    def stop_reason(self) -> StopReason | None: ...
    @property
    def title(self) -> str: ...
    @property
    def scales(self) -> dict[str, Any] | None: ...
    @property
    def critical(self) -> State | None: ...
    @property
    def dimensionless(self) -> dict[str, float] | None: ...
    @property
    def maugis_parameter(self) -> float | None: ...
    @property
    def peak(self) -> State | None: ...
    @property
    def tangential_strength(self) -> float | None: ...
    @property
    def stages(self) -> list[StageEnd]: ...
    @property
    def jumps(self) -> list[Jump]: ...
    @property
    def work(self) -> Work | None: ...
    @property
    def sliding(self) -> bool: ...
    @property
    def dissipated_by_friction(self) -> float | None: ...
    @property
    def dissipated_at_front(self) -> float | None: ...
    @property
    def dissipated_by_bulk(self) -> float | None: ...
    @property
    def warnings(self) -> list[str]: ...
    @property
    def disk_valid(self) -> bool: ...
    @property
    def accuracy(self) -> dict[str, Any] | None: ...
    @property
    def counts(self) -> dict[str, int]: ...
    @property
    def springs(self) -> int: ...
    @property
    def wall_time_s(self) -> float: ...
    @property
    def trajectory(self) -> Trajectory | None: ...
    def curve(self, stage: str | None = ...) -> Trajectory: ...
    @property
    def trajectory_rows_seen(self) -> int: ...
    @property
    def trajectory_stride(self) -> int: ...
    def to_dict(self) -> dict[str, Any]: ...
    def to_dataframe(self) -> Any: ...  # pandas.DataFrame
    # Returns the matplotlib Axes.
    def plot(self, ax: Any = ..., view: Literal["normal", "tangential"] = ...) -> Any: ...

class SweepResult:
    @property
    def identity(self) -> str: ...
    @property
    def columns(self) -> list[str]: ...
    @property
    def rows(self) -> list[dict[str, float | int | bool | str | None]]: ...
    def to_csv(self, path: ScenePath | None = ...) -> str | None: ...
    def to_dataframe(self) -> Any: ...
    def __len__(self) -> int: ...

class Parameter:
    help: str
    default: float | None
    required: bool | None
    above: float | None
    at_least: float | None
    below: float | None
    at_most: float | None
    kind: Literal["number", "integer", "number_list", "text", "path"]
    def __init__(self, help: str = ..., default: float | None = ..., required: bool | None = ...,
                 above: float | None = ..., at_least: float | None = ...,
                 below: float | None = ..., at_most: float | None = ...,
                 kind: Literal["number", "integer", "number_list", "text", "path"] = ...) -> None: ...

SceneLike = Union[Scene, ScenePath, Mapping[str, Any]]
Parameters = Union[Mapping[str, Union[Parameter, float, None]], Sequence[str], None]

def run(scene: SceneLike, trajectory: Union[bool, int] = ..., method: Method | None = ...,
        samples: int | None = ...) -> Result: ...
def sweep(scene: SceneLike, grid: Mapping[str | tuple[str, ...], Any],
          executor: Executor | None = ..., batch_seconds: float = ...,
          method: Method | None = ..., *, where: str | Sequence[str] | None = ...,
          design: Literal["grid", "random", "latin"] | None = ..., samples: int | None = ...,
          seed: int | None = ...) -> SweepResult: ...
def parts() -> dict[str, dict[str, str]]: ...
def register_criterion(name: str, margin: Callable[..., float], *,
                       critical_elongation: Callable[..., float | None] | None = ...,
                       parameters: Parameters = ..., summary: str = ...) -> None: ...
def register_profile(name: str, shape: Callable[..., float],
                     image: Callable[..., float] | None = ..., *, parameters: Parameters = ...,
                     tip_radius: Union[float, str, Callable[..., float | None], None] = ...,
                     summary: str = ...) -> None: ...
def set_log_level(level: Literal["trace", "debug", "info", "warn", "error", "off"]) -> None: ...

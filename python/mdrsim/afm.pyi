# Type stubs of mdrsim.afm: measured force curves read and fitted (afm.py).
import os
from typing import Any, Iterable, Literal, Union

import numpy as np
import numpy.typing as npt

from mdrsim import SceneError as SceneError

Array = npt.NDArray[np.float64]
SegmentKind = Literal["approach", "retract", "pause"]
FitStatus = Literal["fitted", "no-contact", "not-converged", "unreadable"]

class Calibrated:
    value: float
    source: str
    def __init__(self, value: float, source: str) -> None: ...

class MapPosition:
    x: float
    y: float
    index: int
    def __init__(self, x: float, y: float, index: int) -> None: ...

class Segment:
    name: str
    kind: SegmentKind
    time: Array | None
    piezo_height: Array | None
    measured_height: Array | None
    deflection: Array | None
    tip_position: Array | None
    force: Array | None
    def __len__(self) -> int: ...

class Curve:
    file: str
    format: str
    label: str
    unreadable: str
    segments: list[Segment]
    calibration: dict[str, Calibrated | None]
    position: MapPosition | None
    @property
    def segment_names(self) -> list[str]: ...
    def segment(self, kind: SegmentKind) -> Segment: ...
    @property
    def spring_constant(self) -> float | None: ...
    @property
    def sensitivity(self) -> float | None: ...

class FitParameter:
    value: float | None
    standard_error: float | None
    fixed: bool
    def __init__(self, value: float | None, standard_error: float | None, fixed: bool) -> None: ...

class Fit:
    # The fields of `mdrsim fit --json` (to_dict()); work_of_adhesion, adhesion_force and
    # contact_samples for the adhesive models only, maugis_parameter for maugis and auto, auto
    # ({"picked", "reason"}) for auto, position for a curve of a map.
    file: str
    curve: str
    position: dict[str, float]
    status: FitStatus
    model: Literal["hertz", "dmt", "jkr", "maugis", "auto"]
    tip: str
    segment: Literal["approach", "retract"]
    poisson_ratio: float
    youngs_modulus: FitParameter
    work_of_adhesion: FitParameter
    contact_point: FitParameter
    baseline_offset: FitParameter
    baseline_slope: FitParameter
    residual_rms: float | None
    max_indentation: float | None
    adhesion_force: dict[str, float | None]
    contact_samples: int
    points: int
    iterations: int
    warnings: list[str]
    tip_position_from: str
    calibration: dict[str, dict[str, Any] | None]
    tip_position: Array | None
    force: Array | None
    fitted_force: Array | None
    @property
    def message(self) -> str: ...
    @property
    def indentation(self) -> Array | None: ...
    def to_dict(self) -> dict[str, Any]: ...
    # Returns the matplotlib Axes.
    def plot(self, ax: Any = ...) -> Any: ...

def load(path: Union[str, os.PathLike[str]], sensitivity: float | None = ...,
         spring_constant: float | None = ...) -> list[Curve]: ...
def fit(curve: Curve, model: Literal["hertz", "dmt", "jkr", "maugis", "auto"] = ..., tip: str = ...,
        poisson_ratio: float = ..., segment: Literal["approach", "retract"] = ...,
        fix: dict[str, float] | None = ...) -> Fit: ...
def fit_files(paths: Iterable[Union[str, os.PathLike[str]]], executor: Any = ...,
              sensitivity: float | None = ..., spring_constant: float | None = ...,
              model: Literal["hertz", "dmt", "jkr", "maugis", "auto"] = ..., tip: str = ...,
              poisson_ratio: float = ..., segment: Literal["approach", "retract"] = ...,
              fix: dict[str, float] | None = ...) -> list[dict[str, Any]]: ...

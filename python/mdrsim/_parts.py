"""Detachment criteria and profiles written in Python, registered by one call each."""

import numbers
from collections.abc import Mapping
from dataclasses import dataclass

from . import _core

_KINDS = ("number", "integer", "number_list", "text", "path")


@dataclass(frozen=True)
class Parameter:
    """A key a registered part reads from its scene table, checked like a built-in part's
    (messages with file:line:col). Bounds: `above`/`at_least` and `below`/`at_most`."""

    help: str = ""
    default: float = None
    required: bool = None  # default: required unless a default is given
    above: float = None
    at_least: float = None
    below: float = None
    at_most: float = None
    kind: str = "number"  # number, integer, number_list, text or path

    def _spec(self, key):
        if self.kind not in _KINDS:
            raise ValueError(f"parameter {key!r}: unknown kind {self.kind!r} (known: {', '.join(_KINDS)})")
        if self.above is not None and self.at_least is not None:
            raise ValueError(f"parameter {key!r}: give above or at_least, not both")
        if self.below is not None and self.at_most is not None:
            raise ValueError(f"parameter {key!r}: give below or at_most, not both")
        lower = ((float(self.above), False) if self.above is not None else
                 (float(self.at_least), True) if self.at_least is not None else None)
        upper = ((float(self.below), False) if self.below is not None else
                 (float(self.at_most), True) if self.at_most is not None else None)
        required = self.default is None if self.required is None else bool(self.required)
        default = None if self.default is None else float(self.default)
        return (key, self.kind, self.help, required, default, lower, upper)


def _specs(parameters):
    """{key: Parameter | default number | None (a required number)} or [key, ...]."""
    if parameters is None:
        return []
    if not isinstance(parameters, Mapping):
        parameters = {key: None for key in parameters}
    specs = []
    for key, p in parameters.items():
        if p is None:
            p = Parameter()
        elif isinstance(p, numbers.Real) and not isinstance(p, bool):
            p = Parameter(default=p)
        elif not isinstance(p, Parameter):
            raise TypeError(f"parameter {key!r}: expected a Parameter, a default number or None")
        specs.append(p._spec(key))
    return specs


def register_criterion(name, margin, *, critical_elongation=None, parameters=None, summary=""):
    """Registers a detachment criterion usable as `[detachment] criterion = NAME`.

    margin(elongation, tangential_displacement, contact_radius, material, **parameters)
    returns a float: > 0 while the boundary spring holds, <= 0 when it lets go; continuous
    and non-increasing in the elongation (-u_z >= 0) [m]. tangential_displacement is u_x [m],
    contact_radius a [m], material an mdrsim.Material (E*, G*, dgamma; where the scene's
    dgamma varies with the radius, material.work_of_adhesion_at(contact_radius)). Without
    critical_elongation the engine root-finds the let-go on margin.
    critical_elongation(contact_radius, tangential_displacement, material, **parameters),
    optional, returns the closed-form smallest elongation [m] with margin <= 0 (None: root-find).
    parameters: {key: Parameter(...) | default | None}, read from the [detachment] table and
    passed as keyword arguments. Registering a name again replaces the part; built-in names
    are refused. A scene built before keeps the part it was built with.
    """
    _check_callable("margin", margin)
    if critical_elongation is not None:
        _check_callable("critical_elongation", critical_elongation)
    _core.register_criterion(name, summary, _specs(parameters), margin, critical_elongation)


def register_profile(name, shape, image=None, *, parameters=None, tip_radius=None, summary=""):
    """Registers an indenter profile usable as `[profile] type = NAME`.

    shape(r, **parameters) returns f(r) [m] at r >= 0 [m]; image(x, **parameters), optional,
    the MDR image g(x) [m] (paper eq. 4), non-decreasing. Without image, g is computed from f
    by eq. 4 (tanh-sinh over a numerical f', thousands of calls of shape) at a few knots per
    octave of x, the first time the octave is needed, and interpolated (log g over log x, to
    1e-11 relative; an octave where that fails keeps eq. 4 at every call): a scene of 2000
    springs builds in 0.2 s instead of 4 minutes. The tables are kept for the last 8
    parameter sets, so that a sweep builds them once.
    tip_radius, optional, makes the dimensionless output (F/F0, ...) available: the radius R
    of a tip that is the parabola r^2/(2R), as a number, the name of a parameter, or a
    callable(**parameters).
    """
    _check_callable("shape", shape)
    if image is not None:
        _check_callable("image", image)
    if tip_radius is None or callable(tip_radius):
        tip = tip_radius
    elif isinstance(tip_radius, str):
        key = tip_radius
        tip = lambda **p: p[key]  # noqa: E731
    else:
        value = float(tip_radius)
        tip = lambda **p: value  # noqa: E731
    _core.register_profile(name, summary, _specs(parameters), shape, image, tip)


def _check_callable(what, fn):
    if not callable(fn):
        raise TypeError(f"{what} must be callable, got {type(fn).__name__}")


def parts():
    """The registered part names and summaries: {"profiles": {...}, "criteria": {...},
    "controllers": {...}}, built-in and Python ones."""
    return _core.parts()

"""Scenes from a TOML file, TOML text or a nested dict, checked as soon as they are made."""

import json
import math
import numbers
import os
import re
from collections.abc import Mapping

try:
    import tomllib  # Python 3.11
except ImportError:  # pragma: no cover
    tomllib = None

from . import _core
from ._core import SceneError

# The tables of a scene in the order docs/scene.md and the scene files have them.
_ORDER = ("title", "material", "profile", "loading", "detachment", "friction", "discretization",
          "solver")
_METHODS = ("event", "stepping", "continuum")
_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+\Z")
_ESCAPES = {'"': '\\"', "\\": "\\\\", "\b": "\\b", "\t": "\\t", "\n": "\\n", "\f": "\\f", "\r": "\\r"}


def _string(text):
    out = []
    for c in text:
        if c in _ESCAPES:
            out.append(_ESCAPES[c])
        elif ord(c) < 0x20 or ord(c) == 0x7F:
            out.append("\\u%04x" % ord(c))
        else:
            out.append(c)
    return '"' + "".join(out) + '"'


def _key(key, where):
    if not isinstance(key, str):
        raise SceneError(f"{where}: the key {key!r} is not a string")
    return key if _BARE_KEY.match(key) else _string(key)


def _is_table_array(value):
    return isinstance(value, (list, tuple)) and len(value) > 0 and all(
        isinstance(v, Mapping) for v in value)


def toml_value(value, where):
    """One value as TOML text on one line: what `--set KEY=VALUE` takes as VALUE."""
    if hasattr(value, "dtype") and getattr(value, "ndim", None) == 0:
        value = value.item()  # a NumPy scalar
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        x = float(value)
        return repr(x) if math.isfinite(x) else ("nan" if x != x else ("inf" if x > 0 else "-inf"))
    if isinstance(value, str):
        return _string(value)
    if isinstance(value, Mapping):
        items = ", ".join(f"{_key(k, where)} = {toml_value(v, f'{where}.{k}')}"
                          for k, v in value.items())
        return "{ " + items + " }" if items else "{}"
    if hasattr(value, "tolist"):  # a NumPy array (a pandas Series)
        value = _array_value(value, where)
        if isinstance(value, str):
            return value
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(v, where) for v in value) + "]"
    raise SceneError(f"{where}: {type(value).__name__} {value!r:.40} is not a scene value "
                     "(expected a number, string, boolean, list or table)")


def _array_value(array, where):
    """A NumPy array as a TOML array's text (1-D of floats or integers: every element as
    its exact double, non-finite ones as nan/inf for the engine to refuse by index), or its
    elements as a list for toml_value; more than one dimension is refused here: no scene key
    takes an array of arrays."""
    ndim, dtype = getattr(array, "ndim", 1), getattr(array, "dtype", None)
    if ndim > 1:
        raise SceneError(f"{where}: a {ndim}-D array of shape {tuple(array.shape)} is not a "
                         "scene value (expected a 1-D array)")
    kind, size = getattr(dtype, "kind", ""), getattr(dtype, "itemsize", 0)
    if ndim == 1 and kind in ("i", "u"):
        return "[" + ", ".join(map(str, array.tolist())) + "]"
    if ndim == 1 and kind == "f" and size <= 8:
        # repr of a float is what toml_value writes: the shortest text of the same double,
        # and nan, inf and -inf as TOML spells them.
        return "[" + ", ".join(map(repr, array.tolist())) + "]"
    return array.tolist()


def _inline(value, path):
    """A table below the top level with plain values only (`normal = { control = ... }`)."""
    return bool(path) and isinstance(value, Mapping) and len(value) <= 4 and all(
        not isinstance(v, Mapping) and not _is_table_array(v) for v in value.values())


def _table_lines(table, path, lines, name):
    where = f"{name}: {'.'.join(path)}" if path else name
    if not isinstance(table, Mapping):
        raise SceneError(f"{where}: expected a table (dict), got {type(table).__name__}")
    tables, arrays = [], []
    for key, value in table.items():
        _key(key, where)
        if isinstance(value, Mapping) and not _inline(value, path):
            tables.append((key, value))
        elif _is_table_array(value):
            arrays.append((key, value))
        else:
            lines.append(f"{_key(key, where)} = {toml_value(value, f'{name}: ' + '.'.join(path + [key]))}")
    for key, value in tables:
        header = ".".join(_key(k, where) for k in path + [key])
        # A table of tables alone needs no header of its own ([loading] before
        # [[loading.stage]]).
        if not value or any(not (isinstance(v, Mapping) and not _inline(v, path + [key]))
                            and not _is_table_array(v) for v in value.values()):
            lines.extend(["", f"[{header}]"])
        _table_lines(value, path + [key], lines, name)
    for key, value in arrays:
        header = ".".join(_key(k, where) for k in path + [key])
        for item in value:
            lines.extend(["", f"[[{header}]]"])
            _table_lines(item, path + [key], lines, name)


def to_toml(table, name="<dict>"):
    """A nested dict as scene TOML: dicts are tables, lists of dicts arrays of tables."""
    lines = []
    _table_lines(table, [], lines, name)
    return "\n".join(lines) + "\n"


class Scene:
    """A checked scene: made by from_file, from_toml or from_dict, changed by with_values or
    set, shown by to_toml or to_dict, written by save.

    Immutable: with_values and set return a new Scene. Every make builds the scene at once (parts
    created, preload solved), so bad input raises mdrsim.SceneError there, with the one-line
    message `mdrsim run` prints; the built scene is kept for every run of it.
    """

    # _text and _base_dir (made absolute) remake the scene elsewhere: pickle, mdrsim.sweep.
    __slots__ = ("_doc", "_overrides", "_text", "_base_dir")

    def __init__(self):
        raise TypeError("make a Scene with Scene.from_file, Scene.from_toml or Scene.from_dict")

    @classmethod
    def _wrap(cls, doc, overrides, text, base_dir):
        scene = object.__new__(cls)
        scene._doc = doc
        scene._overrides = tuple(overrides)
        scene._text = text
        scene._base_dir = os.path.abspath(base_dir)
        return scene

    @classmethod
    def from_file(cls, path):
        """Reads a scene file, TOML or JSON (a scene, or the JSON of `mdrsim run --json`,
        whose `scene` is read, as `mdrsim run result.json` does); messages name it as given,
        with line and column."""
        path = os.fspath(path)
        # Read here, so that the bytes kept are the ones built (`mdrsim run` reads them so).
        try:
            with open(path, "rb") as f:
                text = f.read()
        except OSError:
            _core.Document.from_file(path)  # raises the command's message
            raise
        base_dir = os.path.dirname(path) or "."
        return cls._wrap(_core.Document.from_text(text, path, base_dir), (), text, base_dir)

    @classmethod
    def from_toml(cls, text, name="<toml>", base_dir="."):
        """Scene text; `name` stands for the file in messages, `base_dir` resolves relative
        paths (a tabulated profile's file)."""
        base_dir = os.fspath(base_dir)
        return cls._wrap(_core.Document.from_text(text, name, base_dir), (), text, base_dir)

    @classmethod
    def from_dict(cls, table, name="<dict>", base_dir="."):
        """A nested dict laid out like the TOML file: {"material": {...}, "loading":
        {"stage": [{...}, ...]}}."""
        return cls.from_toml(to_toml(table, name), name, base_dir)

    def with_values(self, values):
        """A new Scene with {"dotted.key": value, ...} set, checked exactly like
        `mdrsim run --set KEY=VALUE` (messages start with --set). Keys of [[loading.stage]]
        count from 1: "loading.stage.2.tangential.by"."""
        pairs = [(key, toml_value(value, f"--set: {key}")) for key, value in dict(values).items()]
        return Scene._wrap(self._doc.with_values(pairs), self._overrides + tuple(pairs),
                           self._text, self._base_dir)

    def with_method(self, method, rtol=None):
        """A new Scene that runs by `method`: "event" or "stepping" (spring rows) or
        "continuum" (no springs: the continuum branch's root searches, docs/continuum.md).
        "continuum" drops the row's `springs` and `extrapolation` and keeps `rtol` (default
        1e-10 on that route); "event" drops the stepping keys of [solver]. `rtol` replaces
        [discretization] by {"rtol": rtol}. Refused as --set refuses: a loading program
        that shears, or one the route cannot answer exactly (docs/continuum.md)."""
        if method not in _METHODS:
            raise SceneError(f"--set: solver.method: unknown name '{method}' (known: "
                             f"{', '.join(_METHODS)})")
        values = {}
        if rtol is not None:
            values["discretization"] = {"rtol": rtol}
        elif method == "continuum":
            kept = self.to_dict().get("discretization", {})
            values["discretization"] = {k: v for k, v in kept.items() if k == "rtol"}
        if method == "stepping":
            values["solver.method"] = method
        else:
            values["solver"] = {"method": method}
        return self.with_values(values)

    def set(self, key, value):
        """A new Scene with one value set: scene.set("material.poisson_ratio", 0.3) is
        scene.with_values({"material.poisson_ratio": 0.3}), checked like --set."""
        return self.with_values({key: value})

    def to_dict(self):
        """The scene's values, overrides applied, as a nested dict laid out like the file
        (what from_dict takes)."""
        text = self._doc.to_toml()
        if tomllib is None:  # pragma: no cover
            raise RuntimeError("Scene.to_dict needs Python 3.11 (tomllib)")
        return tomllib.loads(text)

    def to_toml(self):
        """The scene's values as TOML, overrides applied, keys in order: what `mdrsim run`
        and Scene.from_toml read back to the same scene. Comments are not kept."""
        if tomllib is None:  # pragma: no cover
            return self._doc.to_toml()
        head = f"# From {self.source}"
        for key, value in self._overrides:
            head += f"\n#   --set {key}={value}"
        values = self.to_dict()
        ordered = {key: values[key] for key in _ORDER if key in values}
        ordered.update((key, value) for key, value in values.items() if key not in ordered)
        return head + "\n" + to_toml(ordered, self.source)

    def save(self, path):
        """Writes to_toml() to `path` (or JSON when it ends in .json). A relative path in the
        scene (a tabulated profile's file) is read from the saved file's folder: save it
        beside the original, or make that path absolute first with set()."""
        path = os.fspath(path)
        if path.endswith(".json"):
            text = json.dumps(self.to_dict(), indent=2) + "\n"
        else:
            text = self.to_toml()
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)

    def _state(self):
        """What remakes this scene in another process: (text, source, absolute base
        directory, overrides)."""
        return (self._text, self.source, self._base_dir, self._overrides)

    def __reduce__(self):
        # Pickled as its text and overrides, built again when unpickled: a part registered
        # from Python must be registered in the process that unpickles it.
        return (_scene_from_state, self._state())

    @property
    def source(self):
        """The file name (or the name given to from_toml / from_dict)."""
        return self._doc.source_name

    @property
    def overrides(self):
        """The with_values settings so far, as (dotted key, TOML value text)."""
        return self._overrides

    @property
    def title(self):
        return self._doc.title

    @property
    def springs(self):
        """Springs across the glued radius of a fixed row (meaningless with rtol or on the
        continuum route, which has none)."""
        return self._doc.springs

    @property
    def method(self):
        """"event", "stepping" or "continuum": the route the scene runs by, as built (rtol
        with no method named takes "continuum" where it answers the scene)."""
        return self._doc.method

    @property
    def material(self):
        return self._doc.material

    @property
    def profile(self):
        return self._doc.profile

    @property
    def criterion(self):
        return self._doc.criterion

    @property
    def control(self):
        """(normal, tangential) controller names; a program's last ones."""
        return self._doc.control

    def __repr__(self):
        title = f" {self.title!r}" if self.title else ""
        sets = "".join(f", {k}={v}" for k, v in self._overrides)
        route = "continuum route" if self.method == "continuum" else f"{self.springs} springs"
        return (f"<mdrsim.Scene {self.source!r}{title}: {self.profile} profile, {self.criterion}, "
                f"{route}{sets}>")


def _scene_from_state(text, source, base_dir, overrides):
    doc = _core.Document.from_text(text, source, base_dir)
    if overrides:
        doc = doc.with_values(list(overrides))
    return Scene._wrap(doc, overrides, text, base_dir)


def as_scene(scene, who):
    """A Scene, or one made from a scene file path or a dict (what mdrsim.run accepts)."""
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, Mapping):
        return Scene.from_dict(scene)
    if isinstance(scene, (str, os.PathLike)):
        return Scene.from_file(scene)
    raise TypeError(f"{who}() needs a Scene, a scene file path or a dict, not "
                    f"{type(scene).__name__}")

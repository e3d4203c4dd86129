"""mdrsim.sweep: the rows of `mdrsim sweep`, run on any concurrent.futures executor (threads,
processes, a Dask cluster), in batches that each last at least `batch_seconds`."""

import collections
import logging
import math
import numbers
import threading
import time
import uuid
from collections.abc import Mapping
from concurrent.futures import ThreadPoolExecutor
from functools import cached_property

from . import _core
from ._core import SceneError
from ._scene import as_scene

# Batches submitted and not yet collected: enough to keep any cluster busy, few enough that
# a grid of millions of rows does not queue millions of tasks at once.
_IN_FLIGHT = 256
# The rows after row 0 go out in at least this many tasks (or one per row), however cheap row
# 0 was: a row 0 far cheaper than the others (springs over decades) must not put the whole
# sweep in one task. At ~1 ms a Dask task, they cost at most ~32 ms.
_MIN_TASKS = 32
# A long sweep logs how far it is (as the command does) to the "mdrsim" logger at INFO, at
# most once per this many seconds.
_PROGRESS_SECONDS = 10.0
_log = logging.getLogger("mdrsim")
# The columns of the command's CSV that count things, read as int.
_COUNT_COLUMNS = frozenset({"springs_in_contact", "springs", "warnings", "springs_sliding"})
# The columns that are yes or no (true/false), read as bool.
_FLAG_COLUMNS = frozenset({"disk_valid", "sliding"})


def _item_text(key, item, flag="--vary"):
    """One value of a list as the command line writes it in `--vary KEY=V1,V2,...`."""
    if hasattr(item, "dtype") and getattr(item, "ndim", None) == 0:
        item = item.item()  # a NumPy scalar
    if isinstance(item, bool):
        return "true" if item else "false"
    if isinstance(item, numbers.Integral):
        return str(int(item))
    if isinstance(item, numbers.Real):
        return repr(float(item))  # the shortest text that reads back as the same double
    if isinstance(item, str):
        if "," in item or ":" in item:
            raise SceneError(f"{flag}: {key}: '{item}' is not one value (a name has no ',' or "
                             "':')")
        return item
    raise SceneError(f"{flag}: {key}: {type(item).__name__} {item!r:.40} is not a number or a "
                     "name")


def _vary_text(key, values, flag="--vary"):
    """`KEY=VALUES` as `mdrsim sweep --vary` (or --link) takes it."""
    if not isinstance(key, str):
        raise SceneError(f"{flag}: the key {key!r} is not a string")
    if "=" in key:
        raise SceneError(f"{flag}: '{key}' is not a key (it has '=')")
    if isinstance(values, str):
        return f"{key}={values}"
    if isinstance(values, numbers.Real) or (hasattr(values, "dtype") and values.ndim == 0):
        values = [values]
    try:
        items = list(values)
    except TypeError:
        raise SceneError(f"{flag}: {key}: {type(values).__name__} {values!r:.40} is not a list "
                         "of values or a string such as '0:1:11'") from None
    return f"{key}=" + ",".join(_item_text(key, item, flag) for item in items)


def _grid_flags(grid, where, design, samples, seed):
    """The command's flags of a grid and design, as SweepPlan takes them: (vary, linked,
    where, design, samples, seed). A tuple of keys in the grid is one axis: its first key a
    --vary, the others --link."""
    vary, linked = [], []
    for key, values in grid.items():
        if isinstance(key, tuple):
            if len(key) < 2:
                raise SceneError(f"--link: the keys {key!r} are not two or more keys varied "
                                 "together")
            if isinstance(values, (str, bytes)) or not hasattr(values, "__len__") or \
                    len(values) != len(key):
                raise SceneError(f"--link: the keys {key!r} need one value list per key, "
                                 f"not {values!r:.60}")
            for i, (each, its) in enumerate(zip(key, values)):
                flag = "--vary" if i == 0 else "--link"
                vary.append(_vary_text(each, its, flag))
                linked.append(i > 0)
        else:
            vary.append(_vary_text(key, values))
            linked.append(False)
    if where is None:
        where = []
    elif isinstance(where, str):
        where = [where]
    else:
        try:
            where = list(where)
        except TypeError:
            raise SceneError(f"--where: {type(where).__name__} {where!r:.40} is not a condition "
                             "or a list of them") from None
    for condition in where:
        if not isinstance(condition, str):
            raise SceneError(f"--where: {condition!r:.40} is not a condition such as 'a <= b'")
    if design is not None and not isinstance(design, str):
        raise SceneError(f"--design: {design!r:.40} is not grid, latin or random")

    def whole(flag, value):
        if value is None:
            return ""
        if isinstance(value, bool) or not isinstance(value, numbers.Integral):
            raise SceneError(f"{flag}: {value!r:.40} is not a whole number")
        return str(int(value))

    return (vary, linked, where, design or "", whole("--samples", samples), whole("--seed", seed))


class _Job:
    """What a task needs to run rows in any process: the scene's text and overrides, the
    grid's flags (_grid_flags) and the CSV's optional columns (dimensionless, friction, work,
    bulk, front).
    Pickled without its plan, which each process makes once (_plan_for)."""

    __slots__ = ("token", "scene", "vary", "columns", "plan")

    def __init__(self, token, scene, vary, columns, plan=None):
        self.token, self.scene, self.vary = token, scene, vary
        self.columns, self.plan = columns, plan

    def __getstate__(self):
        return (self.token, self.scene, self.vary, self.columns)

    def __setstate__(self, state):
        self.token, self.scene, self.vary, self.columns = state
        self.plan = None


_plans = collections.OrderedDict()  # token -> SweepPlan, the last few sweeps of this process
_plans_lock = threading.Lock()


def _plan_for(job):
    if job.plan is not None:
        return job.plan
    with _plans_lock:
        plan = _plans.get(job.token)
    if plan is None:
        plan = _core.SweepPlan(*job.scene, *job.vary, *job.columns)
        with _plans_lock:
            _plans[job.token] = plan
            while len(_plans) > 4:
                _plans.popitem(last=False)
    job.plan = plan
    return plan


def _run_rows(job, first, count):
    """One task: the CSV lines of rows first .. first + count - 1 (plain strings)."""
    return _plan_for(job).run_rows(first, count)


class SweepResult:
    """The rows of a sweep in the command's row order (the first key outermost, the last
    varying fastest)."""

    def __init__(self, identity, header, values, lines):
        self._identity = identity
        self._header = header
        self._values = values
        self._lines = lines

    @property
    def identity(self):
        """The CSV's first line, without its newline: `# mdrsim sweep: scene S, grid G, rows
        M, shard 0/1`. S hashes the scene's text and its with_values settings as `KEY=VALUE`,
        so it is the command's for a scene file swept with the same --set texts."""
        return self._identity.rstrip("\n")

    @cached_property
    def columns(self):
        """The CSV header: status, stop_reason, the varied keys, the run's fields."""
        return self._header.rstrip("\n").split(",")

    @cached_property
    def rows(self):
        """One dict per row, keyed by `columns`: the status and a varied name as str, the
        stop reason as str (None but for step-limit), a varied number and the fields as float (the counts springs_in_contact, springs and
        warnings, springs_sliding as int; disk_valid, sliding as bool), None where the CSV
        field is empty."""
        keys = [None if values is None else dict(values) for values in self._values]
        names = self.columns[2 + len(keys):]
        rows = []
        for line in self._lines:
            fields = line.rstrip("\n").split(",")
            row = {"status": fields[0], "stop_reason": fields[1] or None}
            for column, lookup, text in zip(self.columns[2:], keys, fields[2:]):
                row[column] = float(text) if lookup is None else lookup[text]
            for name, text in zip(names, fields[2 + len(keys):]):
                if text == "":
                    row[name] = None
                elif name in _COUNT_COLUMNS:
                    row[name] = int(text)
                elif name in _FLAG_COLUMNS:
                    row[name] = text == "true"
                else:
                    row[name] = float(text)
            rows.append(row)
        return rows

    def to_csv(self, path=None):
        """The command's CSV: the identity line, the header and the row lines, with the
        command's text for every number. Returned as a str, or written to `path`."""
        text = self._identity + self._header + "".join(self._lines)
        if path is None:
            return text
        with open(path, "w", encoding="utf-8", newline="") as f:
            f.write(text)
        return None

    def to_dataframe(self):
        """The rows as a pandas DataFrame (pandas is optional)."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError("SweepResult.to_dataframe needs pandas, which is not installed "
                              "(Debian: apt-get install python3-pandas)") from e
        return pandas.DataFrame(self.rows, columns=self.columns)

    def __len__(self):
        return len(self._lines)

    def __repr__(self):
        return f"<mdrsim.SweepResult {len(self)} rows x {len(self.columns)} columns>"


def sweep(scene, grid, executor=None, batch_seconds=0.1, method=None, *, where=None,
          design=None, samples=None, seed=None):
    """Runs one scene per row of a grid, as `mdrsim sweep` does, and returns a SweepResult.

    scene: a Scene, a scene file path or a dict (as mdrsim.run takes).
    grid: {key: values}, in the order of the command's --vary flags (the first outermost,
    the last varying fastest). values is a string in --vary's syntax, parsed by the
    command's own parser ("0:1e-5:41", "1e2:1e6:9:log", "mode-mixed,stress"), or a list of
    numbers and names (a str item is read as the command reads one: "2" is the number 2).
    A tuple of keys is one axis, its keys varied together (the command's --vary and --link):
    {("material.work_of_adhesion", "material.approach_work_of_adhesion"): ("0.01:0.1:10",
    "0.005:0.05:10")}, one value list per key, each as long as the others.
    where: a condition or a list of them, as the command's --where ("a <= b", "a < 0.5*b"):
    only the rows where every one holds run.
    design: None or "grid" (the product), "random" or "latin" (the command's --design): then
    samples (int) rows, drawn from seed (int, default 0) in each key's "FROM:TO" or
    "FROM:TO:log" (uniform, log-uniform) or list; the same seed, the same rows.
    executor: any concurrent.futures.Executor (a Dask cluster: Client.get_executor()); None
    runs the rows on a ThreadPoolExecutor of one thread per CPU this process may use (its
    affinity mask: taskset, a SLURM allocation), as the command's --threads default.

    Every value is checked before any run, as the command checks it: a bad key or value
    raises SceneError with the command's message. Row 0 then runs in the calling thread,
    and its time sets the batch: the other rows go to the executor in runs of consecutive
    rows that each take about batch_seconds or more (Dask spends ~1 ms on a task), in at
    least 32 tasks (or one per row), so that a row 0 much cheaper than the rest does not
    put the whole sweep in one task. A failing row raises its error (the first in row
    order); the rows that ran are not returned then.
    A long sweep says how far it is every 10 s, as the command does ("sweep: 120 of 2000
    rows in 31 s, about 8 min to go"), to the logging logger "mdrsim" at INFO (shown after
    logging.basicConfig(level=logging.INFO)).
    Tasks carry the scene as text and return the CSV lines as strings, so they pickle; a
    part registered from Python must be registered in every process that runs rows.
    method: None sweeps the scene as it is; "event", "stepping" or "continuum" sweeps
    scene.with_method(method) (the continuum route: a row in microseconds, no springs).
    """
    scene = as_scene(scene, "sweep")
    if method is not None:
        scene = scene.with_method(method)
    if not isinstance(grid, Mapping):
        raise TypeError(f"sweep() needs a grid {{key: values}}, not {type(grid).__name__}")
    if not grid:
        raise SceneError("--vary: the grid has no keys (give at least one key and its values)")
    if not (isinstance(batch_seconds, numbers.Real) and batch_seconds >= 0):
        raise ValueError(f"sweep(): batch_seconds must be a number >= 0, not {batch_seconds!r}")
    flags = _grid_flags(grid, where, design, samples, seed)
    state = scene._state()
    plan = _core.SweepPlan(*state, *flags)  # every value checked, as the command does
    job = _Job(uuid.uuid4().hex, state, flags, (plan.dimensionless, plan.friction, plan.work, plan.bulk,
                                      plan.front),
               plan)

    started = time.perf_counter()
    lines = plan.run_rows(0, 1)
    row_seconds = time.perf_counter() - started
    rows = plan.rows
    per_batch = batch_seconds / row_seconds if row_seconds > 0 else math.inf
    size = rows if per_batch >= rows else math.ceil(per_batch)
    size = max(1, min(size, math.ceil((rows - 1) / _MIN_TASKS)))

    own = executor is None
    if own:
        executor = ThreadPoolExecutor(_core.available_cpus(), thread_name_prefix="mdrsim-sweep")
    pending = collections.deque()
    progress = _core.SweepProgress(rows, _PROGRESS_SECONDS)

    def collect():
        lines.extend(pending.popleft().result())
        line = progress.line(len(lines))
        if line is not None:
            _log.info("%s", line)

    try:
        for first in range(1, rows, size):
            if len(pending) >= _IN_FLIGHT:
                collect()
            pending.append(executor.submit(_run_rows, job, first, min(size, rows - first)))
        while pending:
            collect()
    finally:
        for future in pending:
            future.cancel()
        if own:
            executor.shutdown(wait=True, cancel_futures=True)
    return SweepResult(plan.identity, plan.header, plan.values(), lines)

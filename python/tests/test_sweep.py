"""mdrsim.sweep: the rows of `mdrsim sweep`, byte for byte, on a thread pool and on Dask."""

import io
import logging
import math
import pickle
import subprocess
import time
from concurrent.futures import Executor, ThreadPoolExecutor

import pytest

import mdrsim

SCENE = "scenes/fig3a_fixed_load.toml"
# Few springs, nu = 0.3 (where the criteria differ): 3 criteria x 5 tangential displacements
# give instabilities and shear-offs (the critical fields empty).
SETS = {"discretization.springs": 200, "material.poisson_ratio": 0.3}
GRID = {"detachment.criterion": ["mode-mixed", "stress", "deformation"],
        "loading.tangential.displacement": "0:2e-5:5"}
VARY = ["--vary", "detachment.criterion=mode-mixed,stress,deformation",
        "--vary", "loading.tangential.displacement=0:2e-5:5"]
# 150 rows: enough to batch.
LONG_GRID = {"detachment.criterion": ["mode-mixed", "stress", "deformation"],
             "loading.tangential.displacement": "0:2e-5:50"}
LONG_VARY = ["--vary", "detachment.criterion=mode-mixed,stress,deformation",
             "--vary", "loading.tangential.displacement=0:2e-5:50"]


def small_scene():
    return mdrsim.Scene.from_file(SCENE).with_values(SETS)


def command_sweep(cli, vary, *more):
    sets = [arg for key, value in SETS.items() for arg in ("--set", f"{key}={value}")]
    return subprocess.run([cli, "sweep", SCENE, *sets, *vary, "--csv", "-", "--log-level", "off",
                           *more], capture_output=True, text=True)


@pytest.fixture
def command_csv(cli):
    done = command_sweep(cli, VARY, "--threads", "2")
    assert done.returncode == 0, done.stderr
    return done.stdout


@pytest.fixture
def long_command_csv(cli):
    done = command_sweep(cli, LONG_VARY, "--threads", "2")
    assert done.returncode == 0, done.stderr
    return done.stdout


class CountingExecutor(Executor):
    """Passes each task on to `inner` and counts them."""

    def __init__(self, inner):
        self.inner = inner
        self.tasks = 0

    def submit(self, fn, /, *args, **kwargs):
        self.tasks += 1
        return self.inner.submit(fn, *args, **kwargs)


def test_thread_pool_gives_the_command_csv(command_csv):
    with ThreadPoolExecutor(2) as pool:
        result = mdrsim.sweep(small_scene(), GRID, executor=pool)
    # The identity line too: the same scene bytes, --set text and grid.
    assert result.to_csv() == command_csv
    lines = command_csv.splitlines()
    assert result.identity == lines[0]
    assert result.columns == lines[1].split(",")
    assert len(result) == len(result.rows) == 15 == len(lines) - 2
    first, last = result.rows[0], result.rows[-1]
    assert first["detachment.criterion"] == "mode-mixed"
    assert first["loading.tangential.displacement"] == 0.0
    assert last["detachment.criterion"] == "deformation"
    assert last["loading.tangential.displacement"] == 2e-5
    assert {row["status"] for row in result.rows} == {"instability", "shear-off"}
    assert {row["stop_reason"] for row in result.rows} == {None}
    assert last["normal_force"] is None and last["tangential_strength"] > 0
    assert first["springs_in_contact"] > 0 and isinstance(first["springs_in_contact"], int)
    assert isinstance(first["springs"], int) and isinstance(first["warnings"], int)
    assert first["glued_radius"] > 0
    for row, line in zip(result.rows, lines[2:]):
        fields = line.split(",")
        assert row["status"] == fields[0]
        for name, text in zip(result.columns[4:], fields[4:]):
            if name == "disk_valid":
                assert row[name] is (text == "true")
            else:
                assert row[name] == (None if text == "" else float(text))


def test_to_dataframe(command_csv):
    pandas = pytest.importorskip("pandas")
    result = mdrsim.sweep(small_scene(), GRID)
    frame = result.to_dataframe()
    assert list(frame.columns) == result.columns and len(frame) == 15
    read = pandas.read_csv(io.StringIO(command_csv), comment="#")
    pandas.testing.assert_frame_equal(frame, read, check_dtype=False)


def test_default_executor_and_lists_give_the_same_rows(command_csv, tmp_path):
    # A list of numbers is the same grid as the range that gives them (docs/sweeps.md: G hashes the
    # values as the CSV writes them); executor=None: a thread pool of its own.
    # (1 - t) FROM + t TO at t = 3/4 is 1.5000000000000002e-05, within its rounding error of
    # 1.5e-05, which the range gives.
    grid = {"detachment.criterion": "mode-mixed,stress,deformation",
            "loading.tangential.displacement": [0, 5e-6, 1e-5, 1.5e-5, 2e-5]}
    result = mdrsim.sweep(small_scene(), grid)
    assert result.to_csv() == command_csv
    path = tmp_path / "sweep.csv"
    assert result.to_csv(path) is None
    assert path.read_bytes() == command_csv.encode()


def test_rows_are_batched(long_command_csv):
    with ThreadPoolExecutor(2) as pool:
        # Row 0 runs in the calling thread and sets the batch; the other 149 rows go out in
        # at least 32 tasks (batches of 5: 30 tasks), or one task per row.
        for batch_seconds, tasks in ((1e3, 30), (math.inf, 30), (0, 149)):
            counting = CountingExecutor(pool)
            result = mdrsim.sweep(small_scene(), LONG_GRID, executor=counting,
                                  batch_seconds=batch_seconds)
            assert counting.tasks == tasks and result.to_csv() == long_command_csv


# Names the Python registries cannot extend (test_parts.py adds criteria to the known list).
@pytest.mark.parametrize("vary, grid", [
    (["--vary", "loading.normal.control=fixed-load,fixed-grip"],
     {"loading.normal.control": ["fixed-load", "fixed-grip"]}),
    (["--vary", "discretization.springs=100,many"], {"discretization.springs": [100, "many"]}),
    (["--vary", "loading.tangential.displacement=0:1e-6:0"],
     {"loading.tangential.displacement": "0:1e-6:0"}),
    (["--vary", "material.poisson_rate=0,0.3"], {"material.poisson_rate": [0, 0.3]}),
    (["--vary", "discretization.springs=100,nan"], {"discretization.springs": [100, float("nan")]}),
])
def test_bad_grid_raises_the_command_message_before_any_run(cli, vary, grid):
    done = command_sweep(cli, vary)
    assert done.returncode == 2 and done.stdout == ""
    with ThreadPoolExecutor(1) as pool:
        counting = CountingExecutor(pool)
        with pytest.raises(mdrsim.SceneError) as caught:
            mdrsim.sweep(small_scene(), grid, executor=counting)
    assert str(caught.value) == done.stderr.strip()
    assert counting.tasks == 0


@pytest.mark.parametrize("grid, message", [
    ({}, "--vary: the grid has no keys (give at least one key and its values)"),
    ({"detachment.criterion": ["stress,deformation"]},
     "--vary: detachment.criterion: 'stress,deformation' is not one value (a name has no ',' or "
     "':')"),
    ({"discretization.springs": [100, None]},
     "--vary: discretization.springs: NoneType None is not a number or a name"),
])
def test_grid_a_command_line_cannot_give(grid, message):
    with pytest.raises(mdrsim.SceneError) as caught:
        mdrsim.sweep(small_scene(), grid)
    assert str(caught.value) == message


def test_scene_pickles_as_its_text_and_overrides():
    scene = mdrsim.Scene.from_file("scenes/tabulated_cone_fixed_load.toml").with_values(
        {"discretization.springs": 2000})
    again = pickle.loads(pickle.dumps(scene))
    assert (again.source, again.overrides, again.springs) == (scene.source, scene.overrides, 2000)
    assert mdrsim.run(again).critical == mdrsim.run(scene).critical


# Debian's tornado 6.2 under distributed 2022.12: a warning of theirs, not ours.
@pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")
def test_dask_local_cluster_gives_the_command_csv(command_csv, long_command_csv):
    distributed = pytest.importorskip(
        "distributed", reason="Dask's distributed is not installed (Debian: python3-distributed)")
    started = time.perf_counter()
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None, silence_logs=logging.ERROR) as cluster, \
            distributed.Client(cluster) as client:
        # batch_seconds=0: one task per row, so that both workers run rows and their order is
        # put back; the scene travels as text, the rows come back as strings.
        result = mdrsim.sweep(small_scene(), GRID, executor=client.get_executor(),
                              batch_seconds=0)
        assert result.to_csv() == command_csv
        # Both workers ran rows: each made the sweep's plan once (a lambda pickles by value).
        assert list(client.run(lambda: len(mdrsim._sweep._plans)).values()) == [1, 1]
        result = mdrsim.sweep(small_scene(), LONG_GRID, executor=client.get_executor())
        assert result.to_csv() == long_command_csv
    assert time.perf_counter() - started < 30


def test_log_lines_name_their_row(capfd):
    # 20 springs do not resolve the critical point: each row warns, and its warning says
    # which row it is, as the command's do.
    scene = mdrsim.Scene.from_file("scenes/fig3a_fixed_grips.toml").with_values(
        {"discretization": {"springs": 20}})  # a plain row (the scene extrapolates)
    mdrsim.set_log_level("warn")
    try:
        result = mdrsim.sweep(scene, {"loading.tangential.displacement": [0, 4e-6]})
    finally:
        mdrsim.set_log_level("off")
    err = capfd.readouterr().err.splitlines()
    assert [row["warnings"] for row in result.rows] == [1, 1]
    for index, value in enumerate(["0", "4e-06"]):
        label = f"[mdrsim warning] row {index} of 2 (loading.tangential.displacement={value}): "
        assert sum(line.startswith(label) for line in err) == 1, err
    assert all(line.startswith("[mdrsim warning] row ") for line in err), err


def test_progress_lines_go_to_the_mdrsim_logger(monkeypatch, caplog):
    # Every collected batch says how far the sweep is once the interval has passed: here at
    # once. The rows run by now, of all; the time to go once a row has run.
    monkeypatch.setattr(mdrsim._sweep, "_PROGRESS_SECONDS", 0.0)
    with caplog.at_level(logging.INFO, logger="mdrsim"):
        result = mdrsim.sweep(small_scene(), GRID, batch_seconds=0)
    messages = [r.getMessage() for r in caplog.records if r.name == "mdrsim"]
    assert len(messages) == 13, messages  # rows 2 .. 14 of 15 (row 0 runs first, 15 is the end)
    for written, message in zip(range(2, 15), messages):
        assert message.startswith(f"sweep: {written} of 15 rows in "), message
        assert message.endswith(" to go"), message
    assert len(result) == 15


def test_quiet_by_default_with_warnings_on_the_result(capfd):
    # Without set_log_level nothing reaches standard error; each row's warnings are counted in
    # its row and a run's are on its result.
    scene = mdrsim.Scene.from_file("scenes/fig3a_fixed_grips.toml").with_values(
        {"discretization": {"springs": 20}})
    result = mdrsim.sweep(scene, {"loading.tangential.displacement": [0, 4e-6]})
    run = mdrsim.run(scene)
    assert capfd.readouterr().err == ""
    assert [row["warnings"] for row in result.rows] == [1, 1]
    assert len(run.warnings) == 1


def test_work_columns_are_the_runs_work():
    # A program's sweep has the run's total work per axis last, as the command's CSV.
    scene = mdrsim.Scene.from_file("scenes/programs/fretting_parabola.toml").with_values(
        {"discretization.springs": 400})
    result = mdrsim.sweep(scene, {"friction.coefficient": [0.3, 0.5]})
    assert result.columns[-2:] == ["work_normal", "work_tangential"]
    for row, mu in zip(result.rows, [0.3, 0.5]):
        work = mdrsim.run(scene.with_values({"friction.coefficient": mu})).work
        assert row["work_normal"] == work.normal
        assert row["work_tangential"] == work.tangential
        assert row["dissipated_by_friction"] == work.dissipated_by_friction


# dgamma_a <= dgamma: the program refuses a row with dgamma_a > dgamma.
PROGRAM = "scenes/programs/jkr_cycle_reversible.toml"
DGAMMA = "material.work_of_adhesion"
DGAMMA_A = "material.approach_work_of_adhesion"


def program_command(cli, *flags):
    done = subprocess.run([cli, "sweep", PROGRAM, "--set", "discretization.springs=200", *flags,
                           "--csv", "-", "--log-level", "off"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


def program_scene():
    return mdrsim.Scene.from_file(PROGRAM).with_values({"discretization.springs": 200})


def test_linked_keys_and_where_give_the_command_csv(cli):
    where = f"{DGAMMA_A} <= {DGAMMA}"
    filtered = mdrsim.sweep(program_scene(), {DGAMMA: "0.01:0.04:4", DGAMMA_A: "0.01:0.04:4"},
                            where=where)
    assert filtered.to_csv() == program_command(
        cli, "--vary", f"{DGAMMA}=0.01:0.04:4", "--vary", f"{DGAMMA_A}=0.01:0.04:4", "--where",
        where)
    assert len(filtered) == 10
    assert all(row[DGAMMA_A] <= row[DGAMMA] for row in filtered.rows)
    linked = mdrsim.sweep(program_scene(), {(DGAMMA, DGAMMA_A): ("0.01:0.04:4", [0.005, 0.01,
                                                                                 0.015, 0.02])})
    assert linked.to_csv() == program_command(
        cli, "--vary", f"{DGAMMA}=0.01:0.04:4", "--link", f"{DGAMMA_A}=0.005,0.01,0.015,0.02")
    assert [row[DGAMMA_A] / row[DGAMMA] for row in linked.rows] == [0.5] * 4


def test_random_design_gives_the_command_csv_and_is_reproducible(cli):
    grid = {"material.poisson_ratio": "0:0.45", "profile.radius": "1e-3:1e-1:log"}
    flags = ["--vary", "material.poisson_ratio=0:0.45", "--vary", "profile.radius=1e-3:1e-1:log"]
    for design in ("random", "latin"):
        result = mdrsim.sweep(small_scene(), grid, design=design, samples=12, seed=5)
        assert result.to_csv() == command_sweep(cli, flags, "--design", design, "--samples", "12",
                                                "--seed", "5").stdout
        assert result.to_csv() == mdrsim.sweep(small_scene(), grid, design=design, samples=12,
                                               seed=5).to_csv()
        assert result.to_csv() != mdrsim.sweep(small_scene(), grid, design=design, samples=12,
                                               seed=6).to_csv()
        for row in result.rows:
            assert 0.0 <= row["material.poisson_ratio"] <= 0.45
            assert 1e-3 <= row["profile.radius"] <= 1e-1


@pytest.mark.parametrize("kwargs, message", [
    ({"grid": {("a.b",): ["1"]}},
     "--link: the keys ('a.b',) are not two or more keys varied together"),
    ({"grid": {(DGAMMA, DGAMMA_A): "0.01:0.04:4"}},
     f"--link: the keys ('{DGAMMA}', '{DGAMMA_A}') need one value list per key, not "
     "'0.01:0.04:4'"),
    ({"grid": {(DGAMMA, DGAMMA_A): ("0.01:0.04:4", "0.01:0.04:3")}},
     f"--link: {DGAMMA_A} has 3 values, {DGAMMA} has 4 (a linked key needs as many as the key "
     "it varies with)"),
    ({"grid": {DGAMMA: "0.01:0.04:4"}, "where": 3},
     "--where: int 3 is not a condition or a list of them"),
    ({"grid": {DGAMMA: "0.01:0.04:4"}, "where": [f"{DGAMMA} <= x"]},
     f"--where: x is not a varied key (known: {DGAMMA})"),
    ({"grid": {DGAMMA: "0.01:0.04"}, "design": "random"},
     "--samples: --design random needs --samples N"),
    ({"grid": {DGAMMA: "0.01:0.04"}, "design": "random", "samples": 2.5},
     "--samples: 2.5 is not a whole number"),
    ({"grid": {DGAMMA: "0.01:0.04"}, "design": "random", "samples": 3, "seed": -1},
     "--seed: '-1' is not a whole number from 0 to 18446744073709551615"),
    ({"grid": {DGAMMA: "0.01:0.04:4"}, "design": "sobol"},
     "--design: unknown 'sobol' (known: grid, latin, random)"),
])
def test_bad_design_arguments_raise_scene_error(kwargs, message):
    with pytest.raises(mdrsim.SceneError) as caught:
        mdrsim.sweep(program_scene(), **kwargs)
    assert str(caught.value) == message


def test_a_long_run_and_a_sweep_print_nothing_by_default(capfd):
    # Logs are off until set_log_level (test_log_lines_name_their_row turns them on): a program
    # run of 2e6 springs, whose engine asks every 65536 events whether its progress line is due
    # (at info, every 2 s), and a sweep whose every row warns write nothing to standard output
    # or error. The warnings are on the result, as a count per row in the sweep.
    cycle = mdrsim.Scene.from_file("scenes/programs/jkr_cycle_reversible.toml")
    long = mdrsim.run(cycle.set("discretization.springs", 2_000_000), trajectory=False)
    coarse = mdrsim.Scene.from_file("scenes/fig3a_fixed_grips.toml").with_values(
        {"discretization": {"springs": 20}})  # a plain row (the scene extrapolates)
    rows = mdrsim.sweep(coarse, {"loading.tangential.displacement": [0, 2e-6, 4e-6]}).rows
    assert capfd.readouterr() == ("", "")
    assert long.counts["events"] > 1 << 16
    assert [row["warnings"] for row in rows] == [1, 1, 1]

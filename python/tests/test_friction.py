"""Friction from Python (docs/friction.md): scenes with [friction] from files and dicts, the
states' stick radius and sliding springs, the frictional work, the trajectory's `sliding`
column and `slip`/`stick` events, held to Cattaneo-Mindlin and Mindlin-Deresiewicz."""

import csv
import math
import pickle
import subprocess

import numpy as np
import pytest

import mdrsim

FRETTING = "scenes/programs/fretting_parabola.toml"
SPRINGS = 1000

# The fretting scene's values: R = 1 cm, E* = G* = 1 MPa (nu = 0), mu = 0.5, F_z = 1 mN, the
# indenter moved to u_m = 1 um, back to -u_m and up to u_m again.
RADIUS, MODULUS, SHEAR_MODULUS, MU, FORCE, AMPLITUDE = 0.01, 1.0e6, 1.0e6, 0.5, 1.0e-3, 1.0e-6


def fretting_dict(springs=SPRINGS, coefficient=MU):
    """The fretting scene built in Python, value for value as the file has it."""
    return {
        "title": "fretting from a dict",
        "material": {"youngs_modulus": MODULUS, "poisson_ratio": 0.0, "work_of_adhesion": 0.0},
        "profile": {"type": "parabolic", "radius": RADIUS},
        "loading": {"stage": [
            {"name": "press", "normal": {"control": "fixed-load", "to": FORCE}},
            {"name": "load", "tangential": {"control": "fixed-grips", "by": AMPLITUDE}},
            {"name": "unload", "tangential": {"by": -2 * AMPLITUDE}},
            {"name": "reload", "tangential": {"by": 2 * AMPLITUDE}},
        ]},
        "friction": {"coefficient": coefficient},
        "discretization": {"springs": springs},
        "solver": {"method": "event"},
    }


class ClosedForms:
    """The parabola under Coulomb friction (docs/friction.md "The closed forms the tests use"),
    derived here apart from the engine: a = (3 F_z R / (4 E*))^(1/3), d = a^2/R, full slip at
    u* = mu E* d / G*, xi = u_m/u*."""

    def __init__(self):
        self.a = (3 * FORCE * RADIUS / (4 * MODULUS)) ** (1 / 3)
        self.d = self.a ** 2 / RADIUS
        self.u_star = MU * MODULUS * self.d / SHEAR_MODULUS
        self.limit = MU * FORCE

    def loading(self, u):
        """Cattaneo-Mindlin L(u) = mu F_z [1 - (1 - u/u*)^(3/2)], odd in u."""
        x = min(abs(u) / self.u_star, 1.0)
        return math.copysign(self.limit * (1 - (1 - x) ** 1.5), u)

    def stick_radius(self, u):
        return self.a * math.sqrt(max(1 - abs(u) / self.u_star, 0.0))

    def unloading(self, u):
        """Mindlin-Deresiewicz from u_m down: L(u_m) - 2 L((u_m - u)/2)."""
        return self.loading(AMPLITUDE) - 2 * self.loading((AMPLITUDE - u) / 2)

    def reloading(self, u):
        """From -u_m up: -L(u_m) + 2 L((u_m + u)/2)."""
        return -self.loading(AMPLITUDE) + 2 * self.loading((AMPLITUDE + u) / 2)

    def loop_energy(self):
        """W = mu F_z u* [4 xi - 16/5 + 4 xi (1 - xi)^(3/2) + (16/5)(1 - xi)^(5/2)]."""
        xi = AMPLITUDE / self.u_star
        return self.limit * self.u_star * (4 * xi - 16 / 5 + 4 * xi * (1 - xi) ** 1.5
                                           + 16 / 5 * (1 - xi) ** 2.5)


CLOSED = ClosedForms()


@pytest.fixture(scope="module")
def fretting():
    return mdrsim.run(mdrsim.Scene.from_file(FRETTING).set("discretization.springs", SPRINGS))


def stage(result, name):
    return next(s for s in result.stages if s.name == name)


def test_closed_forms_agree_with_the_scene_files_comment():
    # The numbers the scene file states (to its 6 digits): a check of this file's algebra.
    assert CLOSED.a == pytest.approx(1.95743e-4, rel=1e-5)
    assert CLOSED.u_star == pytest.approx(1.91577e-6, rel=1e-5)
    assert CLOSED.loading(AMPLITUDE) == pytest.approx(3.34752e-4, rel=1e-5)
    assert CLOSED.stick_radius(AMPLITUDE) == pytest.approx(1.35335e-4, rel=1e-5)
    assert CLOSED.loop_energy() == pytest.approx(8.00087e-11, rel=1e-5)


def test_load_stage_ends_on_cattaneo_mindlin(fretting):
    # The row's d under the fixed load and its sums over springs (a monotone line load summed
    # at spacing dx = a/N) are each off by O(1/N): F_x within 4/N of mu F_z, as
    # tests/engine/program/program_examples_test.cpp holds the command's run.
    end = stage(fretting, "load").end
    assert end.tangential_force == pytest.approx(CLOSED.loading(AMPLITUDE),
                                                 abs=4 / SPRINGS * CLOSED.limit)
    # The stick radius is a spring's place x_{j-1} (j the innermost sliding spring): within
    # 2 dx of c = a sqrt(1 - u/u*), one spacing for the place and one for the row's a.
    assert end.stick_radius == pytest.approx(CLOSED.stick_radius(AMPLITUDE),
                                             abs=2 * CLOSED.a / SPRINGS)
    assert 0 < end.springs_sliding < end.springs_in_contact
    # The springs outside c slide: (a - c)/dx of them, within 2 for the ends.
    outside = (CLOSED.a - CLOSED.stick_radius(AMPLITUDE)) / (CLOSED.a / SPRINGS)
    assert abs(end.springs_sliding - outside) <= 2
    # Pressed, nothing slides: the stick radius is the contact radius.
    press = stage(fretting, "press").end
    assert press.springs_sliding == 0 and press.stick_radius == press.contact_radius


def test_unloading_and_reloading_follow_mindlin_deresiewicz(fretting):
    unload, reload = stage(fretting, "unload").end, stage(fretting, "reload").end
    tolerance = 4 / SPRINGS * CLOSED.limit  # as on loading
    assert unload.tangential_force == pytest.approx(CLOSED.unloading(-AMPLITUDE), abs=tolerance)
    assert reload.tangential_force == pytest.approx(CLOSED.reloading(AMPLITUDE), abs=tolerance)
    # Masing: the loop closes on the loading curve's end, to rounding.
    assert reload.tangential_force == pytest.approx(stage(fretting, "load").end.tangential_force,
                                                    rel=1e-12)
    # Along the branches, the trajectory's rows (each an event of the row) on the closed forms.
    t = fretting.trajectory
    for name, branch in (("unload", CLOSED.unloading), ("reload", CLOSED.reloading)):
        rows = [i for i, s in enumerate(t["stage"]) if s == name]
        u = t["tangential_displacement"][rows]
        fx = t["tangential_force"][rows]
        worst = max(abs(f - branch(x)) for x, f in zip(u, fx))
        assert worst <= tolerance, name


def test_loop_energy_is_mindlin_deresiewicz_and_all_of_it_dissipated(fretting):
    work = sum(stage(fretting, n).work.tangential for n in ("unload", "reload"))
    dissipated = sum(stage(fretting, n).work.dissipated_by_friction for n in ("unload", "reload"))
    # Sums over springs at spacing a/N: W within 4/N of itself (observed 9e-5 at 4000 springs).
    assert work == pytest.approx(CLOSED.loop_energy(), rel=4 / SPRINGS)
    # A closed cycle: the machine's work is all dissipated, to rounding.
    assert dissipated == pytest.approx(work, rel=1e-12)
    # The total is the stages' sum (press dissipates nothing: nothing moves tangentially).
    assert stage(fretting, "press").work.dissipated_by_friction == 0.0
    total = sum(s.work.dissipated_by_friction for s in fretting.stages)
    assert fretting.dissipated_by_friction == pytest.approx(total, rel=1e-12)
    assert fretting.work.dissipated_by_friction == fretting.dissipated_by_friction
    assert fretting.to_dict()["work"]["dissipated_by_friction"] == fretting.dissipated_by_friction
    assert fretting.status == "completed" and fretting.sliding is False


def test_trajectory_has_slip_and_stick_events_and_the_sliding_column(fretting):
    t = fretting.trajectory
    events = t["event"]
    assert "slip" in events and "stick" in events
    sliding = t["sliding"]
    assert sliding.dtype == np.int64 and sliding.shape == (len(events),)
    assert not sliding.flags.writeable
    # One `slip` per spring that comes to slide on loading, none before it moves.
    load = [i for i, s in enumerate(t["stage"]) if s == "load"]
    slips = sum(1 for i in load if events[i] == "slip")
    assert slips == stage(fretting, "load").end.springs_sliding
    assert sliding[load[-1]] == stage(fretting, "load").end.springs_sliding
    # Reversal: every sliding spring sticks at the unload's start (its parameter 0).
    unload = [i for i, s in enumerate(t["stage"]) if s == "unload"]
    sticks = [i for i in unload if events[i] == "stick"]
    assert len(sticks) == stage(fretting, "load").end.springs_sliding
    assert all(t["tangential_displacement"][i] == t["tangential_displacement"][sticks[0]]
               for i in sticks)
    # A slip adds a sliding spring, a stick takes one away.
    for i in range(1, len(events)):
        if events[i] == "slip":
            assert sliding[i] == sliding[i - 1] + 1
        elif events[i] == "stick":
            assert sliding[i] == sliding[i - 1] - 1


def test_trajectory_columns_are_the_commands_csv(fretting, cli, tmp_path):
    csv_path = tmp_path / "fretting.csv"
    subprocess.run([cli, "run", FRETTING, "--set", f"discretization.springs={SPRINGS}",
                    "--trajectory", str(csv_path)], check=True, capture_output=True)
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    t = fretting.trajectory
    assert list(rows[0])[-1] == "sliding"
    assert [r["event"] for r in rows] == t["event"]
    assert [int(r["sliding"]) for r in rows] == t["sliding"].tolist()
    assert [float(r["tangential_force"]) for r in rows] == t["tangential_force"].tolist()
    pandas = pytest.importorskip("pandas")
    frame = fretting.to_dataframe()
    assert isinstance(frame, pandas.DataFrame) and "sliding" in frame.columns


def test_a_scene_from_a_dict_runs_as_the_file_does(fretting):
    from_dict = mdrsim.run(mdrsim.Scene.from_dict(fretting_dict()))
    assert [s.end for s in from_dict.stages] == [s.end for s in fretting.stages]
    assert [s.work for s in from_dict.stages] == [s.work for s in fretting.stages]
    # And the file's scene read back through to_dict.
    back = mdrsim.Scene.from_dict(mdrsim.Scene.from_file(FRETTING).to_dict())
    assert back.to_dict()["friction"] == {"coefficient": MU}


def test_pickle_keeps_the_friction_outputs(fretting):
    copy = pickle.loads(pickle.dumps(fretting))
    assert copy.dissipated_by_friction == fretting.dissipated_by_friction
    assert copy.sliding == fretting.sliding
    assert copy.stages[1].end.stick_radius == fretting.stages[1].end.stick_radius
    assert np.array_equal(copy.trajectory["sliding"], fretting.trajectory["sliding"])


def test_coefficient_zero_is_the_frictionless_run():
    # An adhesive contact glued, unloaded to -d0 and sheared under fixed grips until it comes
    # off (scenes/programs/shear_ramp_fixed_grips.toml): with mu = 0 every number is the
    # frictionless run's, bit for bit (docs/friction.md).
    scene = mdrsim.Scene.from_file("scenes/programs/shear_ramp_fixed_grips.toml").set(
        "discretization.springs", 500)
    plain = mdrsim.run(scene)
    zero = mdrsim.run(scene.set("friction", {"coefficient": 0.0}))
    assert plain.status == zero.status == "instability"

    def numbers(state):
        return (state.normal_force, state.tangential_force, state.contact_radius,
                state.indentation, state.tangential_displacement, state.springs_in_contact)

    assert numbers(zero.critical) == numbers(plain.critical)
    assert [numbers(s.end) for s in zero.stages] == [numbers(s.end) for s in plain.stages]
    assert [(s.work.normal, s.work.tangential) for s in zero.stages] == \
        [(s.work.normal, s.work.tangential) for s in plain.stages]
    for name in ("indentation", "normal_force", "tangential_force", "springs_in_contact"):
        assert np.array_equal(zero.trajectory[name], plain.trajectory[name]), name
    # mu = 0 under the unlimited glue is no friction at all (engine/scene/friction_reader.cpp):
    # the friction outputs are absent, as from the JSON and the CSV.
    for result in (plain, zero):
        assert result.critical.springs_sliding is None and result.critical.stick_radius is None
        assert all(s.work.dissipated_by_friction is None for s in result.stages)
        assert "sliding" not in result.trajectory
        assert "dissipated_by_friction" not in result.to_dict()["stages"][0]["work"]


def test_friction_leaves_the_normal_problem_alone(fretting):
    # In the MDR the springs' normal and tangential forces are independent: the fretting run's
    # normal path is the frictionless one's, bit for bit, while its F_x is not zero.
    plain = mdrsim.run(mdrsim.Scene.from_file(FRETTING).with_values(
        {"discretization.springs": SPRINGS, "friction.coefficient": 0.0}))
    assert [(s.end.indentation, s.end.normal_force, s.end.springs_in_contact)
            for s in plain.stages] == [(s.end.indentation, s.end.normal_force,
                                        s.end.springs_in_contact) for s in fretting.stages]
    assert all(s.end.tangential_force == 0.0 for s in plain.stages)
    assert stage(fretting, "load").end.tangential_force > 0


def test_a_held_force_friction_cannot_hold_ends_in_gross_sliding():
    # Pressed with F_z, then F_x held at 0.6 mN > mu F_z = 0.5 mN: the springs slide from the
    # edge inwards (Cattaneo-Mindlin under a rising F_x) until all slide at F_x = mu F_z, at
    # u_x = u* (docs/friction.md "Statuses").
    table = fretting_dict()
    table["loading"]["stage"] = [table["loading"]["stage"][0], {
        "name": "push", "tangential": {"control": "fixed-load", "to": 1.2 * MU * FORCE}}]
    with pytest.warns(mdrsim.RunWarning, match="friction can no longer hold"):
        result = mdrsim.run(mdrsim.Scene.from_dict(table))
    assert result.status == "shear-off" and result.sliding is True
    assert result.to_dict()["sliding"] is True
    c = result.critical
    assert c.springs_sliding == c.springs_in_contact and c.stick_radius == 0.0
    assert c.tangential_force == pytest.approx(MU * c.normal_force, rel=1e-12)  # the row's limit
    # The row's d under the fixed load is off by O(1/N), and u* with it: within 4/N.
    assert c.tangential_displacement == pytest.approx(CLOSED.u_star, rel=4 / SPRINGS)
    assert result.dissipated_by_friction > 0


@pytest.mark.parametrize("friction, words", [
    ({"coefficient": -0.5}, "coefficient"),
    ({"coefficient": "high"}, "coefficient"),
    ({}, "coefficient"),
    ({"coefficient": 0.5, "glued": "sticky"}, "glued"),
    ({"coefficient": 0.5, "shear_strength": 1.0}, "shear_strength"),
    ({"coefficient": 0.5, "slip": 1.0}, "slip"),
])
def test_bad_friction_raises_scene_error(friction, words):
    table = fretting_dict()
    table["friction"] = friction
    with pytest.raises(mdrsim.SceneError, match=words) as raised:
        mdrsim.Scene.from_dict(table)
    assert "\n" not in str(raised.value)


def test_bad_friction_by_set_raises_scene_error():
    scene = mdrsim.Scene.from_file(FRETTING)
    with pytest.raises(mdrsim.SceneError, match="friction.coefficient"):
        scene.set("friction.coefficient", -1.0)
    with pytest.raises(mdrsim.SceneError, match="friction"):
        scene.with_method("stepping")  # friction runs on the event engine only


def test_sweep_of_friction_scenes_has_the_friction_columns(cli):
    """A sweep of friction scenes (docs/outputs.md "The sweep CSV") ends each row with the
    critical state's springs_sliding and stick_radius, sliding and dissipated_by_friction, read
    as int, float, bool and float, then a program's work per axis; its CSV is the command's byte for byte, and a process pool
    (whose workers rebuild the plan from the job) writes the same."""
    import concurrent.futures

    scene = mdrsim.Scene.from_file("scenes/programs/pull_off_after_shear.toml")
    grid = {"loading.stage.2.tangential.to": [5e-6, 2e-5], "friction.coefficient": [0.0, 1.0]}
    result = mdrsim.sweep(scene, grid)
    assert result.columns[-6:] == ["springs_sliding", "stick_radius", "sliding",
                                   "dissipated_by_friction", "work_normal", "work_tangential"]
    rows = result.rows
    assert [type(rows[0][k]) for k in ("springs_sliding", "sliding")] == [int, bool]
    # Sheared past the glue's break under mu = 1: the pressed springs slid and dissipated.
    assert rows[3]["dissipated_by_friction"] > 0 and rows[2]["dissipated_by_friction"] == 0.0
    assert not any(row["sliding"] for row in rows)  # u_x driven: nothing slides away
    command = subprocess.run(
        [cli, "sweep", "scenes/programs/pull_off_after_shear.toml",
         "--vary", "loading.stage.2.tangential.to=5e-6,2e-5", "--vary", "friction.coefficient=0,1",
         "--csv", "-", "--log-level", "off"],
        capture_output=True, text=True, check=True).stdout
    assert result.to_csv().split("\n", 1)[1] == command.split("\n", 1)[1]
    with concurrent.futures.ProcessPoolExecutor(2) as pool:
        assert mdrsim.sweep(scene, grid, executor=pool).to_csv() == result.to_csv()

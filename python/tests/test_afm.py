"""mdrsim.afm: measured files read into NumPy arrays, and curves fitted by the engine's fit, the
same numbers as `mdrsim fit --json`."""

import json
import subprocess
import zipfile

import numpy as np
import pytest

import mdrsim
from mdrsim import afm

AFM = "tests/data/afm"
SPOT3 = f"{AFM}/fmt-jpk-fd_spot3-0192.jpk-force"
TIP = "parabolic:radius=1e-5"


def jpk_properties(path, member):
    """A Java properties member of a JPK archive as a dict, read here with zipfile."""
    with zipfile.ZipFile(path) as archive:
        text = archive.read(member).decode("latin-1")
    out = {}
    for line in text.splitlines():
        if line and not line.startswith("#") and "=" in line:
            key, value = line.split("=", 1)
            out[key.strip()] = value.strip().replace("\\:", ":")
    return out


def cli_fit(cli, *args):
    out = subprocess.run([cli, "fit", "--json", "-", *args], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


def test_load_gives_the_segments_as_arrays_with_the_files_calibration():
    curves = afm.load(SPOT3)
    assert len(curves) == 1
    curve = curves[0]
    assert curve.file == SPOT3 and curve.format == "jpk-force" and curve.label == ""
    assert curve.unreadable == ""
    assert [s.kind for s in curve.segments] == ["approach", "retract"]
    assert curve.segment_names == ["extend-spm", "retract-spm"]
    header = jpk_properties(SPOT3, "header.properties")
    assert curve.position == afm.MapPosition(
        float(header["force-scan-series.header.position.x"]),
        float(header["force-scan-series.header.position.y"]),
        int(header["force-scan-series.header.position-index"]))
    segment_header = jpk_properties(SPOT3, "segments/0/segment-header.properties")
    approach = curve.segment("approach")
    assert len(approach) == int(segment_header["force-segment-header.num-points"]) == 2000
    # The calibration as the file's shared header holds it, under the key it names.
    spring = curve.calibration["spring_constant"]
    sensitivity = curve.calibration["sensitivity"]
    shared = {**header, **jpk_properties(SPOT3, "segments/0/segment-header.properties")}
    for value in (spring, sensitivity):
        keys = [k for k in shared if k.endswith(value.source)]
        assert keys and float(shared[keys[0]]) == value.value
    assert curve.spring_constant == spring.value == 0.043493666407368466
    assert curve.calibration["approach_speed"].value == pytest.approx(5e-6, rel=1e-12)
    for name in ("tip_position", "force", "deflection", "time"):
        values = getattr(approach, name)
        assert isinstance(values, np.ndarray) and values.dtype == np.float64
        assert values.shape == (2000,) and np.isfinite(values).all()
    # The fit's rule: force = deflection x spring constant; tip position = height + deflection.
    np.testing.assert_allclose(approach.force, approach.deflection * curve.spring_constant,
                               rtol=1e-15)
    height = approach.measured_height if approach.measured_height is not None \
        else approach.piezo_height
    np.testing.assert_allclose(approach.tip_position, height + approach.deflection, rtol=0,
                               atol=1e-20)
    assert approach.time[0] == pytest.approx(0.0, abs=1e-9)


def test_a_map_loads_every_curve_with_its_position():
    curves = afm.load(f"{AFM}/fmt-jpk-fd_map-data-reference-points.jpk-force-map")
    assert len(curves) > 1
    assert all(c.position is not None for c in curves)
    assert len({(c.position.x, c.position.y) for c in curves}) == len(curves)
    assert all(c.label.startswith("index/") for c in curves)


def test_a_file_without_sensitivity_raises_the_readers_one_line(cli):
    path = f"{AFM}/fmt-jpk-cl_calibration_force-save-2015.02.04-11.25.21.294.jpk-force"
    with pytest.raises(mdrsim.SceneError) as caught:
        afm.load(path)
    message = str(caught.value)
    assert "\n" not in message and message.startswith(path + ": ")
    out = subprocess.run([cli, "fit", path, "--tip", TIP], capture_output=True, text=True)
    assert out.returncode == 2 and message in out.stderr
    with pytest.raises(mdrsim.SceneError, match="unknown kind of file '.toml'"):
        afm.load("scenes/fig2_fixed_load.toml")


@pytest.mark.parametrize("options, args", [
    ({}, []),
    ({"fix": {"baseline_slope": 0.0}}, ["--fix", "baseline_slope=0"]),
    ({"model": "jkr", "segment": "retract"}, ["--model", "jkr", "--segment", "retract"]),
    ({"model": "dmt", "segment": "retract", "poisson_ratio": 0.3},
     ["--model", "dmt", "--segment", "retract", "--poisson-ratio", "0.3"]),
    ({"model": "maugis", "segment": "retract", "fix": {"maugis_parameter": 1.0}},
     ["--model", "maugis", "--segment", "retract", "--fix", "maugis_parameter=1"]),
    ({"model": "auto", "segment": "retract"}, ["--model", "auto", "--segment", "retract"]),
])
def test_the_python_fit_is_the_commands_json_to_the_last_digit(cli, options, args):
    fit = afm.fit(afm.load(SPOT3)[0], tip=TIP, **options)
    [theirs] = cli_fit(cli, SPOT3, "--tip", TIP, *args)
    assert fit.to_dict() == theirs  # floats compared exactly: the same binary64 values
    assert json.dumps(fit.to_dict()) == json.dumps(theirs)


def test_the_fit_of_nanites_curve_and_its_plotting_arrays():
    # The numbers of docs/afm.md's walk-through (the engine's Hertz fit; nanite: 14741.96 Pa).
    fit = afm.fit(afm.load(SPOT3)[0], model="hertz", tip=TIP, poisson_ratio=0.5,
                  fix={"baseline_slope": 0.0})
    assert fit.status == "fitted" and fit.message == ""
    assert fit.youngs_modulus.value == pytest.approx(14741.907782, rel=1e-9)
    assert fit.youngs_modulus.value == pytest.approx(14741.96, rel=1e-3)  # nanite's test
    assert fit.contact_point.value == pytest.approx(1.80293102e-05, abs=1e-12)
    assert fit.baseline_slope.fixed and fit.baseline_slope.standard_error == 0.0
    assert fit.points == 2000 and fit.tip_position_from == "measured_height"
    assert fit.tip_position.shape == fit.force.shape == fit.fitted_force.shape == (2000,)
    # The fitted curve is the model at the fitted values: its rms is the fit's own.
    rms = np.sqrt(np.mean((fit.fitted_force - fit.force) ** 2))
    assert rms == pytest.approx(fit.residual_rms, rel=1e-9)
    np.testing.assert_allclose(fit.indentation, fit.contact_point.value - fit.tip_position)


def test_a_fit_it_cannot_vouch_for_carries_the_commands_warnings(cli):
    # The cell's retract under JKR: the tethers' pull taken as the contact branch leaves a short
    # baseline and a residual above twice the noise; nanite's Hertz case has none.
    assert afm.fit(afm.load(SPOT3)[0], tip=TIP).warnings == []
    fit = afm.fit(afm.load(SPOT3)[0], model="jkr", tip=TIP, segment="retract")
    [theirs] = cli_fit(cli, SPOT3, "--tip", TIP, "--model", "jkr", "--segment", "retract")
    assert fit.warnings == theirs["warnings"]
    assert [w.split(":")[0] for w in fit.warnings] == [
        "short baseline", "the model does not describe the curve"]


@pytest.mark.parametrize("model", ["dmt", "jkr"])
def test_the_adhesive_fits_curve_follows_the_data(model):
    fit = afm.fit(afm.load(SPOT3)[0], model=model, tip=TIP, segment="retract")
    assert fit.status in ("fitted", "not-converged")
    rms = np.sqrt(np.mean((fit.fitted_force - fit.force) ** 2))
    # The JKR branch is sampled anew for the plot (256 contact radii, one Newton step per
    # depth): the same residual to well within 1 %.
    assert rms == pytest.approx(fit.residual_rms, rel=1e-2)


@pytest.mark.parametrize("kwargs, line", [
    ({"model": "hertzz"}, "model 'hertzz': unknown (known: hertz, dmt, jkr, maugis, auto)"),
    ({"tip": "parabolic:radius=-1"}, None),
    ({"tip": "pyramid"}, None),
    ({"fix": {"youngs_modulu": 1.0}},
     "fix youngs_modulu: unknown (known: youngs_modulus, work_of_adhesion, maugis_parameter, "
     "contact_point, baseline_offset, baseline_slope)"),
    ({"fix": {"maugis_parameter": 1.0}}, "fix maugis_parameter: not a parameter of model 'hertz'"),
    ({"fix": {"work_of_adhesion": 0.1}}, "fix work_of_adhesion: not a parameter of model 'hertz'"),
    ({"fix": {"spring_constant": 0.1}},
     "fix spring_constant: a calibration, given when the file is read "
     "(mdrsim.afm.load(path, spring_constant=...))"),
    ({"fix": {"youngs_modulus": -5.0}}, "fix youngs_modulus: must be > 0"),
    ({"fix": {"contact_point": "x"}}, "fix contact_point: 'x' is not a number"),
    ({"segment": "both"}, "segment 'both': unknown (known: approach, retract)"),
    ({"poisson_ratio": 0.7}, "poisson_ratio 0.7: outside (-1, 0.5]"),
    ({"model": "dmt", "tip": "cone:half_angle_deg=35"}, None),
])
def test_bad_arguments_raise_one_clear_line(kwargs, line):
    curve = afm.load(SPOT3)[0]
    with pytest.raises(mdrsim.SceneError) as caught:
        afm.fit(curve, **{"tip": TIP, **kwargs})
    message = str(caught.value)
    assert "\n" not in message and message
    if line is not None:
        assert message == line


def test_a_tip_refused_by_python_is_refused_by_the_command_with_the_same_words(cli):
    with pytest.raises(mdrsim.SceneError) as caught:
        afm.fit(afm.load(SPOT3)[0], tip="pyramid")
    out = subprocess.run([cli, "fit", SPOT3, "--tip", "pyramid"], capture_output=True, text=True)
    assert out.returncode == 2 and str(caught.value) in out.stderr


def test_calibration_given_to_load_is_the_commands_fix(cli):
    curve = afm.load(SPOT3, spring_constant=0.05)[0]
    assert curve.spring_constant == 0.05
    fit = afm.fit(curve, tip=TIP)
    [theirs] = cli_fit(cli, SPOT3, "--tip", TIP, "--fix", "spring_constant=0.05")
    assert fit.to_dict() == theirs


def test_fit_wants_a_curve():
    with pytest.raises(TypeError, match="mdrsim.afm.Curve"):
        afm.fit(SPOT3)


def test_the_stubs_name_what_the_module_has():
    import ast
    from pathlib import Path
    tree = ast.parse((Path(afm.__file__).parent / "afm.pyi").read_text())
    functions = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
    assert functions == {"load", "fit", "fit_files"}
    curve = afm.load(SPOT3)[0]
    fit = afm.fit(curve, model="jkr", tip=TIP, segment="retract")  # every field, position too
    instances = {"Curve": curve, "Segment": curve.segments[0], "Fit": fit,
                 "FitParameter": fit.youngs_modulus, "Calibrated": curve.calibration["spring_constant"],
                 "MapPosition": curve.position}
    classes = {n.name: n for n in tree.body if isinstance(n, ast.ClassDef)}
    assert set(classes) == set(instances)
    assert set(afm.__all__) == set(classes) | functions
    for name, node in classes.items():
        for member in node.body:
            attribute = getattr(member, "name", None) or getattr(getattr(member, "target", None),
                                                                 "id", None)
            if attribute and attribute not in ("__init__", "__len__"):
                assert hasattr(instances[name], attribute), f"{name}.{attribute}"


STUDY = [SPOT3, f"{AFM}/fmt-jpk-cl_calibration_force-save-2015.02.04-11.25.21.294.jpk-force",
         f"{AFM}/fmt-jpk-fd_map-data-reference-points.jpk-force-map",
         f"{AFM}/fmt-igor-fd_SiN_FD_plot.ibw"]


def test_fit_files_gives_the_commands_objects_in_order_past_a_bad_file(cli):
    # The command refuses the calibration file (no sensitivity) with exit 2; fit_files gives it
    # its status and goes on, every other curve's object equal to the command's.
    documents = afm.fit_files(STUDY, tip=TIP, fix={"baseline_slope": 0.0})
    assert [d["file"] for d in documents] == [STUDY[0], STUDY[1]] + [STUDY[2]] * 3 + [STUDY[3]]
    bad = documents[1]
    assert bad["status"] == "unreadable" and "no sensitivity" in bad["message"]
    good = [d for i, d in enumerate(documents) if i != 1]
    theirs = cli_fit(cli, STUDY[0], STUDY[2], STUDY[3], "--tip", TIP, "--fix", "baseline_slope=0",
                     "--threads", "1")
    assert good == theirs


def test_fit_files_on_a_process_pool_is_the_same(cli):
    from concurrent.futures import ProcessPoolExecutor
    with ProcessPoolExecutor(2) as pool:
        on_pool = afm.fit_files(STUDY, executor=pool, tip=TIP, model="jkr", segment="retract")
    assert on_pool == afm.fit_files(STUDY, tip=TIP, model="jkr", segment="retract")


@pytest.mark.parametrize("kwargs, line", [
    ({"model": "hertzz"}, "model 'hertzz': unknown (known: hertz, dmt, jkr, maugis, auto)"),
    ({"modle": "jkr"}, "fit_files: unknown option 'modle' (known: model, tip, poisson_ratio, "
                       "segment, fix, sensitivity, spring_constant)"),
    ({"tip": "cone:half_angle_deg=70", "model": "dmt"}, "model 'dmt': not for a cone"),
])
def test_fit_files_refuses_bad_options_before_any_task(kwargs, line):
    class NoTasks:
        def submit(self, *args):
            raise AssertionError("a task was sent")
    options = {"tip": TIP, **kwargs}
    with pytest.raises(mdrsim.SceneError) as error:
        afm.fit_files(STUDY, executor=NoTasks(), **options)
    assert str(error.value).startswith(line)

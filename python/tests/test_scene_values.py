"""A Scene shows, changes and saves its values; reads the JSON `mdrsim run` reruns."""

import json
import subprocess

import pytest

import mdrsim

FIG2 = "scenes/fig2_fixed_load.toml"
CYCLE = "scenes/programs/jkr_cycle_glue_on_touch.toml"


def same_run(a, b):
    """Two scenes run to the same result, wall time aside."""
    x, y = mdrsim.run(a, trajectory=False).to_dict(), mdrsim.run(b, trajectory=False).to_dict()
    x.pop("wall_time_s"), y.pop("wall_time_s")
    return x == y


def test_set_is_with_values_and_checked_like_the_command():
    scene = mdrsim.Scene.from_file(FIG2).with_values({"discretization.springs": 500})
    changed = scene.set("material.poisson_ratio", 0.3)
    assert changed.overrides[-1] == ("material.poisson_ratio", "0.3")
    assert same_run(changed, scene.with_values({"material.poisson_ratio": 0.3}))
    assert scene.overrides == (("discretization.springs", "500"),)  # unchanged itself
    with pytest.raises(mdrsim.SceneError,
                       match=r"^--set: material.poisson_ratio = 0.7 is outside \(-1, 0.5\]$"):
        scene.set("material.poisson_ratio", 0.7)


@pytest.mark.parametrize("path", [FIG2, CYCLE])
def test_to_toml_reads_back_to_the_same_scene(path):
    scene = mdrsim.Scene.from_file(path).set("material.poisson_ratio", 0.3).set(
        "discretization.springs", 700)
    text = scene.to_toml()
    assert text.startswith(f"# From {path}\n#   --set material.poisson_ratio=0.3\n")
    assert "\npoisson_ratio = 0.3\n" in text and "\nsprings = 700\n" in text
    again = mdrsim.Scene.from_toml(text, name=path)
    assert again.to_dict() == scene.to_dict()
    assert same_run(again, scene)


def test_to_dict_has_the_values_the_file_gives_and_the_overrides():
    values = mdrsim.Scene.from_file(FIG2).set("material.poisson_ratio", 0.25).to_dict()
    assert values["material"] == {"youngs_modulus": 1.0e6, "poisson_ratio": 0.25,
                                  "work_of_adhesion": 0.05}
    assert values["loading"]["normal"] == {"control": "fixed-load"}
    assert values["discretization"] == {"springs": 10000, "extrapolation": "richardson"}
    # An exclusive key replaces the others of its group, as --set does.
    values = mdrsim.Scene.from_file(FIG2).set("discretization.rtol", 1e-3).to_dict()
    assert values["discretization"] == {"rtol": 1e-3, "extrapolation": "richardson"}


@pytest.mark.parametrize("suffix", [".toml", ".json"])
def test_save_writes_a_scene_the_command_and_from_file_read(tmp_path, suffix):
    scene = mdrsim.Scene.from_file(FIG2).set("discretization.springs", 600)
    path = tmp_path / f"saved{suffix}"
    scene.save(path)
    again = mdrsim.Scene.from_file(path)
    assert again.to_dict() == scene.to_dict()
    assert same_run(again, scene)


def test_repr_names_source_title_parts_and_overrides():
    scene = mdrsim.Scene.from_file(FIG2).set("discretization.springs", 600)
    assert repr(scene) == ("<mdrsim.Scene 'scenes/fig2_fixed_load.toml' 'Fig. 2: JKR pull-off, "
                           "fixed-load': parabolic profile, mode-mixed, 600 springs, "
                           "discretization.springs=600>")


def test_from_file_reads_a_result_json(tmp_path):
    scene = mdrsim.Scene.from_file(FIG2).set("discretization.springs", 800)
    result = mdrsim.run(scene, trajectory=False)
    path = tmp_path / "result.json"
    path.write_text(json.dumps(result.to_dict()))
    rerun = mdrsim.Scene.from_file(path)
    assert rerun.springs == 800 and rerun.title == scene.title
    assert same_run(rerun, scene)
    # Pickled as its text: a JSON scene too.
    import pickle
    assert same_run(pickle.loads(pickle.dumps(rerun)), scene)


def test_from_file_reads_the_commands_result_json(cli, tmp_path):
    path = tmp_path / "result.json"
    subprocess.run([cli, "run", FIG2, "--set", "discretization.springs=900", "--json", str(path),
                    "--log-level", "off"], check=True, capture_output=True)
    rerun = mdrsim.run(mdrsim.Scene.from_file(path), trajectory=False).to_dict()
    theirs = json.loads(path.read_text())
    rerun.pop("wall_time_s"), theirs.pop("wall_time_s")
    assert rerun == theirs

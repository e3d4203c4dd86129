"""The disk check from Python: Result.disk_valid, each State's, and the sweep's column, on the
wavy sphere whose strong ripple touches the surface again outside the preload's disk."""

import mdrsim

WAVY = "scenes/wavy_sphere.toml"


def wavy(amplitude):
    return mdrsim.Scene.from_file(WAVY).with_values({"profile.amplitude": amplitude,
                                                     "discretization.springs": 1000})


def test_a_strong_ripple_is_not_one_disk():
    result = mdrsim.run(wavy(1e-6), trajectory=False)
    assert result.disk_valid is False
    assert result.stages[0].end.disk_valid is False  # the preload's disk, a = 2 a0
    assert any("not one disk" in w for w in result.warnings)
    assert result.to_dict()["disk_valid"] is False


def test_a_gentle_ripple_is_one_disk():
    result = mdrsim.run(wavy(1e-8), trajectory=False)
    assert result.disk_valid is True
    assert all(stage.end.disk_valid for stage in result.stages)


def test_the_sweep_column_is_a_bool():
    rows = mdrsim.sweep(wavy(1e-8), {"profile.amplitude": [1e-8, 1e-6]}).rows
    assert [row["disk_valid"] for row in rows] == [True, False]

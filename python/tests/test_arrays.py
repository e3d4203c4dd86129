"""The trajectory's arrays are the engine's own buffers: no copy, owned through a capsule."""

import gc

import numpy as np
import pytest

import mdrsim

NUMERIC = ("in_cascade", "indentation", "normal_force", "contact_radius",
           "tangential_displacement", "tangential_force", "springs_in_contact", "normal_control")


@pytest.fixture
def result():
    return mdrsim.run(mdrsim.Scene.from_file("scenes/fig2_fixed_grips.toml").with_values(
        {"discretization.springs": 2000}))


def test_arrays_do_not_own_their_data_a_capsule_does(result):
    t = result.trajectory
    n = len(t["event"])
    assert n == len(t["stage"]) > 2000
    for name in NUMERIC:
        a = t[name]
        assert isinstance(a, np.ndarray) and a.shape == (n,), name
        assert not a.flags.owndata, name
        assert type(a.base).__name__ == "PyCapsule", name
        assert not a.flags.writeable, name
    assert t["normal_force"].dtype == np.float64
    assert t["springs_in_contact"].dtype == np.int64
    assert t["in_cascade"].dtype == np.bool_


def test_every_access_shares_the_same_memory(result):
    first, second = result.trajectory, result.trajectory
    for name in NUMERIC:
        assert first[name] is second[name]
        assert np.shares_memory(first[name], second[name])
        assert first[name].__array_interface__["data"][0] == \
            second[name].__array_interface__["data"][0]


def test_arrays_outlive_the_result():
    result = mdrsim.run(mdrsim.Scene.from_file("scenes/fig2_fixed_load.toml"))
    force = result.trajectory["normal_force"]
    expected = force.copy()
    del result
    gc.collect()
    mdrsim.run(mdrsim.Scene.from_file("scenes/fig2_fixed_load.toml"))  # reuses freed memory
    assert np.array_equal(force, expected)


def test_columns_hold_the_path(result):
    t = result.trajectory
    assert t["event"][0] == "preload" and t["stage"][0] == "preload"
    assert t["event"][-1] == "instability"
    assert set(t["stage"]) == {"preload", "pull-off"}  # no tangential load in Fig. 2
    detached = np.array([e == "detached" for e in t["event"]])
    assert np.all(np.diff(t["springs_in_contact"][detached]) <= 0)
    c = result.critical
    assert t["normal_force"][-1] == c.normal_force
    assert t["springs_in_contact"][-1] == c.springs_in_contact

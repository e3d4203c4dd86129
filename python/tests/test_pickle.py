"""A Result pickles with all its values, so that ProcessPoolExecutor.map(mdrsim.run, ...) works."""

import pickle
from concurrent.futures import ProcessPoolExecutor

import numpy as np

import mdrsim

FIG2 = "scenes/fig2_fixed_load.toml"
CYCLE = "scenes/programs/jkr_cycle_glue_on_touch.toml"


def test_a_result_pickles_with_its_values_and_trajectory():
    result = mdrsim.run(mdrsim.Scene.from_file(CYCLE).with_values({"discretization.springs": 500}))
    again = pickle.loads(pickle.dumps(result))
    for name in ("status", "title", "critical", "peak", "tangential_strength", "stages", "jumps",
                 "work", "warnings", "counts", "springs", "wall_time_s", "scales",
                 "dimensionless", "trajectory_rows_seen", "trajectory_stride"):
        assert getattr(again, name) == getattr(result, name), name
    assert again.to_dict() == result.to_dict()
    assert repr(again) == repr(result)
    t, u = result.trajectory, again.trajectory
    assert t.keys() == u.keys()
    for name, column in t.items():
        if isinstance(column, np.ndarray):
            assert np.array_equal(column, u[name]) and u[name].dtype == column.dtype, name
            assert not u[name].flags.writeable, name
        else:
            assert column == u[name], name
    assert pickle.loads(pickle.dumps(mdrsim.run(FIG2, trajectory=False))).trajectory is None


def test_process_pool_map_runs_scenes():
    scenes = [FIG2, mdrsim.Scene.from_file(FIG2).with_values({"discretization.springs": 2000})]
    with ProcessPoolExecutor(2) as pool:
        results = list(pool.map(mdrsim.run, scenes))
    assert [r.critical for r in results] == [mdrsim.run(s).critical for s in scenes]

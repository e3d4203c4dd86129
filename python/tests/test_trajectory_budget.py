"""mdrsim.run keeps at most a budget of trajectory rows: the special ones all, the others thinned."""

import pytest

import mdrsim

FIG2 = "scenes/fig2_fixed_load.toml"
CYCLE = "scenes/programs/jkr_cycle_glue_on_touch.toml"
ALWAYS = {"preload", "tangential", "stage-end", "instability"}  # CSV names of the kinds kept


def ranks(t):
    """Each row's rank as trajectory_recorder.hpp defines it, from the full trajectory."""
    n = len(t["event"])
    rank = [2 if e in ALWAYS else 1 if e == "jump" else 0 for e in t["event"]]
    for i in range(1, n):
        if t["in_cascade"][i] != t["in_cascade"][i - 1]:  # a cascade's two ends
            rank[i - 1], rank[i] = max(rank[i - 1], 1), max(rank[i], 1)
    rank[0] = rank[-1] = 2
    return rank


def held_rows(t, rank, stride):
    """The rows a budget keeps with `stride` on the ordinary rows (rank 1 not thinned)."""
    out, ordinal = [], 0
    for i, r in enumerate(rank):
        if r == 0:
            if ordinal % stride == 0:
                out.append(i)
            ordinal += 1
        else:
            out.append(i)
    return out


def test_default_budget_holds_at_most_trajectory_rows():
    springs = 300_000
    result = mdrsim.run(mdrsim.Scene.from_file(FIG2).with_values(
        {"discretization.springs": springs, "discretization.extrapolation": "none"}))
    t = result.trajectory
    n = len(t["event"])
    # The whole run gives the preload, one row per spring let go down to the critical point
    # (a = a0 = a_g / 2, eq. 19: springs / 2 of them), the let-go that starts the flight and
    # the instability: the fixed load's flight past the critical state has no rows (docs).
    assert result.trajectory_rows_seen == springs // 2 + 3
    assert mdrsim.TRAJECTORY_ROWS == 100_000
    assert n <= mdrsim.TRAJECTORY_ROWS
    # Thinned by halvings: a stride of 2 holds 75,000 ordinary rows, 1 would hold 150,001.
    assert result.trajectory_stride == 2
    assert n >= springs // 4
    assert (t["event"][0], t["event"][-1]) == ("preload", "instability")
    # The critical point is held: the equilibrium before the cascade, a cascade's end.
    critical = result.critical
    assert any(f == critical.normal_force and d == critical.indentation and not c
               for f, d, c in zip(t["normal_force"], t["indentation"], t["in_cascade"]))


def test_thinned_rows_are_the_full_trajectorys_rows_kept_by_rank():
    scene = mdrsim.Scene.from_file(CYCLE).with_values({"discretization.springs": 2000})
    full = mdrsim.run(scene).trajectory
    rank = ranks(full)
    special = sum(1 for r in rank if r > 0)
    budget = special + 100
    result = mdrsim.run(scene, trajectory=budget)
    t = result.trajectory
    stride = result.trajectory_stride
    assert result.trajectory_rows_seen == len(full["event"]) > budget
    assert stride > 1 and stride & (stride - 1) == 0
    kept = held_rows(full, rank, stride)
    assert len(t["event"]) == len(kept) <= budget
    # Half the stride would have passed the budget (thinning happens only then).
    assert len(held_rows(full, rank, stride // 2)) > budget
    for name in ("event", "stage"):
        assert t[name] == [full[name][i] for i in kept], name
    for name in ("in_cascade", "indentation", "normal_force", "contact_radius",
                 "tangential_displacement", "tangential_force", "springs_in_contact",
                 "normal_control"):
        assert t[name].tolist() == full[name][kept].tolist(), name
    assert {"stage-end", "jump"} <= set(t["event"])


def test_a_budget_above_the_rows_holds_them_all():
    scene = mdrsim.Scene.from_file(FIG2).with_values(
        {"discretization.springs": 500, "discretization.extrapolation": "none"})
    full = mdrsim.run(scene, trajectory=True)
    exact = mdrsim.run(scene, trajectory=253)  # 500 / 2 + 3 rows, as above
    assert exact.trajectory_stride == 1 and exact.trajectory_rows_seen == 253
    assert exact.trajectory["normal_force"].tolist() == full.trajectory["normal_force"].tolist()
    assert mdrsim.run(scene, trajectory=False).trajectory_rows_seen == 0


@pytest.mark.parametrize("bad", [0, -5, 2.5, "many"])
def test_a_bad_budget_is_refused(bad):
    with pytest.raises(ValueError, match="trajectory="):
        mdrsim.run(FIG2, trajectory=bad)

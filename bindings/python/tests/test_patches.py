"""Patches and intersections (docs/patches.md) through the binding: the
rule's defaults and checks, parallel sheets merged and unmerged, crossing
sheets reported as an intersection."""

import math

import numpy as np
import pytest

import proxima


def _sheet(n, side, facing_down):
    g = np.linspace(0.0, side, n + 1)
    x, y = np.meshgrid(g, g)
    positions = np.column_stack([x.ravel(), y.ravel(), np.zeros(x.size)])
    tris = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            b, c = a + 1, a + n + 1
            d = c + 1
            tris += [(a, d, b), (a, c, d)] if facing_down else [(a, b, d), (a, d, c)]
    return positions, np.array(tris, dtype=np.uint32)


@pytest.fixture
def sheets(world):
    floor = world.create_body(world.create_mesh(*_sheet(20, 0.02, False)), "static")
    tool = world.create_body(world.create_mesh(*_sheet(20, 0.02, True)), "tool",
                             pose=([0.0, 0.0, 0.001], [1.0, 0.0, 0.0, 0.0]))
    return floor, tool


def test_patch_settings_default_and_checked(world):
    s = world.patch_settings
    assert (s.radius_over_cutoff, s.max_angle_degrees, s.max_spread_over_cutoff) == (1.0, 5.0, 0.002)
    with pytest.raises(proxima.InvalidArgument, match="radiusOverCutoff"):
        world.patch_settings = (-1.0, 5.0, 0.002)
    with pytest.raises(proxima.InvalidArgument, match="maxAngleDegrees"):
        world.patch_settings = (1.0, 200.0, 0.002)
    with pytest.raises(proxima.InvalidArgument, match="maxSpreadOverCutoff"):
        world.patch_settings = (1.0, 5.0, -1.0)
    with pytest.raises(proxima.InvalidArgument, match="radius_over_cutoff"):
        world.patch_settings = ("wide", 5.0, 0.002)
    world.patch_settings = (0.5, 2.0, 0.01)
    assert world.patch_settings == proxima.PatchSettings(radius_over_cutoff=0.5, max_angle_degrees=2.0,
                                                         max_spread_over_cutoff=0.01)


def test_parallel_sheets_merge_and_can_be_left_unmerged(world, sheets):
    _, tool = sheets
    world.step()
    merged = world.patch_stats
    assert merged.lmds > 800 and 1 <= merged.patches <= 31
    assert merged.merged == merged.lmds - merged.patches and merged.largest_patch > 1
    c = tool.contacts()
    assert len(c) == merged.patches
    assert merged.intersecting_pairs == 0
    # Each contact's patch: the counts add up to the LMDs before merging, and
    # every patch keeps the rule (radius = the 5 mm cutoff, 0.2% of it, 5 deg).
    assert c["patch_count"].sum() == merged.lmds and c["patch_count"].max() == merged.largest_patch
    assert (c["patch_count"] >= 1).all()
    assert (c["patch_extent"] <= 0.005 + 1e-12).all() and (c["patch_spread"] <= 1e-5 + 1e-12).all()
    assert (c["patch_angle"] <= math.radians(5.0) + 1e-9).all()
    world.patch_settings = (0.0, 5.0, 0.002)
    world.step()
    unmerged = world.patch_stats
    assert unmerged.lmds == merged.lmds == unmerged.patches and unmerged.merged == 0
    c = tool.contacts()
    assert len(c) == unmerged.lmds
    assert (c["patch_count"] == 1).all() and (c["patch_extent"] == 0).all() and (c["patch_angle"] == 0).all()


def test_crossing_sheets_are_an_intersection(world, sheets):
    _, tool = sheets
    h = math.sqrt(0.5)
    tool.pose = ([0.0, 0.01, -0.01], [h, h, 0.0, 0.0])
    world.step()
    s = world.patch_stats
    assert s.intersecting_pairs >= 1 and s.intersecting_bodies == 1
    assert (tool.contacts()["distance"] > 0).all()


def test_leaf_budget_bounds_the_search_of_parallel_sheets(world, sheets):
    _, tool = sheets
    assert world.leaf_budget == 50000
    with pytest.raises(proxima.InvalidArgument, match="leaf_budget"):
        world.leaf_budget = -1
    with pytest.raises(proxima.InvalidArgument, match="leaf_budget"):
        world.leaf_budget = 1.5
    world.step()
    exact = world.patch_stats, world.search_stats, tool.contacts()
    assert exact[0].cut_node_pairs == 0
    world.leaf_budget = 100
    assert world.leaf_budget == 100
    world.step()  # the setting alone makes it search again
    cut = world.patch_stats, world.search_stats, tool.contacts()
    assert cut[0].cut_node_pairs > 0
    # At most 8 triangle pairs tried per cut node pair beyond the budget.
    assert cut[1].leaf_pairs <= 100 + 8 * cut[0].cut_node_pairs < exact[1].leaf_pairs
    assert 1 <= len(cut[2]) and cut[0].lmds < exact[0].lmds
    # The sheets are flat: the closest contact is as close as ever.
    assert cut[2]["distance"].min() == pytest.approx(exact[2]["distance"].min(), abs=1e-12)
    world.leaf_budget = 0  # no bound
    world.step()
    assert world.patch_stats.cut_node_pairs == 0 and world.patch_stats.lmds == exact[0].lmds

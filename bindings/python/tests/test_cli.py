"""The binding against the `proxima` command-line tool (a C API customer) on
the same scenes: every contact, force and torque equal to the last bit.

The tool's path comes from PROXIMA_CLI (scripts/test.sh sets it); without it
these tests fail, naming the variable."""

import json
import os
import subprocess

import numpy as np
import pytest

import proxima

from conftest import BUNNY, NEAR_POSE, box_centre

FEATURES = {"vertex": 0, "edge": 1, "face": 2}


@pytest.fixture(scope="module")
def cli():
    path = os.environ.get("PROXIMA_CLI")
    assert path and os.access(path, os.X_OK), (
        "PROXIMA_CLI must name the proxima command-line tool (build/release/samples/cli/proxima: "
        "cmake --build build/release --target proxima)")
    return path


def _pose_args(pose):
    p, q = pose
    return [repr(float(x)) for x in (*p, *q)]


def _run(cli, tmp_path, *args):
    out = tmp_path / "out.json"
    subprocess.run([cli, *args, "--json", str(out)], check=True, capture_output=True)
    return json.loads(out.read_text())


def _python_scene(method, force, cutoff, pose):
    w = proxima.World(method=method, cutoff=cutoff, force=force)
    m = w.load_mesh(BUNNY)
    w.create_body(m, "static")
    tool = w.create_body(m, "tool", pose=pose, reference_point=box_centre(m))
    return w, tool


@pytest.mark.parametrize("method, force, cutoff, pose", [
    ("precise", "hard", 0.005, ((0.14, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0))),
    ("precise", "hard", 0.005, NEAR_POSE),
    ("original", "hard", 0.005, NEAR_POSE),
    ("precise", "soft", 0.008, NEAR_POSE),
])
def test_contacts_equal_the_cli(cli, tmp_path, method, force, cutoff, pose):
    expected = _run(cli, tmp_path, "lmd", str(BUNNY), str(BUNNY), "--pose-b", *_pose_args(pose),
                    "--method", method, "--force", force, "--cutoff", repr(cutoff))
    w, tool = _python_scene(method, force, cutoff, pose)
    with w:
        w.step()
        c = tool.contacts()
        lmds = expected["lmds"]
        assert len(lmds) > 0 and len(c) == len(lmds)
        for row, lmd in zip(c, lmds):
            assert row["triangle_other"] == lmd["tri_a"] and row["triangle_tool"] == lmd["tri_b"]
            assert row["point_other"].tolist() == lmd["point_a"]
            assert row["point_tool"].tolist() == lmd["point_b"]
            assert row["distance"] == lmd["distance"]
            assert row["feature_other"] == FEATURES[lmd["feature_a"]]
            assert row["feature_tool"] == FEATURES[lmd["feature_b"]]
            assert row["patch_count"] == lmd["patch_count"] and row["patch_extent"] == lmd["patch_extent"]
            assert row["patch_spread"] == lmd["patch_spread"] and row["patch_angle"] == lmd["patch_angle"]
        assert c["distance"].min() == expected["min_distance"]
        force_, torque, _ = tool.wrench()
        assert force_.tolist() == expected["force"] and torque.tolist() == expected["torque"]
        s = w.search_stats
        assert s.candidates == expected["stats"]["candidates"]
        assert s.node_pairs == expected["stats"]["node_pairs"]
        assert s.distance_evaluations == expected["stats"]["distance_evaluations"]


def test_intersections_equal_the_cli(cli, tmp_path):
    pose = ((0.12, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0))
    expected = _run(cli, tmp_path, "polylines", str(BUNNY), str(BUNNY), "--pose-b", *_pose_args(pose))
    w, tool = _python_scene("precise", "hard", 0.005, pose)
    with w:
        lines = tool.intersections()
        assert len(lines) == len(expected["polylines"]) > 0
        for (points, closed, _), line in zip(lines, expected["polylines"]):
            assert closed == line["closed"]
            assert points.tolist() == line["points"]
        stats = tool.intersection_stats
        assert stats.intersecting_pairs == expected["stats"]["intersecting_pairs"]
        assert stats.segments == expected["stats"]["segments"]

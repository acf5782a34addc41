"""The constrained tool (docs/coupling.md) through the binding: a unit cube's
small copy pushed into it by the deterministic step stays outside, and the
coupling pulls back."""

import numpy as np
import pytest

import proxima

from conftest import cube


def test_constrained_tool_stays_outside_and_pulls_back(world):
    v, t = cube()
    big = world.create_mesh(v * 0.02 - 0.01, t)
    small = world.create_mesh(v * 0.01 - 0.005, t)
    a = world.create_body(big)
    start = ((0.02, 0.001, 0.002), (1, 0, 0, 0))
    tool = world.create_body(small, "tool", pose=start, tool_mode="constrained")
    for i in range(150):
        tool.pose = ((max(0.007, 0.02 - 0.0001 * i), 0.001, 0.002), (1, 0, 0, 0))
        world.step()
        assert proxima.distance(a, tool) >= 0.0003 * (1 - 1e-6)
    position, _ = tool.pose
    proxy, _ = tool.proxy_pose
    assert position[0] == pytest.approx(0.007)  # the device
    assert proxy[0] > 0.015  # the proxy: outside A's face at x = 0.01
    force, _, _ = tool.wrench()
    assert force[0] > 1.0 and np.linalg.norm(force) <= 3.0 + 1e-9


def test_a_free_tools_proxy_is_its_pose(world):
    v, t = cube()
    tool = world.create_body(world.create_mesh(v, t), "tool", pose=((1, 2, 3), (1, 0, 0, 0)))
    position, rotation = tool.proxy_pose
    assert np.array_equal(position, [1, 2, 3]) and np.array_equal(rotation, [1, 0, 0, 0])


def test_bad_tool_mode_and_coupling_are_refused_by_name(world):
    v, t = cube()
    mesh = world.create_mesh(v, t)
    with pytest.raises(proxima.InvalidArgument, match="tool_mode"):
        world.create_body(mesh, "tool", tool_mode="sticky")
    with pytest.raises(proxima.InvalidArgument, match="coupling"):
        world.create_body(mesh, "tool", tool_mode="constrained", coupling=(1, 2))
    with pytest.raises(proxima.InvalidArgument, match="couplingStiffness"):
        world.create_body(mesh, "tool", tool_mode="constrained", coupling=(0, 2, 1, 0.002))
    with pytest.raises(proxima.InvalidArgument, match="PROX_BODY_TOOL"):
        world.create_body(mesh, "static", tool_mode="constrained")

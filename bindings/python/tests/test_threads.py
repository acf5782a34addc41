"""Proxima's own threads with the built-in scripted device (real threads, the bunny)."""

import time

import numpy as np
import pytest

import proxima

from conftest import BUNNY, box_centre


def _approach(steps=50):
    """The tool bunny from 20 mm to about 0.5 mm from the static one along +x."""
    xs = np.linspace(0.1592, 0.1392, steps)
    return np.column_stack([xs, np.zeros((steps, 2)), np.ones(steps), np.zeros((steps, 3))])


def _wait_for(predicate, seconds=5.0):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.01)
    return False


def test_threads_with_the_scripted_device(world, bunny):
    rock = world.create_body(bunny, "static")
    tool = world.create_body(bunny, "tool", pose=((0.16, 0, 0), (1, 0, 0, 0)), reference_point=box_centre(bunny))
    device = world.create_scripted_device(_approach(), seconds_per_pose=0.004, loop=False)
    tool.set_device(device)
    assert not world.thread_stats("haptic").running
    # The global search on two threads: the contacts are the same.
    world.start_threads(haptic_rate=1000, local_rate=1000, global_worker_count=2)
    try:
        assert world.thread_stats("haptic").running
        # The path takes 0.2 s; then the device holds the last pose.
        assert _wait_for(lambda: device.record.progress >= 49 and len(tool.contacts()) > 0)
        assert _wait_for(lambda: np.linalg.norm(tool.wrench()[0]) > 0)
        p, _ = tool.pose
        assert p[0] == pytest.approx(0.1392, abs=1e-9)
        with pytest.raises(proxima.Busy, match="proxWorld_Step"):
            world.step()
        # Meshes, bodies and tools come and go while the threads run, and a tool's mesh deforms.
        other = world.load_mesh(BUNNY)
        far = world.create_body(other, "static", pose=((0, 1, 0), (1, 0, 0, 0)))
        far.destroy()
        second = world.create_body(other, "tool", pose=((0, -1, 0), (1, 0, 0, 0)))
        other.set_vertices(other.triangles()[0] * 1.01)
        second.destroy()
        with pytest.raises(proxima.Busy):
            tool.pose = ((0.2, 0, 0), (1, 0, 0, 0))
        time.sleep(0.2)
    finally:
        world.stop_threads()
    haptic = world.thread_stats("haptic")
    assert not haptic.running and haptic.updates > 100 and haptic.target_rate == 1000
    assert haptic.achieved_rate > 0 and 0 < haptic.period_p50 <= haptic.period_max
    for name in ("local", "global"):
        assert world.thread_stats(name).updates > 0
    record = device.record
    assert record.reads > 100 and record.writes > 100 and record.all_finite
    assert record.max_force > 0 and record.max_force <= 3.0 + 1e-9
    assert isinstance(record.last_force, np.ndarray)
    assert world.safety_stats.torn_snapshots == 0
    # Stopped: the world steps again, at the pose the device left.
    world.step()
    assert len(tool.contacts()) > 0
    assert proxima.distance(rock, tool) == pytest.approx(tool.contacts()["distance"].min(), rel=1e-12)


def test_scripted_device_from_a_file(world, bunny, tmp_path):
    path = tmp_path / "poses.txt"
    path.write_text("# tx ty tz qw qx qy qz\n" + "\n".join(" ".join(repr(float(v)) for v in row) for row in _approach(10)))
    world.create_body(bunny, "static")
    tool = world.create_body(bunny, "tool", pose=((0.16, 0, 0), (1, 0, 0, 0)))
    device = world.load_scripted_device(path, seconds_per_pose=0.005, loop=True)
    tool.set_device(device)
    world.start_threads()
    try:
        assert _wait_for(lambda: device.record.reads > 50)
    finally:
        world.stop_threads()
    assert device.record.all_finite
    tool.set_device(None)
    tool.pose = ((0.3, 0, 0), (1, 0, 0, 0))  # no device holds it now


def test_device_less_tool_follows_set_pose(world, bunny):
    world.create_body(bunny, "static")
    tool = world.create_body(bunny, "tool", pose=((0.3, 0, 0), (1, 0, 0, 0)))
    world.start_threads()
    try:
        tool.pose = ((0.1392, 0, 0), (1, 0, 0, 0))
        assert _wait_for(lambda: len(tool.contacts()) > 0)
    finally:
        world.stop_threads()


def test_stopping_twice_and_closing_a_running_world(bunny):
    with proxima.World() as w:
        m = w.load_mesh(BUNNY)
        w.create_body(m, "static")
        w.create_body(m, "tool", pose=((0.14, 0, 0), (1, 0, 0, 0)))
        w.start_threads()
        assert w.thread_stats("global").running
    # Closing stopped the threads first; the world is gone.
    assert w.closed
    with pytest.raises(proxima.InvalidHandle):
        w.stop_threads()


def test_timing_settings_reach_the_haptic_loop(world, bunny):
    world.create_body(bunny, "static")
    world.create_body(bunny, "tool", pose=((0.14, 0, 0), (1, 0, 0, 0)))
    for timing in ("sleep", "spin"):
        world.start_threads(haptic_timing=timing, spin_margin=0.0002, haptic_priority=0, lock_memory=False)
        try:
            assert _wait_for(lambda: world.thread_stats("haptic").updates > 20)
        finally:
            world.stop_threads()
        stats = world.thread_stats("haptic")
        assert stats.timing == timing and stats.memory_locked is False and stats.realtime_priority == 0
        assert stats.period_p50 <= stats.period_p999 <= stats.period_max
        # What its sleeps waited on, by the header's name (the wheel is Linux's).
        assert stats.sleep_timer == "system"


def test_the_flight_recorder_keeps_what_the_device_was_handed(world, bunny):
    world.create_body(bunny, "static")
    tool = world.create_body(bunny, "tool", pose=((0.16, 0, 0), (1, 0, 0, 0)), reference_point=box_centre(bunny))
    device = world.create_scripted_device(_approach(), seconds_per_pose=0.004, loop=False)
    tool.set_device(device)
    assert len(tool.haptic_trace()) == 0, "never started: nothing recorded"
    world.start_threads(trace_capacity=4096)
    try:
        # Closed on the count: the path done and 300 ticks of holding.
        assert _wait_for(lambda: device.record.progress >= 49)
        held = device.record.writes
        assert _wait_for(lambda: device.record.writes > held + 300)
        running = tool.haptic_trace(64)
        assert len(running) == 64
        assert np.all(np.diff(running["tick"].astype(np.int64)) == 1)
    finally:
        world.stop_threads()
    trace = tool.haptic_trace()
    record = device.record
    assert trace.dtype == proxima.trace_dtype()
    assert len(trace) == record.writes, "every tick of the run, the fade-out included, in 4096"
    assert np.all(np.diff(trace["tick"].astype(np.int64)) == 1) and trace["tick"][0] == 0
    assert np.all(np.diff(trace["time"]) > 0)
    # The device pose is the scripted path's: x from 0.1592 down to 0.1392.
    x = trace["device_position"][:, 0]
    assert x.max() <= 0.1592 + 1e-12 and x.min() == pytest.approx(0.1392, abs=1e-12)
    np.testing.assert_allclose(np.linalg.norm(trace["device_rotation"], axis=1), 1.0, atol=1e-12)
    magnitude = np.linalg.norm(trace["force"], axis=1)
    assert magnitude.max() == pytest.approx(record.max_force, abs=1e-12)
    step = np.abs(np.diff(trace["force"], axis=0)).max()
    assert step <= record.max_force_step + 1e-12
    assert magnitude[-1] == 0.0 and proxima.has_flag(trace, "stopping")[-1]
    assert proxima.has_flag(trace, "faded")[-1]
    assert trace["contact_count"][np.argmax(magnitude)] > 0
    with pytest.raises(ValueError):
        tool.haptic_trace(-1)

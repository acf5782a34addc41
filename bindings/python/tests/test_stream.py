"""The streamed device: poses pushed from a Python thread, rendered by the
haptic loop in C (real threads, the bunny)."""

import math
import threading
import time

import numpy as np
import pytest

import proxima

from conftest import box_centre
from test_threads import _wait_for


def test_get_time_is_monotonic_seconds():
    a = proxima.get_time()
    time.sleep(0.02)
    b = proxima.get_time()
    assert 0.015 < b - a < 1.0


def test_poses_pushed_from_a_python_thread_move_the_tool(world, bunny):
    rock = world.create_body(bunny, "static")
    tool = world.create_body(bunny, "tool", pose=((0.2, 0, 0), (1, 0, 0, 0)), reference_point=box_centre(bunny))
    hand = world.create_stream_device(mode="interpolate", delay=1 / 90)
    tool.set_device(hand)
    world.start_threads()
    stop = threading.Event()
    felt = []

    def push():
        # A 90 Hz frame loop: from 20 mm to about 0.5 mm apart in 0.3 s, then held.
        start = proxima.get_time()
        while not stop.is_set():
            t = proxima.get_time()
            x = 0.1592 - 0.02 * min((t - start) / 0.3, 1.0)
            hand.push_pose((x, 0, 0), (1, 0, 0, 0), t)
            felt.append(np.linalg.norm(hand.wrench()[0]))  # any thread
            time.sleep(1 / 90)

    pusher = threading.Thread(target=push)
    pusher.start()
    try:
        assert _wait_for(lambda: len(tool.contacts()) > 0 and np.linalg.norm(hand.wrench()[0]) > 0.1)
        assert _wait_for(lambda: abs(tool.pose[0][0] - 0.1392) < 1e-6)
        force, torque, clipped = hand.wrench()
        assert force.shape == (3,) and force[0] > 0  # pushes the tool away, along +x
    finally:
        stop.set()
        pusher.join()
        world.stop_threads()
    assert max(felt) > 0.1
    s = hand.stats
    assert s.samples_pushed > 20 and s.samples_refused == 0 and s.reads > 100
    assert 0.005 < s.mean_sample_interval < 0.05
    haptic = world.thread_stats("haptic")
    assert haptic.updates > 100 and world.safety_stats.torn_snapshots == 0
    world.step()
    assert proxima.distance(rock, tool) == pytest.approx(0.0005, rel=0.2)


def test_stream_modes_and_settings(world, bunny):
    for mode in ("hold", "interpolate", "extrapolate"):
        assert isinstance(world.create_stream_device(mode=mode), proxima.StreamDevice)
    world.create_stream_device(mode="extrapolate", max_extrapolation=0.01, stale_after=0.1, delay=0)
    with pytest.raises(proxima.InvalidArgument, match="mode must be one of 'hold', 'interpolate', 'extrapolate'"):
        world.create_stream_device(mode="predict")
    with pytest.raises(proxima.InvalidArgument, match="unknown setting 'latency'; the settings are delay"):
        world.create_stream_device(latency=0.01)
    with pytest.raises(proxima.InvalidArgument, match="delay"):
        world.create_stream_device(delay=-1)
    with pytest.raises(proxima.InvalidArgument, match="stale_after must be a number"):
        world.create_stream_device(stale_after="soon")


def test_stream_misuse(world, bunny):
    hand = world.create_stream_device()
    now = proxima.get_time()
    with pytest.raises(proxima.InvalidArgument, match="not finite|non-finite"):
        hand.push_pose((math.nan, 0, 0), (1, 0, 0, 0), now)
    with pytest.raises(proxima.InvalidArgument, match="zero quaternion"):
        hand.push_pose((0, 0, 0), (0, 0, 0, 0), now)
    with pytest.raises(proxima.InvalidArgument):
        hand.push_pose((0, 0, 0), (1, 0, 0, 0), -1.0)
    with pytest.raises(proxima.InvalidArgument, match="push_pose: t must be a number"):
        hand.push_pose((0, 0, 0), (1, 0, 0, 0), "now")
    with pytest.raises(proxima.InvalidArgument, match="push_pose position must be 3 numbers"):
        hand.push_pose((0, 0), (1, 0, 0, 0))
    hand.push_pose((0, 0, 0), (1, 0, 0, 0), now)
    hand.push_pose((0, 0, 0), (1, 0, 0, 0), now)  # no newer: dropped, not an error
    hand.push_pose((0, 0, 0), (2, 0, 0, 0))  # default time: now; normalised
    s = hand.stats
    assert (s.samples_pushed, s.samples_dropped, s.samples_refused) == (2, 1, 3)
    with proxima.World() as other:
        foreign = other.create_stream_device()
        tool = world.create_body(bunny, "tool")
        with pytest.raises(proxima.InvalidArgument, match="belongs to another world than this body"):
            tool.set_device(foreign)
        with pytest.raises(proxima.InvalidArgument, match="belongs to another world than this body"):
            tool.set_device(other.create_scripted_device([((0, 0, 0), (1, 0, 0, 0))], 0.1))
    with pytest.raises(proxima.InvalidHandle):
        foreign.push_pose((0, 0, 0), (1, 0, 0, 0))
    with pytest.raises(proxima.InvalidHandle):
        foreign.wrench()
    with pytest.raises(proxima.InvalidHandle):
        foreign.stats


def test_a_destroyed_device_lets_its_tool_fade_and_its_id_goes(world, bunny):
    world.create_body(bunny, "static")
    tool = world.create_body(bunny, "tool", pose=((0.1592, 0, 0), (1, 0, 0, 0)), reference_point=box_centre(bunny))
    hand = world.create_stream_device(mode="hold")
    tool.set_device(hand)
    world.start_threads()
    stop = threading.Event()

    def push():
        while not stop.is_set():
            try:
                hand.push_pose((0.1392, 0, 0), (1, 0, 0, 0))
            except proxima.InvalidHandle:
                return  # destroyed under this thread: the push is refused by name
            time.sleep(0.005)

    pusher = threading.Thread(target=push)
    pusher.start()
    try:
        assert _wait_for(lambda: np.linalg.norm(tool.wrench()[0]) > 0.01), "no force in contact"
        assert hand.valid
        hand.destroy()
        assert not hand.valid
        # The tool has no pose from then on: its force fades to exactly zero.
        assert _wait_for(lambda: np.linalg.norm(tool.wrench()[0]) == 0.0), "the force did not fade"
    finally:
        stop.set()
        pusher.join()
        world.stop_threads()
    with pytest.raises(proxima.InvalidHandle, match="destroyed"):
        hand.push_pose((0, 0, 0), (1, 0, 0, 0))
    with pytest.raises(proxima.InvalidHandle):
        hand.destroy()
    scripted = world.create_scripted_device([((0.2, 0, 0), (1, 0, 0, 0))], 0.1)
    assert scripted.valid
    scripted.destroy()
    assert not scripted.valid
    with pytest.raises(proxima.InvalidHandle, match="scripted device"):
        scripted.record

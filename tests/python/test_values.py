"""Joystick scaling against the formula of onetip/joystick_axes.hpp, and the
simulated sensor's frames as numpy arrays."""
import numpy as np
import pytest

import onetip


def test_joystick_and_spnav_axes_follow_the_documented_formula():
    ranges = onetip.default_axis_ranges()
    np.testing.assert_array_equal(ranges, [[-4, 4], [-4, 4], [0, 3], [-40, 40], [-40, 40], [-15, 15]])
    dx, dy, dz, yaw, pitch, roll = 1.0, -5.0, 1.2, 7.5, -10.0, 20.0
    axes = np.array([dx, dy, dz, pitch, roll, yaw])  # x, y, z, rx, ry, rz
    lo, hi = ranges[:, 0], ranges[:, 1]
    expected_joy = np.round((2 * (np.clip(axes, lo, hi) - lo) / (hi - lo) - 1) * 32767)
    expected_spnav = np.round(np.clip(axes / np.maximum(abs(lo), abs(hi)), -1, 1) * 350)
    inputs = [dx, dy, dz, yaw, pitch, roll]
    assert onetip.joystick_axes(inputs) == list(expected_joy.astype(int))
    assert onetip.spnav_axes(np.array(inputs)) == list(expected_spnav.astype(int))
    with pytest.raises(onetip.InputError):
        onetip.joystick_axes(inputs, ranges=[[1, 2]] * 6)  # does not contain 0


def test_simulated_frames_are_numpy_arrays(press_scenario):
    sim = onetip.SimulatedSensor(str(press_scenario), frames=2)
    assert sim.frame_count == 2
    frame = sim.next()
    assert frame.image.dtype == np.uint8 and frame.image.ndim == 2 and frame.image.std() > 10
    assert frame.markers.shape[1] == 4 and len(frame.markers) >= 100
    np.testing.assert_array_equal(frame.markers[:, 0], np.arange(len(frame.markers)))
    assert not frame.contact and np.array_equal(frame.truth, np.zeros(6))
    assert sim.next().index == 1 and sim.next() is None

"""Shared fixtures of the Python binding tests.

The environment (set by the ctest `python_bindings`, tests/python/CMakeLists.txt):
ONETIP_PYTHON_MODULE (the module built by this build), ONETIP_CLI (the `onetip`
program, the C++ reference) and ONETIP_SOURCE_DIR (the repository). `press` is
one lossless run of the press scenario, shared by the test files.
"""
import csv
import os
import subprocess
import threading
from pathlib import Path

import numpy as np
import pytest

import onetip


def _env_path(name):
    value = os.environ.get(name)
    if not value:
        pytest.fail(f"{name} is not set: run these tests through ctest (label python)")
    return Path(value)


@pytest.fixture(scope="session", autouse=True)
def built_module():
    """The module under test is the one this build made, not another on the path."""
    expected = _env_path("ONETIP_PYTHON_MODULE").resolve()
    assert Path(onetip.__file__).resolve() == expected
    return expected


@pytest.fixture(scope="session")
def press_scenario():
    return _env_path("ONETIP_SOURCE_DIR") / "samples" / "scenarios" / "press.yaml"


def write_scenario(folder, seconds, depth_mm=-0.3):
    """A short scenario: a finger held at depth_mm (negative: off the pad) for `seconds`."""
    path = Path(folder) / f"hold_{seconds}s.yaml"
    path.write_text(
        "%YAML:1.0\n---\nname: hold\nfps: 30\nindenters:\n  - shape: ellipsoid\n"
        "    semi_axes: [7, 9, 6]\n    keyframes:\n"
        f"      - {{t: 0.0, x: 0, y: 0, depth: {depth_mm}}}\n"
        f"      - {{t: {seconds}, depth: {depth_mm}}}\n")
    return path


class CliReference:
    """`onetip process` over a scenario: pose.csv rows and markers.csv rows by frame."""

    def __init__(self, pose_rows, marker_rows):
        self.pose = {int(r["frame"]): r for r in pose_rows}
        self.markers = {}
        for r in marker_rows:
            self.markers.setdefault(int(r["frame"]), []).append(
                [float(r["id"]), float(r["x"]), float(r["y"]), float(r["z"])])

    def raw(self, frame):
        r = self.pose[frame]
        return np.array([float(r[k]) for k in ("dx", "dy", "dz", "yaw", "pitch", "roll")])

    def sd(self, frame):
        """pose.csv's sd_dx .. sd_roll of the frame (mm, deg)."""
        r = self.pose[frame]
        return np.array([float(r["sd_" + k]) for k in ("dx", "dy", "dz", "yaw", "pitch", "roll")])

    def contact_frames(self):
        return sorted(f for f, r in self.pose.items() if r["contact"] == "1")


@pytest.fixture(scope="session")
def cli_reference(press_scenario, tmp_path_factory):
    work = tmp_path_factory.mktemp("cli")
    calib, pattern = work / "calib.yaml", work / "pattern.yaml"
    onetip.SimulatedSensor(str(press_scenario), render=False, frames=1).save_calibration(str(calib), str(pattern))
    pose, markers = work / "pose.csv", work / "markers.csv"
    subprocess.run([str(_env_path("ONETIP_CLI")), "process", "--calib", str(calib), "--pattern", str(pattern),
                    "--input", f"sim:{press_scenario}", "--out", str(pose), "--markers", str(markers), "--quiet"],
                   check=True, timeout=240)
    with open(pose, newline="") as p, open(markers, newline="") as m:
        return CliReference(list(csv.DictReader(p)), list(csv.DictReader(m)))


class PressRun:
    """One lossless run of the press scenario: events through a callback and
    through wait_event() at the same time, then every frame result."""

    def __init__(self, scenario):
        options = onetip.SensorOptions(lossless=True, event_queue_capacity=100000, frame_queue_capacity=1000)
        self.callback_events, self.callback_threads = [], set()
        self.polled_events, self.frames = [], []
        with onetip.Sensor(f"sim:{scenario}", options=options) as sensor:
            sensor.on_event(self._on_event)
            sensor.start()
            while (event := sensor.wait_event(5.0)) is not None:
                self.polled_events.append(event)
            assert sensor.wait_finished(60.0)
            while (frame := sensor.poll_frame()) is not None:
                self.frames.append(frame)
            self.stats = sensor.stats()

    def _on_event(self, event):
        self.callback_threads.add(threading.get_ident())
        self.callback_events.append(event)

    def of_type(self, kind):
        return [e for e in self.polled_events if e.type == kind]


@pytest.fixture(scope="session")
def press(press_scenario):
    return PressRun(press_scenario)

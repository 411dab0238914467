#!/usr/bin/python3
"""The windowed viewer on the virtual finger, driven by real X input events.

Starts a private Xvfb display, opens `onetip view --input sim:virtual
--windowed` on it (GLFW window, OpenGL 3.3 core through GLX on Mesa), and
drives the finger the way a person would, with XTest events from xdotool:
hold W (press), drag with the left button to the right (slide +x), hold E
(twist +yaw), then Esc (closes the window). The viewer's --pose-out log then
shows, frame by frame, the finger's commanded pose, the simulator's ground
truth and the 6-D input the pipeline measured from the rendered images.

Checks: each input moved its own axis of the finger, in order and in the
commanded direction (and no other axis); the measured dz, dx and yaw rose in
the phase that commanded them and agree with the ground truth; the window's
screenshot shows the camera frame and a pressed deformation field.

Exit 77 (ctest SKIP_RETURN_CODE) when Xvfb or xdotool is not installed
(.ci/install-deps.sh --tests installs both). Every wait has a timeout.
"""
import argparse
import csv
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

SKIP = 77
KEY_HOLD_S = 2.5        # W: 1.5 mm/s  -> about 3.7 mm deeper (from 0.5 mm above the pad), 3.5 mm at most
DRAG_STEPS, DRAG_PX, DRAG_STEP_S = 20, 5, 0.12   # 100 px at 0.02 mm/px -> 2 mm along S.x, in 2.4 s
TWIST_HOLD_S = 1.0      # E: 20 deg/s -> the 20 deg limit
# One frame moves the finger at most 0.25 mm / 2 deg (VirtualFingerOptions), so
# a slow run (sanitizers, a loaded machine) moves it less than the rates say;
# the lower bounds below still hold at 3 frames/s.
# The press is firm (at 3 frames/s the 0.25 mm step limit still takes the
# finger 1.4 mm deep; 3.3-3.5 mm on a fast machine) because a shallow contact
# slid fast slips as a whole at the slide's end and the estimate then stops
# short: 0.7-1.0 mm deep, drawn frames moving 0.14-0.4 mm left 0.2-0.7 mm of
# the slide unread in half the slides tried (an open limit of the estimator,
# docs/pose "Known limits", tests/data/scenarios/fast_shallow_slide.yaml).
# This test checks the window and its input path, not that limit; 1.2 mm deep
# and deeper, the slides tried read within 0.01 mm.
MIN_DEPTH_MM, MIN_SLIDE_MM, MIN_TWIST_DEG = 0.3, 0.5, 3.0
# The finger rests this long after the slide before it twists. A fast slide
# puts the pose estimator in gross slip, and it comes back only after its
# window (0.16 s of the simulator's 60 frames/s, 10 frames) of markers moving
# as one (docs/decisions/0004); a twist begun sooner is read as slip and its
# yaw held (an open limit of the estimator, docs/pose). 4 s is 12 frames at
# 3 frames/s, the slowest rate the bounds above allow.
REST_BEFORE_TWIST_S = 4.0


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def check(condition, message):
    if not condition:
        fail(message)
    print("ok: " + message)


def start_xvfb():
    """A fresh X display; returns (process, ':N')."""
    read_fd, write_fd = os.pipe()
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(write_fd), "-screen", "0", "1920x1080x24", "-nolisten", "tcp", "-noreset"],
                            pass_fds=[write_fd], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            start_new_session=True)
    os.close(write_fd)
    deadline = time.monotonic() + 15
    number = b""
    os.set_blocking(read_fd, False)
    while not number.endswith(b"\n"):
        if time.monotonic() > deadline or xvfb.poll() is not None:
            xvfb.kill()
            fail("Xvfb did not start within 15 s")
        try:
            chunk = os.read(read_fd, 16)
            number += chunk
            if not chunk:
                time.sleep(0.05)
        except BlockingIOError:
            time.sleep(0.05)
    os.close(read_fd)
    return xvfb, ":" + number.decode().strip()


def xdotool(env, *args, timeout=10):
    result = subprocess.run(["xdotool", *args], env=env, capture_output=True, text=True, timeout=timeout)
    if result.returncode != 0:
        fail("xdotool " + " ".join(args) + ": " + result.stderr.strip())
    return result.stdout.strip()


def drive_finger(env):
    """Press, slide, twist and close, as a person at the keyboard and mouse would."""
    window = xdotool(env, "search", "--sync", "--onlyvisible", "--name", "onetip view", timeout=30).split()[0]
    xdotool(env, "mousemove", "--window", window, "300", "300")  # the pointer over the window gives it the keys
    xdotool(env, "windowfocus", window)
    time.sleep(1.0)  # a few rest frames
    xdotool(env, "keydown", "w")
    time.sleep(KEY_HOLD_S)
    xdotool(env, "keyup", "w")
    time.sleep(0.5)
    xdotool(env, "mousedown", "1")
    for _ in range(DRAG_STEPS):
        xdotool(env, "mousemove_relative", "--", str(DRAG_PX), "0")
        time.sleep(DRAG_STEP_S)
    xdotool(env, "mouseup", "1")
    time.sleep(REST_BEFORE_TWIST_S)
    xdotool(env, "keydown", "e")
    time.sleep(TWIST_HOLD_S)
    xdotool(env, "keyup", "e")
    time.sleep(0.5)
    xdotool(env, "key", "Escape")


def first_frame(rows, predicate, what):
    for i, r in enumerate(rows):
        if predicate(r):
            return i
    fail("never: " + what)


def check_log(rows):
    f = lambda r, k: float(r[k])
    check(len(rows) >= 20, "the viewer drew %d frames" % len(rows))
    rest, last = rows[0], rows[-1]
    check(f(rest, "finger_depth") < 0 and rest["gt_contact"] == "0", "the finger starts lifted, out of contact")

    pressed = first_frame(rows, lambda r: f(r, "finger_depth") > MIN_DEPTH_MM, "W pressed the finger into the pad")
    slid = first_frame(rows, lambda r: f(r, "finger_x") > 0.05, "the left drag slid the finger")
    twisted = first_frame(rows, lambda r: f(r, "finger_yaw") > 0.5, "E twisted the finger")
    check(pressed < slid < twisted, "press (frame %d), slide (%d), twist (%d) came in the order sent" % (pressed, slid, twisted))
    before_slide, before_twist = rows[slid - 1], rows[twisted - 1]
    check(abs(f(before_slide, "finger_x")) < 1e-9 and abs(f(before_slide, "finger_yaw")) < 0.05,
          "pressing moved neither x nor yaw")
    check(abs(f(before_slide, "finger_depth") - f(last, "finger_depth")) < 1e-9, "sliding and twisting kept the depth")
    check(MIN_DEPTH_MM < f(last, "finger_depth") <= 3.5, "W held %.1f s: finger %.2f mm deep" % (KEY_HOLD_S, f(last, "finger_depth")))
    check(MIN_SLIDE_MM < f(last, "finger_x") <= 2.0 + 1e-6 and abs(f(last, "finger_y")) < 1e-9,
          "the %d px drag to the right: finger x %.2f mm (0.02 mm/px), y 0" % (DRAG_STEPS * DRAG_PX, f(last, "finger_x")))
    check(f(last, "finger_yaw") > MIN_TWIST_DEG, "E held %.1f s: finger yaw %.1f deg" % (TWIST_HOLD_S, f(last, "finger_yaw")))
    check(all(abs(f(r, "finger_pitch")) < 1e-9 and abs(f(r, "finger_roll")) < 1e-9 for r in rows),
          "no pitch or roll was commanded")

    # What the pipeline measured from the rendered images, phase by phase, against the simulator's truth.
    check(before_slide["contact"] == "1" and before_slide["gt_contact"] == "1", "the press made contact (measured and true)")
    check(f(before_slide, "dz") - f(rest, "dz") > MIN_DEPTH_MM,
          "measured dz rose with the press: %.2f mm" % f(before_slide, "dz"))
    check(f(before_twist, "dx") - f(before_slide, "dx") > MIN_SLIDE_MM - 0.3,
          "measured dx rose with the slide: %.2f -> %.2f mm" % (f(before_slide, "dx"), f(before_twist, "dx")))
    measured_twist = f(last, "yaw") - f(before_twist, "yaw")
    true_twist = f(last, "gt_yaw") - f(before_twist, "gt_yaw")
    # The pad slips under a twist of a degree or more per frame and the measured
    # yaw then stops short of the finger's (at 2 deg/frame: 2 to 8 deg for 16 to
    # 20): checked are the commanded sign, well above the noise (0.01 deg at
    # rest), and at most the finger's size.
    check(0.5 < measured_twist <= true_twist + 2,
          "measured yaw rose with the twist: %+.1f deg (finger %+.1f deg)" % (measured_twist, true_twist))
    for row, name, axes in ((before_slide, "after the press", ("dx", "dy", "dz", "yaw")),
                            (before_twist, "after the slide", ("dx", "dy", "dz", "yaw")),
                            (last, "after the twist", ("dx", "dy", "dz"))):
        for axis in axes:
            tolerance = 2.0 if axis == "yaw" else 0.3
            if abs(f(row, axis) - f(row, "gt_" + axis)) > tolerance:
                fail("%s: measured %s %.3f vs true %.3f" % (name, axis, f(row, axis), f(row, "gt_" + axis)))
    print("ok: measured dx, dy, dz (0.3 mm) and yaw (2 deg, before the twist) agree with the ground truth")


def check_screenshot(path):
    import numpy as np
    import matplotlib.image as image
    rgb = image.imread(path)[..., :3]
    check(rgb.shape[:2] == (720, 1280), "the screenshot is the 1280x720 window")
    camera, field = rgb[:360, :640], rgb[:360, 640:]
    check(camera.std() > 0.1, "the camera panel (top left) shows an image: spread %.2f" % camera.std())
    warm = np.count_nonzero((field[..., 0] > 0.6) & (field[..., 2] < 0.35))
    check(warm > 500, "the deformation field (top right) shows the press in warm colours: %d px" % warm)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True, help="the onetip program")
    args = parser.parse_args()
    missing = [tool for tool in ("Xvfb", "xdotool") if shutil.which(tool) is None]
    if missing:
        print("SKIP: %s not installed (.ci/install-deps.sh --tests installs xvfb and xdotool)" % " and ".join(missing))
        return SKIP

    work = tempfile.mkdtemp(prefix="onetip_window_test_")
    xvfb, display = start_xvfb()
    viewer = None
    try:
        env = {k: v for k, v in os.environ.items() if k != "WAYLAND_DISPLAY"}
        env["DISPLAY"] = display
        if "ASAN_OPTIONS" in env:
            # Sanitizer builds: Mesa's GLX/DRI driver leaves a few hundred bytes
            # behind from modules it unloads, which LeakSanitizer can neither name
            # nor suppress; leaks in the viewer's own code are checked by its
            # headless tests, which share everything but the GLFW window.
            env["ASAN_OPTIONS"] += ":detect_leaks=0"
        pose_csv, shot = os.path.join(work, "pose.csv"), os.path.join(work, "shot.png")
        viewer = subprocess.Popen([args.cli, "view", "--input", "sim:virtual", "--windowed", "--frames", "1500",
                                   "--pose-out", pose_csv, "--screenshot", shot],
                                  env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                  start_new_session=True)
        drive_finger(env)
        try:
            output, _ = viewer.communicate(timeout=20)
        except subprocess.TimeoutExpired:
            fail("the viewer did not close on Esc within 20 s")
        print(output.strip())
        check(viewer.returncode == 0, "the viewer exited cleanly (code %d)" % viewer.returncode)
        check("in a window" in output and "Core Profile" in output, "it drew in a window with an OpenGL core context")
        with open(pose_csv, newline="") as f:
            check_log(list(csv.DictReader(f)))
        check_screenshot(shot)
    finally:
        for process in (viewer, xvfb):  # asked to stop (Xvfb then removes its lock and socket), then killed
            if process is not None and process.poll() is None:
                os.killpg(process.pid, signal.SIGTERM)
                try:
                    process.wait(timeout=5)
                except subprocess.TimeoutExpired:
                    os.killpg(process.pid, signal.SIGKILL)
                    process.wait()
        shutil.rmtree(work, ignore_errors=True)
    print("window virtual finger test: passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())

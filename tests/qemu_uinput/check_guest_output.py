#!/usr/bin/python3
"""Checks what uinput_guest printed inside the qemu guest (run_qemu_uinput.sh).

The expected device layout and event stream are computed here, independently
of the C++ code, from the documented rules (sdk/src/os_outputs/axis_scaling.hpp
and joystick_encoder.hpp): ABS_X..ABS_RZ = dx, dy, dz, pitch, roll, yaw, the
working range dx, dy in [-4, 4] mm, dz in [0, 3] mm, pitch, roll in [-40, 40]
deg, yaw in [-15, 15] deg mapped linearly onto [-32767, 32767]; one button
BTN_TRIGGER; only changed axes are reported, then SYN_REPORT.
Exit 0 when everything matches, 1 otherwise (each mismatch is printed).
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "qemu"))
from guest_console import console_lines  # noqa: E402

EV_SYN, EV_KEY, EV_ABS = 0, 1, 3
BTN_TRIGGER = 0x120
BUS_VIRTUAL = 0x06
INPUT_PROP_ACCELEROMETER = 6
RANGES = [(-4, 4), (-4, 4), (0, 3), (-40, 40), (-40, 40), (-15, 15)]  # dx dy dz pitch roll yaw
FULL = 32767


def round_half_away(x):
    return int(math.copysign(math.floor(abs(x) + 0.5), x))


def joystick_axes(dx, dy, dz, yaw, pitch, roll):
    values = [dx, dy, dz, pitch, roll, yaw]
    out = []
    for v, (lo, hi) in zip(values, RANGES):
        v = min(max(v, lo), hi)
        out.append(round_half_away((2 * (v - lo) / (hi - lo) - 1) * FULL))
    return out


def expected_stream(publishes):
    rest = joystick_axes(0, 0, 0, 0, 0, 0)
    axes, down, stream = list(rest), False, []
    for kind, values in publishes:
        frame = []
        if kind == "input":
            target = joystick_axes(*values)
        elif kind == "contact_end":
            if down:
                frame.append((EV_KEY, BTN_TRIGGER, 0))
                down = False
            target = rest
        else:
            target = axes
            if kind == "press" and not down:
                frame.append((EV_KEY, BTN_TRIGGER, 1))
                down = True
            elif kind == "release" and down:
                frame.append((EV_KEY, BTN_TRIGGER, 0))
                down = False
        for code, (old, new) in enumerate(zip(axes, target)):
            if old != new:
                frame.append((EV_ABS, code, new))
        axes = list(target)
        if frame:
            stream += frame + [(EV_SYN, 0, 0)]
    return stream, rest


def main(path):
    lines = console_lines(path)
    failures = []

    def check(ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            failures.append(what)

    def field(prefix):
        return [l[len(prefix):].strip() for l in lines if l.startswith(prefix)]

    booted = field("BOOTED")
    check(bool(booted), "guest kernel booted: " + (booted[0] if booted else "no"))
    missing = field("MISSING-ERROR")
    check(bool(missing) and "/dev/uinput" in missing[0] and "does not exist" in missing[0],
          "before the module is loaded, open() names /dev/uinput: " + (missing[0] if missing else "no line"))
    check(bool(field("MODULE")), "uinput module loaded")
    errors = field("ERROR")
    check(not errors, "no guest errors " + "; ".join(errors))

    device = field("DEVICE")
    check(bool(device) and "name=onetip tactile joystick " in device[0] + " "
          and f"bustype={BUS_VIRTUAL} " in device[0] + " ", "device name and bus: " + (device[0] if device else ""))
    props = [int(p) for p in field("PROP")]
    check(INPUT_PROP_ACCELEROMETER not in props and not props, f"no input properties (got {props})")
    keys = [int(k) for k in field("KEY")]
    check(keys == [BTN_TRIGGER], f"keys == [BTN_TRIGGER] (got {keys})")

    publishes = []
    for p in field("PUBLISH"):
        parts = p.split()
        publishes.append((parts[0], [float(x) for x in parts[1:7]]))
    stream, rest = expected_stream(publishes)
    abs_lines = [[int(x) for x in a.split()] for a in field("ABS")]
    expected_abs = [[code, -FULL, FULL, rest[code], 0, 0] for code in range(6)]
    check(abs_lines == expected_abs, f"ABS_X..ABS_RZ in [-32767, 32767] at rest {rest} (got {abs_lines})")

    got = [tuple(int(x) for x in e.split()) for e in field("EVENT")]
    check(len(publishes) == 7 and got == stream,
          f"{len(got)} evdev events match the {len(stream)} expected from {len(publishes)} published events")
    if got != stream:
        print("  expected:", stream)
        print("  got:     ", got)
    final = [int(f.split()[1]) for f in field("FINAL")]
    check(final == rest, f"axes back at rest after contact end (got {final})")

    udev = field("UDEV ")
    check(any("ID_INPUT_JOYSTICK=1" in u for u in udev), "udev input_id: ID_INPUT_JOYSTICK=1")
    check(not any("ID_INPUT_ACCELEROMETER" in u for u in udev), "udev input_id: not an accelerometer")
    check(field("GUEST-EXIT") == ["0"] and bool(field("DONE")), "guest program finished")
    print(f"{len(failures)} failed" if failures else "all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

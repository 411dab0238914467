#!/usr/bin/python3
"""Checks what camera_guest printed inside the qemu guest (run_qemu_camera.sh).

  check_camera.py vivid LOG
  check_camera.py loopback LOG DIGEST
  check_camera.py record LOG WORK_DIR

The expectations come from the drivers' documented behaviour and from the
host, not from the guest's own code: vivid offers GREY and YUYV at 1920x1080
and 640x480, so the default request (docs/reference.md: 1920x1080, GREY
first) must pick GREY 1920x1080; frames are numbered without gaps, their
driver timestamps rise by the frame interval; pulling vivid's plug must be an
error event, the source's reconnection must fail while the module is unloaded
and succeed once it is back. For v4l2loopback, DIGEST (camera_frames digest)
holds each JPEG file's bytes and its folder-source frame, hashed on the host:
every file must arrive once and in order, byte for byte, and decode to the
same frame as the folder source gives. For the record drill, the live
`onetip process` run on the loopback camera and the host's run on the
recorded session must give the same pose.csv and markers.csv byte for byte,
the recorded files must equal the fed ones, and dz must follow the
simulator's truth. Prints the figures (frames received,
decode times, error and recovery times). Exit 0 when everything holds.
"""
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "qemu"))
from guest_console import console_lines  # noqa: E402


class Checker:
    def __init__(self, lines):
        self.lines, self.failures = lines, []

    def check(self, ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            self.failures.append(what)

    def field(self, prefix):
        return [l[len(prefix):].strip() for l in self.lines if l.startswith(prefix + " ") or l == prefix]

    def first(self, prefix):
        values = self.field(prefix)
        return values[0] if values else ""


def frames_between(lines, start, stop):
    """FRAME lines after the line starting with `start`, up to the one starting with `stop`."""
    out, inside = [], False
    for l in lines:
        if l.startswith(start):
            inside = True
        elif l.startswith(stop) and inside:
            break
        elif inside and l.startswith("FRAME "):
            p = l.split(" ", 9)
            out.append({"index": int(p[1]), "status": p[2], "t": float(p[3]), "w": int(p[4]), "h": int(p[5]),
                        "stddev": float(p[7]), "ms": float(p[8]), "message": p[9] if len(p) > 9 else ""})
    return out


def check_common(c):
    booted = c.first("BOOTED")
    c.check(bool(booted), "guest kernel booted: " + (booted or "no"))
    c.check(bool(c.field("MODULE")), "module loaded: " + c.first("MODULE"))
    errors = c.field("ERROR")
    c.check(not errors, "no guest errors " + "; ".join(errors))


def check_recovery(c, error_text):
    unplug = c.first("UNPLUG-EVENT").split(" ", 2)
    c.check(len(unplug) == 3 and unplug[1] == "error" and error_text in unplug[2],
            f"unplug mid-stream is an error event naming '{error_text}', after {unplug[0]} ms: "
            + (unplug[2] if len(unplug) == 3 else "none"))
    gone = c.first("WHILE-GONE")
    c.check(gone.startswith("error ") and "reconnection attempt 1 failed" in gone,
            "while the device is gone, the reconnection attempt is an error event: " + gone)
    recovered = c.first("RECOVERED").split()
    c.check(len(recovered) == 2, "frames again after the device came back: "
            + (f"{recovered[0]} ms after it returned, {recovered[1]} ms after the unplug" if recovered else "no"))
    return float(unplug[0]) if len(unplug) == 3 else None, recovered


def check_vivid(c):
    check_common(c)
    missing = c.first("MISSING-ERROR")
    c.check("/dev/video63" in missing and "cannot open" in missing, "a missing device is a clear error: " + missing)
    c.check(c.first("FORMAT-SMALL") == "YUYV 640 480 25.000", "640x480 YUYV negotiated: " + c.first("FORMAT-SMALL"))
    small = frames_between(c.lines, "FORMAT-SMALL", "RECEIVED-SMALL")
    small_ok = [f for f in small if f["status"] == "ok"]
    c.check(c.first("RECEIVED-SMALL") == "5" and all(f["w"] == 640 and f["h"] == 480 for f in small_ok),
            "5 YUYV frames decoded to 640x480 grey")
    fmt = c.first("FORMAT").split()
    c.check(fmt[:3] == ["GREY", "1920", "1080"], "default request: GREY 1920x1080 chosen: " + " ".join(fmt))
    frames = frames_between(c.lines, "FORMAT ", "RECEIVED ")
    want = int(c.first("WANT") or 30)
    ok = [f for f in frames if f["status"] == "ok"]
    c.check(int(c.first("RECEIVED") or -1) == want and len(ok) == len(frames) == want,
            f"{len(ok)} of {want} frames received, none skipped")
    c.check([f["index"] for f in frames] == list(range(len(frames))), "frame indices 0.. without gaps")
    steps = [b["t"] - a["t"] for a, b in zip(frames, frames[1:])]
    period = 1.0 / float(fmt[3]) if len(fmt) == 4 and float(fmt[3]) > 0 else 0
    median_step = statistics.median(steps) if steps else 0
    c.check(bool(steps) and min(steps) > 0 and abs(median_step - period) < 0.1 * period,
            f"driver timestamps rise, median step {median_step * 1000:.1f} ms (frame interval {period * 1000:.1f} ms)")
    c.check(all(f["w"] == 1920 and f["h"] == 1080 and f["stddev"] > 4 for f in ok),
            "every frame 1920x1080 and not blank (stddev > 4 grey levels)")
    c.check(c.first("UNPLUG").endswith(" 0"), "vivid's Disconnect control set: " + c.first("UNPLUG"))
    c.check(c.first("UNLOAD") == "0" and c.first("RELOAD").startswith("0 "), "vivid unloaded, then loaded again")
    latency, recovered = check_recovery(c, "No such device")
    c.check(c.first("RECEIVED-AFTER") == "5", "5 more frames after the recovery")
    c.check(c.first("FORMAT-AFTER") == c.first("FORMAT"), "the same format after the recovery")
    counters = c.first("COUNTERS").split()
    c.check(counters == [str(want + 6), "0", "2"],
            f"counters: {want + 6} delivered, 0 skipped, 2 error events (got {counters})")
    c.check(c.field("GUEST-EXIT") == ["0"], "guest program finished")
    print(f"FIGURES vivid: {len(ok)} frames GREY 1920x1080 at {fmt[3] if len(fmt) == 4 else '?'} fps, "
          f"error event {latency} ms after the unplug, first frame "
          f"{recovered[0] if recovered else '?'} ms after the device returned")


def check_loopback(c, digest_path):
    check_common(c)
    digest = []
    with open(digest_path) as f:
        for line in f:
            name, payload, grey, status = line.split()
            digest.append((name, payload, grey, status))
    c.check(bool(digest) and all(d[3] == "ok" for d in digest), f"host folder source read {len(digest)} JPEG files")
    c.check(c.first("FORMAT").split()[:3] == ["MJPG", "1920", "1080"],
            "MJPEG 1920x1080 negotiated: " + c.first("FORMAT"))
    c.check(c.first("KEEP-ENCODED") == "1", "the source keeps the MJPEG payloads")
    rows = []
    for l in c.field("MJPEG"):
        p = l.split()
        rows.append({"index": int(p[0]), "file": int(p[1]), "bytes": int(p[2]), "payload": p[3], "grey": p[4],
                     "decode_ms": float(p[5]), "same": p[6] == "1"})
    matched = [r for r in rows if r["file"] >= 0]
    # v4l2loopback hands a reader that is faster than the producer the last
    # frame again (seen under the sanitizers, where the producer is slow): an
    # identical payload right after itself is a repeat, not a new frame.
    repeats = sum(1 for a, b in zip(matched, matched[1:]) if a["file"] == b["file"] and a["payload"] == b["payload"])
    fresh = [r for k, r in enumerate(matched)
             if k == 0 or not (r["file"] == matched[k - 1]["file"] and r["payload"] == matched[k - 1]["payload"])]
    c.check([r["file"] for r in fresh] == list(range(len(digest))),
            f"every file arrived once and in order, byte for byte ({len(fresh)} of {len(digest)}, "
            f"{repeats} repeated by the driver)")
    c.check(all(r["payload"] == digest[r["file"]][1] for r in matched), "payload hashes equal the files'")
    c.check(all(r["grey"] == digest[r["file"]][2] for r in matched),
            "every decoded frame equals the host folder source's frame of that file")
    greys = {d[2] for d in digest}
    extra = [r for r in rows if r["file"] < 0]
    c.check(all(r["grey"] in greys for r in extra),
            f"{len(extra)} payloads equal to no file (sizes {[r['bytes'] for r in extra]}) still decode to a fed frame")
    c.check(all(r["same"] for r in rows), "TurboJPEG on the kept payload gives the source's frame")
    latency, recovered = check_recovery(c, "no frame within")
    c.check(c.first("RECEIVED-AFTER") == "3", "3 more frames after the recovery")
    c.check(c.field("GUEST-EXIT") == ["0"], "guest program finished")
    decode = [r["decode_ms"] for r in rows]
    after = frames_between(c.lines, "RECOVERED", "COUNTERS")
    skipped = [f["message"] for f in after if f["status"] == "skipped"]
    print(f"FIGURES loopback: {len(fresh)}/{len(digest)} MJPEG frames received ({repeats} repeats); TurboJPEG decode 1920x1080 in the "
          f"TCG guest median {statistics.median(decode) if decode else 0:.1f} ms (max {max(decode or [0]):.1f}); "
          f"error event {latency} ms after the producer left, first frame "
          f"{recovered[0] if recovered else '?'} ms after it returned; skipped after recovery: {skipped}")


def read_csv(path):
    with open(path) as f:
        rows = [line.rstrip("\n").split(",") for line in f]
    return rows[0], rows[1:]


def read_bytes(*path):
    with open(os.path.join(*path), "rb") as f:
        return f.read()


def check_record(c, work):
    """`onetip process` live on the loopback camera, `onetip record` of the same feed, and the
    session processed on the host; the fed files are sim frames 0, 4, 8, ... (run_qemu_camera.sh)."""
    check_common(c)
    for name in ("live", "record"):
        c.check(c.first(f"{name}-EXIT") == "130", f"{name} pass: ended by Ctrl-C with its outputs (exit 130)")
        c.check(c.first(f"{name}-FEED-EXIT") == "0", f"{name} pass: every file fed")
    c.check(bool(c.field("SAVED")), "the guest saved its outputs")
    out = os.path.join(work, "out")
    frames_dir = os.path.join(work, "root", "frames")
    fed = sorted(os.listdir(frames_dir))
    _, session = read_csv(os.path.join(out, "session", "session.csv"))
    c.check(len(session) == len(fed) + 1,
            f"the session holds {len(session)} frames: the {len(fed)} files and the buffer the driver hands "
            "a new reader")
    same = [read_bytes(out, "session", row[2]) == read_bytes(frames_dir, f) for row, f in zip(session[1:], fed)]
    c.check(bool(same) and all(same), "the recorded MJPEG files equal the fed files byte for byte")
    c.check(read_bytes(out, "pose.csv") == read_bytes(work, "replay_pose.csv"),
            "process --input SESSION gives the live run's pose.csv byte for byte")
    c.check(read_bytes(out, "markers.csv") == read_bytes(work, "replay_markers.csv"),
            "... and its markers.csv")
    header, live = read_csv(os.path.join(out, "pose.csv"))
    c.check(len(live) == len(session),
            f"the live run processed as many frames as the recording holds ({len(live)} rows)")
    # Independent truth: the simulator's dz, relative to the frame where the live run saw contact begin.
    _, truth = read_csv(os.path.join(work, "sim", "gt_pose.csv"))
    dz_truth = {int(r[0]): float(r[5]) for r in truth}
    col = {name: i for i, name in enumerate(header)}
    contact = [r for r in live if r[col["contact"]] == "1"]
    errors = []
    if contact:
        onset = 4 * (int(contact[0][0]) - 1)  # live frame j holds fed file j - 1 = sim frame 4 (j - 1)
        for r in contact:
            want = dz_truth[4 * (int(r[0]) - 1)] - dz_truth[onset]
            errors.append(abs(float(r[col["dz"]]) - want))
    worst = max(errors) if errors else float("inf")
    c.check(len(contact) >= len(live) // 2 and worst < 0.02,
            f"{len(contact)} contact frames, dz against the simulator's truth within {worst:.4f} mm (limit 0.02)")
    print(f"FIGURES record: {len(session)} frames recorded and processed live; replay identical; "
          f"max dz {max(float(r[col['dz']]) for r in live):.3f} mm, worst dz error {worst:.4f} mm")


def main(argv):
    mode, log = argv[1], argv[2]
    c = Checker(console_lines(log))
    if mode == "vivid":
        check_vivid(c)
    elif mode == "record":
        check_record(c, argv[3])
    else:
        check_loopback(c, argv[3])
    print(f"{len(c.failures)} failed" if c.failures else "all checks passed")
    return 1 if c.failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env bash
# shellcheck disable=SC2034  # QG_MEMORY and QG_PACKAGES are read by qemu_guest.sh
# The camera drills (see CMakeLists.txt): builds the guest's initramfs with
# tests/qemu/qemu_guest.sh, boots Debian's kernel under qemu (TCG), runs
# camera_guest there and checks what it printed with check_camera.py.
#
#   run_qemu_camera.sh vivid|loopback|record CAMERA_GUEST CAMERA_FRAMES ONETIP_CLI WORK_DIR
#
# vivid:    vivid n_devs=1 node_types=0x1 (one video capture node, /dev/video0),
#           FRAMES (default 30) frames; the unplug removes the module (rmmod),
#           the replug loads it again.
# loopback: `onetip sim` renders samples/scenarios/press.yaml (FRAMES frames,
#           default 12), camera_frames encodes them as grey JPEG (quality 90)
#           and prints their folder-source digest; v4l2loopback devices=1
#           video_nr=0 max_buffers=4 carries them as MJPEG.
# record:   the same frames, every 4th of 4 x FRAMES (default 16) so that the
#           press reaches its 2.5 mm peak, and the whole onetip tool in the guest (its 271
#           libraries: a 134 MB initramfs, 2 GB of guest memory): guest_record.sh
#           runs `onetip process` live, then `onetip record`, on the same feed;
#           a virtio disk brings the outputs back; the host processes the session.
# Exit: 0 checked, 1 failed, 77 skipped (the reason is printed).
set -euo pipefail

mode=${1:?usage: run_qemu_camera.sh vivid|loopback|record CAMERA_GUEST CAMERA_FRAMES ONETIP_CLI WORK_DIR}
guest=${2:?} frames_tool=${3:?} cli=${4:?} work=${5:?}
here=$(cd "$(dirname "$0")" && pwd)
src=${ONETIP_SOURCE_DIR:-$(cd "$here/../.." && pwd)}
# shellcheck source=../qemu/qemu_guest.sh
source "$here/../qemu/qemu_guest.sh"
QG_MEMORY=1G

# The first $1 frames of press.yaml, rendered by `onetip sim` into $work/sim.
render() {
  "$cli" sim --scenario "$src/samples/scenarios/press.yaml" --out "$work/sim" --frames "$1" >"$work/sim.log" 2>&1 ||
    { echo "FAIL: onetip sim"; cat "$work/sim.log"; exit 1; }
}

case "$mode" in
  vivid)
    qemu_guest_setup "$work" vivid
    qemu_guest_module vivid
    qemu_guest_program "$guest" /camera_guest
    cat >"$QG_ROOT/modules/reload-vivid.sh" <<'LOAD'
#!/bin/busybox sh
/modules/load-vivid.sh n_devs=1 node_types=0x1 || exit 1
for i in $(seq 100); do [ -e /dev/video0 ] && exit 0; sleep 0.05; done
exit 1
LOAD
    chmod +x "$QG_ROOT/modules/reload-vivid.sh"
    qemu_guest_boot "
/modules/reload-vivid.sh && echo 'ONETIP MODULE vivid loaded'
/camera_guest vivid /dev/video0 ${ONETIP_CAMERA_FRAMES:-30} 'rmmod vivid' /modules/reload-vivid.sh
echo \"ONETIP GUEST-EXIT \$?\"" 240
    /usr/bin/python3 "$here/check_camera.py" vivid "$QG_LOG"
    ;;
  loopback)
    QG_PACKAGES="linux-headers-amd64 v4l2loopback-dkms"
    qemu_guest_setup "$work" v4l2loopback
    count=${ONETIP_CAMERA_FRAMES:-12}
    render "$count"
    "$frames_tool" encode "$work/sim/frames" "$QG_ROOT/frames" 90 "$count"
    "$frames_tool" digest "$QG_ROOT/frames" >"$work/digest.txt"
    qemu_guest_module v4l2loopback
    qemu_guest_program "$guest" /camera_guest
    qemu_guest_boot "
/modules/load-v4l2loopback.sh devices=1 video_nr=0 max_buffers=4 && echo 'ONETIP MODULE v4l2loopback loaded'
/camera_guest loopback /dev/video0 /frames/*.jpg
echo \"ONETIP GUEST-EXIT \$?\"" 240
    /usr/bin/python3 "$here/check_camera.py" loopback "$QG_LOG" "$work/digest.txt"
    ;;
  record)
    QG_PACKAGES="linux-headers-amd64 v4l2loopback-dkms"
    qemu_guest_setup "$work" v4l2loopback virtio_blk
    QG_MEMORY=2G
    count=${ONETIP_CAMERA_FRAMES:-16}
    render $((4 * count))
    "$frames_tool" encode "$work/sim/frames" "$QG_ROOT/frames" 90 "$count" 4
    mkdir -p "$QG_ROOT/data"
    cp "$work/sim/calib.yaml" "$work/sim/pattern.yaml" "$QG_ROOT/data/"
    qemu_guest_module v4l2loopback
    load_pci=true
    if qemu_guest_has_module virtio_pci; then qemu_guest_module virtio_pci; load_pci=/modules/load-virtio_pci.sh; fi
    qemu_guest_module virtio_blk
    qemu_guest_program "$guest" /camera_guest
    qemu_guest_program "$cli" /onetip
    truncate -s 64M "$work/out.img"
    cp "$here/guest_record.sh" "$QG_ROOT/guest_record.sh"
    interval=700  # ms between frames; a sanitizer build of onetip processes a 1080p frame in ~1 s under TCG
    if grep -qa __asan_init "$cli"; then interval=2000; fi  # gcc links libasan, clang the runtime itself
    qemu_guest_boot "
$load_pci && /modules/load-virtio_blk.sh && echo 'ONETIP MODULE virtio_blk loaded'
/modules/load-v4l2loopback.sh devices=1 video_nr=0 max_buffers=4 && echo 'ONETIP MODULE v4l2loopback loaded'
/bin/busybox sh /guest_record.sh $interval" 280 -drive "file=$work/out.img,format=raw,if=virtio"
    mkdir -p "$work/out"
    tar -xf "$work/out.img" -C "$work/out" || { echo "FAIL: the guest saved nothing"; tail -n 30 "$QG_LOG"; exit 1; }
    "$cli" process --input "$work/out/session" --calib "$work/sim/calib.yaml" --pattern "$work/sim/pattern.yaml" \
      --out "$work/replay_pose.csv" --markers "$work/replay_markers.csv" --quiet >"$work/replay.log" 2>&1 ||
      { echo "FAIL: onetip process on the recorded session"; cat "$work/replay.log"; exit 1; }
    /usr/bin/python3 "$here/check_camera.py" record "$QG_LOG" "$work"
    ;;
  *) echo "usage: run_qemu_camera.sh vivid|loopback|record ..."; exit 2 ;;
esac

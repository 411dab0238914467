#!/bin/busybox sh
# shellcheck shell=dash
# Runs inside the qemu guest (run_qemu_camera.sh record): the whole `onetip`
# tool against v4l2loopback (/dev/video0), in two passes over the same feed:
#   live    `onetip process --input v4l2:/dev/video0` -> /out/pose.csv, /out/markers.csv
#   record  `onetip record --input v4l2:/dev/video0`  -> /out/session
# Each pass: `camera_guest feed` sets the format and writes the first file
# (readers can open the device only then), the reader starts, and once it has
# the device open the feed writes every file, one per INTERVAL_MS (the first
# argument, default 700; below the reader's 2 s frame time-out); 1 s after the
# last one the reader gets Ctrl-C (SIGINT), the way a camera run ends (before
# its 2 s frame time-out, which would make it reconnect and take the last
# buffer again).
# One reader at a time: two readers of one loopback device start seconds apart
# under TCG, so the first would time out and see a different stream.
# Prints "ONETIP <pass>-OPENED <uptime s>" (the reader has the device open),
# "ONETIP <pass>-GO <uptime s>", "ONETIP <pass>-STOP <uptime s>" (Ctrl-C),
# "ONETIP <pass>-EXIT <code>" and
# "ONETIP <pass>-FEED-EXIT <code>".
rig="--calib /data/calib.yaml --pattern /data/pattern.yaml"
interval=${1:-700}

# Whether process $1 has /dev/video0 open.
has_device() {
  for fd in /proc/"$1"/fd/*; do
    [ "$(readlink "$fd")" = /dev/video0 ] && return 0
  done
  return 1
}

pass() {
  name=$1
  shift
  mkdir -p "/flags/$name"
  /camera_guest feed /dev/video0 "$interval" "/flags/$name" /frames/*.jpg &
  feeder=$!
  for _ in $(seq 600); do [ -e "/flags/$name/primed" ] && break; sleep 0.1; done
  "$@" >"/out/$name.log" 2>&1 &
  reader=$!
  for _ in $(seq 600); do has_device $reader && break; sleep 0.1; done
  echo "ONETIP $name-OPENED $(cut -d' ' -f1 /proc/uptime)"
  sleep 0.5
  touch "/flags/$name/go"
  echo "ONETIP $name-GO $(cut -d' ' -f1 /proc/uptime)"
  for _ in $(seq 1200); do [ -e "/flags/$name/fed" ] && break; sleep 0.1; done
  sleep 1
  echo "ONETIP $name-STOP $(cut -d' ' -f1 /proc/uptime)"
  kill -INT $reader
  wait $reader
  echo "ONETIP $name-EXIT $?"
  touch "/flags/$name/stop"
  wait $feeder
  echo "ONETIP $name-FEED-EXIT $?"
}

mkdir -p /out /flags
# shellcheck disable=SC2086
pass live /onetip process --input v4l2:/dev/video0 $rig --out /out/pose.csv --markers /out/markers.csv --quiet
# shellcheck disable=SC2086
pass record /onetip record --input v4l2:/dev/video0 $rig --out /out/session
tar -cf /dev/vda -C /out . && sync && echo "ONETIP SAVED"

#!/usr/bin/env bash
# Runs every command of docs/real_sensor.md as written, with the simulated
# sensor in place of the camera: the fenced block after each
# "<!-- real-sensor: NAME -->" line is taken in order, its "v4l2:/dev/video0"
# replaced by the sim: scenario that shows what that step needs (STAND_IN
# below; a block without one fails the test), and all of them run as one
# bash -euo pipefail script in a scratch folder with the build's onetip first
# on PATH. Then the outcomes the document promises are checked.
# Usage: run_real_sensor.sh ONETIP_CLI SOURCE_DIR
set -euo pipefail
cli=$(cd "$(dirname "$1")" && pwd)/$(basename "$1") src=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/bin"
ln -s "$cli" "$work/bin/onetip"
/usr/bin/python3 - "$src/docs/real_sensor.md" "$work/steps.sh" "$src/samples/scenarios" <<'PY'
import pathlib, re, sys
doc, out, scenarios = sys.argv[1:4]
STAND_IN = {"camera": "press.yaml", "board": "calibration.yaml", "check": "press.yaml",
            "rest": "press.yaml", "events": "press.yaml", "lost": None}
blocks = re.findall(r"<!-- real-sensor: (\S+) -->\n```sh\n(.*?)```", pathlib.Path(doc).read_text(), re.S)
if [name for name, _ in blocks] != list(STAND_IN):
    sys.exit("run_real_sensor: blocks %s, expected %s" % ([n for n, _ in blocks], list(STAND_IN)))
script = []
for name, body in blocks:
    if STAND_IN[name] is None and "v4l2:" in body:
        sys.exit("run_real_sensor: block %s reads the camera but has no stand-in" % name)
    if STAND_IN[name]:
        body = body.replace("v4l2:/dev/video0", "sim:%s/%s" % (scenarios, STAND_IN[name]))
    script.append("echo '== %s'\n%s" % (name, body))
pathlib.Path(out).write_text("\n".join(script))
PY
cd "$work"
PATH="$work/bin:$PATH" bash -euo pipefail steps.sh > out.txt 2>&1 || { cat out.txt; exit 1; }
cat out.txt
fail() { echo "run_real_sensor: $*"; exit 1; }
grep -q "^recorded 30 frames" out.txt || fail "step 1 did not record 30 frames"
rms=$(grep "^RMS reprojection error (px): " out.txt | awk '{print $NF}')
awk -v r="$rms" 'BEGIN { exit !(r > 0 && r < 0.9) }' || fail "calibration RMS '$rms'"
[ -s check.png ] || fail "no viewer screenshot"
# The press read with the calibration of step 2 against the simulator's truth:
# the largest dz within 0.05 mm (docs/pose: press dz 0.002 mm RMSE with the
# true calibration; the calibrated one adds its own small scale error).
"$cli" sim --quiet --field-only --scenario "$src/samples/scenarios/press.yaml" --out truth > /dev/null
max_dz=$(awk -F, 'NR > 1 && $6 > m { m = $6 } END { print m + 0 }' pose.csv)
true_dz=$(awk -F, 'NR > 1 && $6 > m { m = $6 } END { print m + 0 }' truth/gt_pose.csv)
awk -v d="$max_dz" -v t="$true_dz" 'BEGIN { e = d - t; exit !(t > 2 && e < 0.05 && e > -0.05) }' ||
  fail "largest dz $max_dz mm, the truth's $true_dz mm"
grep -Eq "^[0-9]+ 289$" out.txt || fail "step 6 counted no frame with all 289 markers"
echo "run_real_sensor: every step ran; RMS $rms px, largest dz $max_dz mm (truth $true_dz mm)"

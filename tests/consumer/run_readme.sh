#!/usr/bin/env bash
# Runs the README's "Use the installed SDK" lines exactly as written: every
# fenced block after a "<!-- installed-sdk: NAME -->" line is saved as NAME in
# a scratch folder (HOME points there too), `build` there is BUILD_DIR, and
# install.sh runs with bash -euo pipefail; each program must print input events,
# and print one clear line (usage, or the library's message) when run wrongly.
# Usage: run_readme.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 - "$src/README.md" "$work" <<'PY'
import pathlib, re, sys
text = pathlib.Path(sys.argv[1]).read_text()
blocks = re.findall(r"<!-- installed-sdk: (\S+) -->\n```[a-z]*\n(.*?)```", text, re.S)
names = [name for name, _ in blocks]
if sorted(names) != sorted(["install.sh", "app.c", "app.cpp", "app.py", "App.cs"]):
    sys.exit("run_readme: README blocks found: %s" % names)
for name, body in blocks:
    pathlib.Path(sys.argv[2], name).write_text(body)
PY
ln -s "$build" "$work/build"
cd "$work"
env -u LD_LIBRARY_PATH -u PYTHONPATH -u MONO_PATH -u PKG_CONFIG_PATH HOME="$work" \
  bash -euo pipefail install.sh > out.txt 2>&1 || { cat out.txt; exit 1; }
for language in C C++ Python C#; do
  n=$(grep -c "^$language: frame" out.txt || true)
  echo "$language: $n input events"
  [ "$n" -gt 10 ] || { cat out.txt; exit 1; }
done

# Copied and run carelessly, each program still says what is wrong in one line on stderr: without its argument
# a usage line and exit status 2 (never its own file read as a scenario), with a scenario that does not exist
# the library's message naming it and exit status 1 (never an abort, exit 134, or a traceback).
P="$work/onetip"
py=$(echo "$P"/lib/python3*/dist-packages)
expect() {  # WHAT STATUS NEEDLE COMMAND...
  local what=$1 want=$2 needle=$3 status=0
  shift 3
  env -u LD_LIBRARY_PATH -u PYTHONPATH -u MONO_PATH HOME="$work" "$@" > run.out 2> run.err || status=$?
  if [ "$status" -ne "$want" ] || ! grep -qF -- "$needle" run.err || [ "$(wc -l < run.err)" -ne 1 ]; then
    echo "run_readme: $what: exit status $status (expected $want), stderr (expected one line with '$needle'):"
    cat run.err
    exit 1
  fi
  echo "$what: exit status $status: $(cat run.err)"
}
for arg in "" "$work/missing.yaml"; do
  if [ -z "$arg" ]; then
    want=2 needle="usage:"
    set --
  else
    want=1 needle="missing.yaml"
    set -- "$arg"
  fi
  expect "app_c $*" "$want" "$needle" ./app_c "$@"
  expect "app_cpp $*" "$want" "$needle" ./app_cpp "$@"
  expect "app.py $*" "$want" "$needle" env PYTHONPATH="$py" /usr/bin/python3 app.py "$@"
  expect "App.exe $*" "$want" "$needle" env MONO_PATH="$P/lib" mono App.exe "$@"
done

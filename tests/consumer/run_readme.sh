#!/usr/bin/env bash
# A new user's first steps with the README, exactly as written, in a copy of the checkout:
#  1. the quick start's demo command (the first line of the block after "<!-- quick-start -->")
#     runs in a copy of the checkout's files as a fresh clone holds them (tracked and new files,
#     nothing git ignores: no build tree, no out/), so its `build` holds only what the demo builds;
#  2. every fenced block after a "<!-- installed-sdk: NAME -->" line is saved as NAME in the copy's
#     root and install.sh runs there with bash -euo pipefail, HOME in a scratch folder: it installs
#     that `build` into $HOME/onetip and builds and runs the first program in each language;
#  3. each program prints input events, and one clear line when run wrongly;
#  4. a CMake project (tests/consumer) builds against the prefix with find_package(onetip) and runs.
# Nothing is installed on the machine: ONETIP_INSTALL_DEPS=check makes .ci/install-deps.sh fail,
# naming the package, when one is missing. The demo's build is served by the compiler cache
# (.ci/build-env.sh) the checkout's own build filled.
# Usage: run_readme.sh SOURCE_DIR
set -euo pipefail
src=$(cd "$1" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
clone="$work/onetip"
mkdir -p "$clone" "$work/home"

# 1. the copy, and the quick start's demo command in it
(cd "$src" && git ls-files -z --cached --others --exclude-standard) |
  (cd "$src" && /usr/bin/python3 -c '
import os, sys
names = [n for n in sys.stdin.buffer.read().split(b"\0") if n and os.path.lexists(n)]  # not files deleted in the tree
sys.stdout.buffer.write(b"\0".join(names) + b"\0")' | tar --null -T - -cf -) | tar -xf - -C "$clone"
/usr/bin/python3 - "$src/README.md" "$work" <<'PY'
import pathlib, re, sys
text = pathlib.Path(sys.argv[1]).read_text()
quick = re.findall(r"<!-- quick-start -->\n```sh\n(.*?)\n", text)
if len(quick) != 1 or not quick[0].startswith("bash .ci/demo.sh"):
    sys.exit("run_readme: the quick start's demo command (the first line after <!-- quick-start -->): %s" % quick)
pathlib.Path(sys.argv[2], "quick_start.sh").write_text(quick[0] + "\n")
blocks = re.findall(r"<!-- installed-sdk: (\S+) -->\n```[a-z]*\n(.*?)```", text, re.S)
names = [name for name, _ in blocks]
if sorted(names) != sorted(["install.sh", "app.c", "app.cpp", "app.py", "App.cs"]):
    sys.exit("run_readme: README blocks found: %s" % names)
for name, body in blocks:
    pathlib.Path(sys.argv[2], name).write_text(body)
PY
cd "$clone"
echo "quick start: $(cat "$work/quick_start.sh")"
env -u LD_LIBRARY_PATH -u PYTHONPATH -u MONO_PATH -u PKG_CONFIG_PATH ONETIP_INSTALL_DEPS=check \
  bash -euo pipefail "$work/quick_start.sh" > "$work/demo.txt" 2>&1 || { cat "$work/demo.txt"; exit 1; }
grep '^install-deps' "$work/demo.txt"
tail -n 1 "$work/demo.txt"
test -s out/demo/contact_sheet.png || { echo "run_readme: the demo wrote no out/demo/contact_sheet.png"; exit 1; }

# 2. the install section, in the copy's root (beside `build`), as a user saves and runs it
for name in install.sh app.c app.cpp app.py App.cs; do mv "$work/$name" .; done
P="$work/home/onetip"
env -u LD_LIBRARY_PATH -u PYTHONPATH -u MONO_PATH -u PKG_CONFIG_PATH HOME="$work/home" \
  bash -euo pipefail install.sh > install.txt 2>&1 || { cat install.txt; exit 1; }
test -f "$P/lib/libonetip.so" || { cat install.txt; echo "run_readme: no $P/lib/libonetip.so"; exit 1; }
for language in C C++ Python C#; do
  n=$(grep -c "^$language: frame" install.txt || true)
  echo "$language: $n input events"
  [ "$n" -gt 10 ] || { cat install.txt; exit 1; }
done

# 3. Copied and run carelessly, each program still says what is wrong in one line on stderr: without its argument
# a usage line and exit status 2 (never its own file read as a scenario), with a scenario that does not exist
# the library's message naming it and exit status 1 (never an abort, exit 134, or a traceback).
py=$(echo "$P"/lib/python3*/dist-packages)
expect() {  # WHAT STATUS NEEDLE COMMAND...
  local what=$1 want=$2 needle=$3 status=0
  shift 3
  env -u LD_LIBRARY_PATH -u PYTHONPATH -u MONO_PATH HOME="$work/home" "$@" > run.out 2> run.err || status=$?
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

# 4. a CMake project against the prefix
env -u LD_LIBRARY_PATH -u CMAKE_PREFIX_PATH cmake -S tests/consumer -B "$work/consumer" -DCMAKE_PREFIX_PATH="$P" \
  -DCMAKE_BUILD_TYPE=Release > "$work/consumer.txt" 2>&1 &&
  cmake --build "$work/consumer" >> "$work/consumer.txt" 2>&1 || { cat "$work/consumer.txt"; exit 1; }
env -u LD_LIBRARY_PATH "$work/consumer/consumer" "$P/share/onetip/scenarios/press.yaml"
env -u LD_LIBRARY_PATH "$work/consumer/consumer_c" "$P/share/onetip/scenarios/press.yaml"
echo "run_readme: the quick start's demo, then the install section as written: a working prefix"

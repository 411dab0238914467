#!/usr/bin/env bash
# Runs the README's "Use the installed SDK" lines exactly as written: every
# fenced block after a "<!-- installed-sdk: NAME -->" line is saved as NAME in
# a scratch folder (HOME points there too), `build` there is BUILD_DIR, and
# install.sh runs with bash -euo pipefail; each program must print input events.
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

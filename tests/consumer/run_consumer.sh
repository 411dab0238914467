#!/usr/bin/env bash
# Installs the build tree into a temporary prefix and uses it as a user would,
# with nothing from the build tree and no LD_LIBRARY_PATH:
#  - tests/consumer built with find_package(onetip) only (C++ and C11);
#  - consumer_c.c built with `pkg-config --cflags --libs onetip` alone, as C11
#    with warnings as errors (the Cflags carry no C++ flag), then again after
#    the prefix is moved elsewhere (onetip.pc is relative to its own folder);
#  - every C header of bindings/c/include installed, each compiling alone (C11, C++);
#  - `import onetip` with PYTHONPATH set to the prefix's site-packages;
#  - a C# program compiled against the installed Onetip.dll (when mcs is here).
# Usage: run_consumer.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
unset LD_LIBRARY_PATH PYTHONPATH MONO_PATH PKG_CONFIG_PATH
scenario="$src/samples/scenarios/press.yaml"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$src/tests/consumer" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/build" >/dev/null
LD_LIBRARY_PATH="$work/prefix/lib" "$work/build/consumer" "$scenario"
LD_LIBRARY_PATH="$work/prefix/lib" "$work/build/consumer_c" "$scenario"
for h in "$src"/bindings/c/include/*.h; do  # onetip_c.h and every header it includes
  test -f "$work/prefix/include/${h##*/}" || { echo "${h##*/} not installed" >&2; exit 1; }
done
for f in share/onetip/docs/reference.md share/onetip/scenarios/press.yaml bin/onetip; do
  test -f "$work/prefix/$f" || { echo "$f not installed" >&2; exit 1; }
done
# the library exports only the public API
if nm -D --defined-only "$work/prefix/lib/libonetip.so" | grep -q 'onetip3sim'; then
  echo "internal symbols leak from libonetip.so" >&2
  exit 1
fi

# pkg-config alone, in place and after moving the whole prefix
for prefix in "$work/prefix" "$work/moved"; do
  [ -d "$prefix" ] || mv "$work/prefix" "$prefix"
  flags=$(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags --libs onetip)
  echo "pkg-config: $flags"
  cc -std=c11 -Wall -Wextra -pedantic -Werror "$src/tests/consumer/consumer_c.c" $flags -o "$work/consumer_pc"
  "$work/consumer_pc" "$scenario"
  for h in "$prefix"/include/onetip_c*.h; do  # each C header alone, as C11 and C++ (pkg-config's Cflags)
    echo "#include <${h##*/}>" | cc -x c -std=c11 -Wall -Wextra -pedantic -Werror -fsyntax-only $flags -
    echo "#include <${h##*/}>" | c++ -x c++ -std=c++20 -Wall -Wextra -pedantic -Werror -fsyntax-only $flags -
  done
  PYTHONPATH=$(echo "$prefix"/lib/python3*/dist-packages) /usr/bin/python3 -c \
    "import onetip; print('python: onetip', onetip.__version__, onetip.__file__)"
done
prefix="$work/moved"
if command -v mcs >/dev/null && command -v mono >/dev/null; then
  cat > "$work/Version.cs" <<'CS'
class Version {
    static int Main(string[] args) {
        using (var sensor = new Onetip.Sensor("sim:" + args[0])) {
            sensor.Start();
            Onetip.SensorEvent e;
            int inputs = 0;
            while (sensor.WaitEvent(10.0, out e)) if (e.Type == Onetip.EventType.Input) ++inputs;
            System.Console.WriteLine("C#: {0} input events", inputs);
            return inputs > 10 ? 0 : 1;
        }
    }
}
CS
  mcs -nologo -r:"$prefix/lib/Onetip.dll" -out:"$work/Version.exe" "$work/Version.cs"
  MONO_PATH="$prefix/lib" mono "$work/Version.exe" "$scenario"
fi
echo "consumer: ok"

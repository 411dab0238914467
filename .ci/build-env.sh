# Sourced by the scripts in .ci/ after install-deps.sh: the generator and the compiler cache of every
# build they make.
# ccache keys each object on the compiler, its flags and the preprocessed source. With
# CCACHE_BASEDIR at the checkout's root, paths below it are made relative before they are hashed
# (and before the compiler sees them), so a clone in another folder (CI's, standalone.sh's scratch
# clone) is served the objects an earlier build left. CCACHE_NOHASHDIR keeps the working directory
# out of the key of objects with debug information (the sanitizer build); their debug information
# then names the folder of the build that filled the cache. The cache only saves time: a run with
# an empty one builds everything, as before.
# Ninja schedules the objects of every target on both cores as soon as their own inputs exist (make
# waits for each target's dependencies to link first); a tree configured before keeps its generator.
if command -v ninja >/dev/null 2>&1; then export CMAKE_GENERATOR=Ninja; fi
if command -v ccache >/dev/null 2>&1; then
  export CMAKE_C_COMPILER_LAUNCHER=ccache CMAKE_CXX_COMPILER_LAUNCHER=ccache
  CCACHE_BASEDIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  export CCACHE_BASEDIR CCACHE_NOHASHDIR=true
  # Depend mode: the key comes from the dependency list the compiler writes anyway (-MD), so a miss
  # costs one compile, not a preprocessor run and a compile.
  export CCACHE_DEPEND=true
  # A fresh clone's files are seconds old when the build starts; without this, ccache would not
  # trust its direct-mode record of any header that young and would preprocess every object.
  export CCACHE_SLOPPINESS=include_file_mtime,include_file_ctime
  # Release (gcc) and sanitizer (clang) trees take about 2 GB together.
  export CCACHE_MAXSIZE="${CCACHE_MAXSIZE:-6G}"
fi

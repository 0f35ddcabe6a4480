#!/usr/bin/env bash
# Runs the README's usage snippets as written (each follows a `<!-- test:NAME -->` line)
# against the installed package: the CLI commands, the library program built with
# pkg-config, and the CMake project with its main.cpp.
# Usage: readme_test.sh SOURCE_DIR PREFIX WORK_DIR
set -euo pipefail
src=$(cd "$1" && pwd) prefix=$(cd "$2" && pwd) work=$3
rm -rf "$work" && mkdir -p "$work"

snippet() {  # the fenced block after <!-- test:$1 -->
  awk -v name="<!-- test:$1 -->" '
    $0 == name { armed = 1; next }
    armed && /^```/ { if (inside) exit; inside = 1; next }
    inside { print }' "$src/README.md"
}
for name in cli library library-build cmake cmake-main; do
  [ -n "$(snippet $name)" ] || { echo "README has no snippet test:$name"; exit 1; }
done

export PATH="$prefix/bin:$PATH"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
export LD_LIBRARY_PATH="$prefix/lib"

# 1. CLI, from a directory that looks like the repository root.
mkdir -p "$work/cli" && ln -s "$src/examples" "$work/cli/examples"
(cd "$work/cli" && bash -euo pipefail -c "$(snippet cli)")
for f in rte.es300.vert rte.es300.json orbit.comp orbit.comp.d lowered/globe_rte.vert.json lowered/orbit_step.comp.d; do
  [ -s "$work/cli/$f" ] || { echo "CLI snippet did not write $f"; exit 1; }
done
grep -q "float_float_io.glsl" "$work/cli/orbit.comp.d"

# 2. Library, built with pkg-config.
mkdir -p "$work/lib" && ln -s "$src/examples" "$work/lib/examples"
snippet library >"$work/lib/lower_one.cpp"
(cd "$work/lib" && bash -euo pipefail -c "$(snippet library-build)" 2>"$work/lib/stderr.log") ||
  { cat "$work/lib/stderr.log"; exit 1; }
grep -q "position_hi" "$work/lib/rte.es300.vert"
grep -q '"split": true' "$work/lib/stderr.log"  # the manifest, printed on stderr

# 3. CMake project with EMBED.
mkdir -p "$work/cmake"
cp -r "$src/examples/cmake-consumer/shaders" "$work/cmake/shaders"
snippet cmake >"$work/cmake/CMakeLists.txt"
snippet cmake-main >"$work/cmake/main.cpp"
cmake -S "$work/cmake" -B "$work/cmake/build" -DCMAKE_PREFIX_PATH="$prefix" >"$work/cmake/configure.log"
cmake --build "$work/cmake/build" >"$work/cmake/build.log"
"$work/cmake/build/app" | tee "$work/cmake/run.log"
grep -q "^dt_hi = 9.99999975e-06" "$work/cmake/run.log"
grep -q "^dt_lo = " "$work/cmake/run.log"
grep -q "bytes of GLSL es310" "$work/cmake/run.log"
echo "README snippets: OK"

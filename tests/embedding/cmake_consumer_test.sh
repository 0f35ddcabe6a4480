#!/usr/bin/env bash
# examples/cmake-consumer against the installed package, from a clean build tree, then
# the depfile contract: editing an #include'd file re-lowers the shaders that include it
# (and rebuilds the program embedding them); a build with nothing changed does nothing.
# Usage: cmake_consumer_test.sh SOURCE_DIR PREFIX WORK_DIR
set -euo pipefail
src=$(cd "$1" && pwd) prefix=$(cd "$2" && pwd) work=$3
rm -rf "$work" && mkdir -p "$work"
cp -r "$src/examples/cmake-consumer" "$work/project"   # a copy: the test edits its files
build=$work/build

cmake -S "$work/project" -B "$build" -DCMAKE_PREFIX_PATH="$prefix" >"$work/configure.log"
cmake --build "$build" -j2 >"$work/build1.log"
[ "$(grep -c "doublet: lowering" "$work/build1.log")" = 2 ] || { echo "expected 2 shaders lowered"; cat "$work/build1.log"; exit 1; }
"$build/orbit_and_zoom"

# The depfile names the shader and its include.
grep -q "float_float_io.glsl" "$build/doublet/orbit_and_zoom/orbit_step.comp.d"

nothing_built() {  # a build log with no lowering, compiling or linking
  ! grep -E "doublet: lowering|Building|Linking" "$1"
}

cmake --build "$build" >"$work/build2.log"
nothing_built "$work/build2.log" || { echo "an untouched build did work:"; cat "$work/build2.log"; exit 1; }

sleep 1  # coarse file-system timestamps
echo "// edited" >>"$work/project/shaders/include/float_float_io.glsl"
cmake --build "$build" >"$work/build3.log"
grep -q "lowering shaders/orbit_step.comp" "$work/build3.log" || { echo "include edit did not re-lower orbit_step"; cat "$work/build3.log"; exit 1; }
grep -q "lowering shaders/mandelbrot_zoom.comp" "$work/build3.log" || { echo "include edit did not re-lower mandelbrot_zoom"; cat "$work/build3.log"; exit 1; }
grep -q "Linking" "$work/build3.log" || { echo "the program was not relinked with the new shaders"; exit 1; }

cmake --build "$build" >"$work/build4.log"
nothing_built "$work/build4.log" || { echo "a second build after the edit did work:"; cat "$work/build4.log"; exit 1; }

sleep 1
echo "// edited" >>"$work/project/shaders/orbit_step.comp"
cmake --build "$build" >"$work/build5.log"
[ "$(grep -c "doublet: lowering" "$work/build5.log")" = 1 ] || { echo "editing one shader should re-lower only it"; cat "$work/build5.log"; exit 1; }
"$build/orbit_and_zoom" >/dev/null
# MODE is reserved until the CLI has precision modes: a clear configure error, not a
# silently different shader.
sed -i 's/  TARGET_ES 310/  TARGET_ES 310 MODE fast/' "$work/project/CMakeLists.txt"
if cmake -S "$work/project" -B "$work/build-mode" -DCMAKE_PREFIX_PATH="$prefix" >"$work/mode.log" 2>&1; then
  if ! grep -q -- "--mode" <<<"$("$prefix/bin/doublet" lower --help)"; then
    echo "MODE was accepted by a CLI without --mode"; exit 1
  fi
else
  grep -q "MODE is reserved" "$work/mode.log" || { cat "$work/mode.log"; exit 1; }
fi
echo "cmake-consumer: OK"

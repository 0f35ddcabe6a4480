#!/usr/bin/env bash
# examples/asset-compiler built against the installed package, once with the static
# library (doublet::doublet, which pulls glslang through find_dependency) and once with
# libdoublet.so (doublet::doublet-shared), then run on examples/shaders.
# Usage: asset_compiler_test.sh SOURCE_DIR PREFIX WORK_DIR
set -euo pipefail
src=$(cd "$1" && pwd) prefix=$(cd "$2" && pwd) work=$3
rm -rf "$work" && mkdir -p "$work"

for linkage in static shared; do
  shared=OFF; [ "$linkage" = shared ] && shared=ON
  build=$work/build-$linkage out=$work/out-$linkage
  cmake -S "$src/examples/asset-compiler" -B "$build" -DCMAKE_PREFIX_PATH="$prefix" \
        -DLINK_SHARED_DOUBLET=$shared >"$work/configure-$linkage.log"
  cmake --build "$build" -j2 >"$work/build-$linkage.log"
  if [ "$linkage" = shared ]; then
    # Capture first: under pipefail, `ldd | grep -q` fails when grep exits before ldd
    # finishes writing (SIGPIPE), which made this check flaky in CI.
    libs=$(ldd "$build/lower_assets")
    grep -q "libdoublet.so" <<<"$libs" || { echo "not linked to libdoublet.so:"; echo "$libs"; exit 1; }
  fi
  "$build/lower_assets" "$src/examples/shaders" "$out" --target es310 -j 4 | tee "$work/run-$linkage.log"
  grep -q "3 of 3 shaders lowered to es310" "$work/run-$linkage.log"
  for f in globe_rte.vert mandelbrot_deep_zoom.frag orbit_step.comp; do
    [ -s "$out/$f" ] && [ -s "$out/$f.json" ] || { echo "missing output for $f"; exit 1; }
    grep -q '^#version 310 es' "$out/$f"
    code=$(grep -v '^ *//' "$out/$f" || true)
    ! grep -qwE 'double|dvec[234]' <<<"$code" || { echo "$f still has doubles"; exit 1; }
  done
  grep -q '"position_hi"' "$out/globe_rte.vert.json"
done
# Same library, same results, whichever way it is linked.
diff -r "$work/out-static" "$work/out-shared"
echo "asset-compiler: OK"

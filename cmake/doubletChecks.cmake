# Build-wide checking modes (issue: robustness).
#   -DDOUBLET_SANITIZE=address,undefined   instrument everything built here with ASan + UBSan
#   -DDOUBLET_FUZZ=ON                       build fuzz/lower_fuzzer (needs clang with libFuzzer)
set(DOUBLET_SANITIZE "" CACHE STRING "Comma-separated -fsanitize= list (e.g. address,undefined)")
option(DOUBLET_FUZZ "Build the libFuzzer target over doublet::lower (clang only)" OFF)

if(DOUBLET_FUZZ)
  # Coverage feedback from all of doublet, not only the fuzz target's own file. Without the
  # comparison hooks (trace-cmp): they made the sanitizer tests that share this build 11% slower and
  # the fuzz runs no better here (docs/robustness.md, "Fuzzing").
  add_compile_options(-fsanitize=fuzzer-no-link -fno-sanitize-coverage=trace-cmp)
endif()

if(DOUBLET_SANITIZE)
  add_compile_options(-fsanitize=${DOUBLET_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=${DOUBLET_SANITIZE})
  if(DOUBLET_SANITIZE MATCHES "undefined")
    # Debian's glslang is built without RTTI: UBSan's vptr check would need its typeinfo.
    add_compile_options(-fno-sanitize=vptr)
  endif()
endif()

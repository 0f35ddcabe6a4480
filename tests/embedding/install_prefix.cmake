# cmake -P: a fresh `cmake --install` of BUILD_DIR into PREFIX (removed first).
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${PREFIX}" --config "${CONFIG}"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
foreach(f bin/doublet include/doublet/doublet.hpp include/doublet/split.hpp include/doublet/pack.hpp
          lib/libdoublet.a lib/libdoublet.so lib/cmake/doublet/doubletConfig.cmake
          lib/cmake/doublet/doubletConfigVersion.cmake lib/pkgconfig/doublet.pc)
  if(NOT EXISTS "${PREFIX}/${f}")
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()

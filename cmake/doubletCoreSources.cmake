# The sources of the doublet library (parse → import → lowering passes → print → re-validate),
# shared by the native build (src/CMakeLists.txt) and the WebAssembly one (wasm/CMakeLists.txt).
get_filename_component(_doublet_src ${CMAKE_CURRENT_LIST_DIR}/../src ABSOLUTE)
file(GLOB DOUBLET_CORE_SOURCES CONFIGURE_DEPENDS
  ${_doublet_src}/frontend/*.cpp
  ${_doublet_src}/ir/*.cpp
  ${_doublet_src}/lower/*.cpp
  ${_doublet_src}/emit/*.cpp
  ${_doublet_src}/api/*.cpp
  ${_doublet_src}/pipeline/*.cpp
  ${_doublet_src}/target/*.cpp
  ${_doublet_src}/support/*.cpp)

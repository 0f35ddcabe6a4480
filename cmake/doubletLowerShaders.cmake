# doublet_lower_shaders(): lower GLSL shaders with doubles at build time.
#
#   doublet_lower_shaders(TARGET <target> SHADERS <file>...
#                         [TARGET_ES 300|100|310|320]   # output dialect, default 300
#                         [MODE <mode>]                 # reserved: precision modes (see below)
#                         [OUTPUT_DIR <dir>]            # default ${CMAKE_CURRENT_BINARY_DIR}/doublet/<target>
#                         [INCLUDE_DIRS <dir>...]       # searched by #include (-I)
#                         [DEFINES <NAME[=VALUE]>...]   # -D
#                         [EMBED [NAMESPACE <ns>]])     # also a C++ header per shader
#
# For each shader one custom command runs `doublet lower` and writes, in OUTPUT_DIR,
#   <name>          the lowered shader (same file name as the input, e.g. globe.vert)
#   <name>.json     its interface manifest (which variables became _hi/_lo pairs)
#   <name>.d        a depfile listing the shader and every file it #includes, so editing
#                   an include re-lowers exactly the shaders that use it
# and, with EMBED, <name>.hpp (OUTPUT_DIR is added to the target's include directories):
#   namespace <ns>::<name with . and - as _> {
#     inline constexpr std::string_view source   = "...lowered GLSL...";
#     inline constexpr std::string_view manifest = "...manifest JSON...";
#     inline constexpr std::string_view stage = "comp", target = "es310";
#   }
# <ns> defaults to doublet_shaders. The outputs are attached to <target> as sources, so
# they are (re)generated before it builds. The list of outputs is returned in
# DOUBLET_LOWERED_FILES (parent scope).
#
# MODE is reserved for doublet's precision modes: it is passed as `--mode <mode>` when the
# doublet executable has that option, and is an error otherwise (rather than silently
# producing a shader of a different precision than asked for).
include_guard(GLOBAL)

function(_doublet_cli_has_option cli option out_var)
  set(${out_var} FALSE PARENT_SCOPE)
  if(NOT TARGET ${cli})
    return()
  endif()
  get_target_property(imported ${cli} IMPORTED)
  if(NOT imported)
    # Built in this project: not runnable at configure time; trust that it is current.
    set(${out_var} TRUE PARENT_SCOPE)
    return()
  endif()
  get_target_property(path ${cli} LOCATION)
  execute_process(COMMAND ${path} lower --help OUTPUT_VARIABLE help ERROR_QUIET RESULT_VARIABLE rc)
  if(rc EQUAL 0 AND help MATCHES "${option}[ ,=]")
    set(${out_var} TRUE PARENT_SCOPE)
  endif()
endfunction()

function(doublet_lower_shaders)
  cmake_parse_arguments(PARSE_ARGV 0 arg "EMBED" "TARGET;TARGET_ES;MODE;OUTPUT_DIR;NAMESPACE"
                        "SHADERS;INCLUDE_DIRS;DEFINES")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "doublet_lower_shaders: unexpected arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_TARGET OR NOT TARGET ${arg_TARGET})
    message(FATAL_ERROR "doublet_lower_shaders: TARGET must name an existing target (got '${arg_TARGET}')")
  endif()
  if(NOT arg_SHADERS)
    message(FATAL_ERROR "doublet_lower_shaders: SHADERS is empty")
  endif()
  if(NOT DEFINED arg_TARGET_ES)
    set(arg_TARGET_ES 300)
  endif()
  if(NOT arg_TARGET_ES MATCHES "^(100|300|310|320)$")
    message(FATAL_ERROR "doublet_lower_shaders: TARGET_ES must be 100, 300, 310 or 320 (got '${arg_TARGET_ES}')")
  endif()
  if(NOT arg_OUTPUT_DIR)
    set(arg_OUTPUT_DIR ${CMAKE_CURRENT_BINARY_DIR}/doublet/${arg_TARGET})
  endif()
  get_filename_component(out_dir "${arg_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  if(NOT arg_NAMESPACE)
    set(arg_NAMESPACE doublet_shaders)
  endif()

  set(cli doublet::doublet-cli)
  if(NOT TARGET ${cli})
    message(FATAL_ERROR "doublet_lower_shaders: target ${cli} not found (find_package(doublet) first)")
  endif()

  set(options --target es${arg_TARGET_ES})
  if(DEFINED arg_MODE)
    _doublet_cli_has_option(${cli} --mode has_mode)
    if(NOT has_mode)
      message(FATAL_ERROR "doublet_lower_shaders: MODE ${arg_MODE}: this doublet has no precision modes yet "
                          "(MODE is reserved); remove MODE to get the default float-float lowering")
    endif()
    list(APPEND options --mode ${arg_MODE})
  endif()
  foreach(dir IN LISTS arg_INCLUDE_DIRS)
    get_filename_component(dir "${dir}" ABSOLUTE)
    list(APPEND options -I ${dir})
  endforeach()
  foreach(def IN LISTS arg_DEFINES)
    list(APPEND options -D ${def})
  endforeach()

  set(all_outputs)
  foreach(shader IN LISTS arg_SHADERS)
    get_filename_component(input "${shader}" ABSOLUTE)
    get_filename_component(name "${input}" NAME)
    set(lowered ${out_dir}/${name})
    set(manifest ${out_dir}/${name}.json)
    set(depfile ${out_dir}/${name}.d)
    set(outputs ${lowered} ${manifest})
    set(embed_command)
    if(arg_EMBED)
      string(MAKE_C_IDENTIFIER "${name}" symbol)
      set(header ${out_dir}/${name}.hpp)
      list(APPEND outputs ${header})
      set(embed_command COMMAND ${CMAKE_COMMAND} -DLOWERED=${lowered} -DMANIFEST=${manifest}
          -DHEADER=${header} -DNAMESPACE=${arg_NAMESPACE}::${symbol} -DSOURCE_NAME=${name}
          -P ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/doublet_embed_shader.cmake)
    endif()
    add_custom_command(
      OUTPUT ${outputs}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${out_dir}
      COMMAND ${cli} lower ${input} ${options} -o ${lowered} --manifest ${manifest} -MD -MF ${depfile}
      ${embed_command}
      MAIN_DEPENDENCY ${input}
      DEPENDS ${cli} ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/doublet_embed_shader.cmake
      DEPFILE ${depfile}
      COMMENT "doublet: lowering ${shader} to es${arg_TARGET_ES}"
      VERBATIM)
    list(APPEND all_outputs ${outputs})
  endforeach()

  target_sources(${arg_TARGET} PRIVATE ${all_outputs})
  if(arg_EMBED)
    target_include_directories(${arg_TARGET} PRIVATE ${out_dir})
  endif()
  set(DOUBLET_LOWERED_FILES ${all_outputs} PARENT_SCOPE)
endfunction()

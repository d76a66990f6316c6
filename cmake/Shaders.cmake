# Shader compilation: GLSL -> SPIR-V (glslangValidator, Vulkan 1.3 / SPIR-V 1.6) -> spirv-val ->
# a generated header with the words as a uint32_t array, compiled into the binary so `pond` runs
# from any directory.
#
# pond_add_shaders(TARGET <target> SOURCES <a.comp> ... [VARIANT <suffix> DEFINES <MACRO> ...])
#   Each <name>.<stage> becomes <binary dir>/spirv/<name><suffix>_<stage>.spv.h declaring
#   `const uint32_t pond_spirv_<name><suffix>_<stage>[]` (a VARIANT is the same source compiled
#   with the DEFINES); the headers are sources of <target> and the
#   directory is on its include path. Every shader depends on all of shaders/shared/*.h (the
#   headers shared by GLSL and C++), so changing a shared layout rebuilds every shader.
file(GLOB POND_SHARED_SHADER_HEADERS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/shaders/shared/*.h)

function(pond_add_shaders)
  cmake_parse_arguments(S "" "TARGET;VARIANT" "SOURCES;DEFINES" ${ARGN})
  set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/spirv)
  file(MAKE_DIRECTORY ${out_dir})
  set(headers)
  foreach(src ${S_SOURCES})
    get_filename_component(abs ${src} ABSOLUTE)
    get_filename_component(name ${src} NAME_WE)
    set(name ${name}${S_VARIANT})
    get_filename_component(ext ${src} LAST_EXT)
    string(SUBSTRING ${ext} 1 -1 stage)
    set(var pond_spirv_${name}_${stage})
    set(spv ${out_dir}/${name}_${stage}.spv)
    set(header ${out_dir}/${name}_${stage}.spv.h)
    set(flags -V --target-env vulkan1.3 -I${PROJECT_SOURCE_DIR}/shaders --quiet)
    foreach(d ${S_DEFINES})
      list(APPEND flags -D${d})
    endforeach()
    add_custom_command(
      OUTPUT ${header} ${spv}
      COMMAND ${GLSLANG_VALIDATOR} ${flags} -o ${spv} ${abs}
      COMMAND ${SPIRV_VAL} --target-env vulkan1.3 ${spv}
      COMMAND ${GLSLANG_VALIDATOR} ${flags} --vn ${var} -o ${header} ${abs}
      DEPENDS ${abs} ${POND_SHARED_SHADER_HEADERS}
      COMMENT "GLSL -> SPIR-V (validated, embedded): ${name}.${stage}"
      VERBATIM)
    list(APPEND headers ${header})
  endforeach()
  target_sources(${S_TARGET} PRIVATE ${headers})
  target_include_directories(${S_TARGET} PRIVATE ${out_dir})
endfunction()

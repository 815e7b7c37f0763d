# Compiles GLSL to SPIR-V at build time and builds it into the library `target`. glslangValidator writes a depfile, so a
# change to any included header under shaders/shared/ rebuilds the shaders using it. An entry NAME=SOURCE:MACRO
# builds SOURCE a second time as NAME with MACRO defined (a variant that keeps the plain build as it is);
# MACRO+MACRO defines both.
function(grotto_add_shaders target)
  set(outputs)
  foreach(entry IN LISTS ARGN)
    set(defines)
    if(entry MATCHES "^([^=]+)=([^:]+):(.+)$")
      set(name ${CMAKE_MATCH_1})
      set(src ${CMAKE_MATCH_2})
      string(REPLACE "+" ";" macros ${CMAKE_MATCH_3})
      foreach(macro IN LISTS macros)
        list(APPEND defines -D${macro})
      endforeach()
    else()
      set(src ${entry})
      get_filename_component(name ${src} NAME)
    endif()
    set(in ${CMAKE_CURRENT_SOURCE_DIR}/${src})
    set(out ${GROTTO_SHADER_DIR}/${name}.spv)
    add_custom_command(
      OUTPUT ${out}
      COMMAND ${GLSLANG_VALIDATOR} --quiet --target-env vulkan1.2 ${defines}
              -I${CMAKE_SOURCE_DIR}/shaders --depfile ${out}.d -o ${out} ${in}
      DEPENDS ${in}
      DEPFILE ${out}.d
      COMMENT "glslang ${name}"
      VERBATIM)
    list(APPEND outputs ${out})
  endforeach()
  # The SPIR-V built into a static library (engine/vk/embedded_shaders.h); the .spv
  # files stay for GROTTO_SHADER_DIR, which loads shaders from a directory instead.
  set(embedded ${CMAKE_CURRENT_BINARY_DIR}/${target}_embedded.cpp)
  add_custom_command(
    OUTPUT ${embedded}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${embedded} "-DSPIRV=${outputs}" -P ${PROJECT_SOURCE_DIR}/cmake/EmbedShaders.cmake
    DEPENDS ${outputs} ${PROJECT_SOURCE_DIR}/cmake/EmbedShaders.cmake ${PROJECT_SOURCE_DIR}/cmake/HexArray.cmake
    COMMENT "embedding ${target}"
    VERBATIM)
  add_library(${target} STATIC ${embedded})
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR})
endfunction()

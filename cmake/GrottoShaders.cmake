# Compiles GLSL to SPIR-V at build time. glslangValidator writes a depfile, so a
# change to any included header under shaders/shared/ rebuilds the shaders using it.
function(grotto_add_shaders target)
  set(outputs)
  foreach(src IN LISTS ARGN)
    get_filename_component(name ${src} NAME)
    set(in ${CMAKE_CURRENT_SOURCE_DIR}/${src})
    set(out ${GROTTO_SHADER_DIR}/${name}.spv)
    add_custom_command(
      OUTPUT ${out}
      COMMAND ${GLSLANG_VALIDATOR} --quiet --target-env vulkan1.2
              -I${CMAKE_SOURCE_DIR}/shaders --depfile ${out}.d -o ${out} ${in}
      DEPENDS ${in}
      DEPFILE ${out}.d
      COMMENT "glslang ${name}"
      VERBATIM)
    list(APPEND outputs ${out})
  endforeach()
  add_custom_target(${target} ALL DEPENDS ${outputs})
endfunction()

# grotto_hex_array(OUT FILE NAME): sets OUT to C++ for `alignas(16) const unsigned char NAME[]`
# holding FILE's bytes, 32 to a line (EmbedShaders.cmake, EmbedProgram.cmake). An empty file is an error.
function(grotto_hex_array out file name)
  file(READ ${file} hex HEX)
  if(hex STREQUAL "")
    message(FATAL_ERROR "${file} is empty")
  endif()
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
  string(REGEX REPLACE "((0x..,){32})" "\\1\n" bytes "${bytes}")
  set(${out} "alignas(16) const unsigned char ${name}[] = {\n${bytes}};\n" PARENT_SCOPE)
endfunction()

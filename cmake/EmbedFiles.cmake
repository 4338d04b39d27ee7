# Embeds text files into C++ at build time.
# tlab_embed_files(TARGET BASE_DIR NAMESPACE FUNCTION file1 file2 ...) produces a translation unit
# defining NAMESPACE::FUNCTION(name) -> the file's text, where name is the path relative to BASE_DIR.
function(tlab_embed_files target base_dir namespace function)
  set(out_cpp ${CMAKE_CURRENT_BINARY_DIR}/${target}_${function}.cpp)
  set(inputs)
  foreach(f IN LISTS ARGN)
    list(APPEND inputs ${base_dir}/${f})
  endforeach()
  add_custom_command(
    OUTPUT ${out_cpp}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out_cpp} -DBASE=${base_dir} "-DFILES=${ARGN}" -DNAMESPACE=${namespace} -DFUNCTION=${function}
            -P ${CMAKE_SOURCE_DIR}/cmake/EmbedFilesScript.cmake
    DEPENDS ${inputs} ${CMAKE_SOURCE_DIR}/cmake/EmbedFilesScript.cmake
    COMMENT "Embedding ${function} files for ${target}" VERBATIM)
  target_sources(${target} PRIVATE ${out_cpp})
endfunction()

# GLSL files next to the passes that own them: tlab::gpu::embeddedShader("buffer/fill.frag").
function(tlab_embed_shaders target base_dir)
  tlab_embed_files(${target} ${base_dir} tlab::gpu embeddedShader ${ARGN})
endfunction()

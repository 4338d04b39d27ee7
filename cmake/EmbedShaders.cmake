# Embeds GLSL files into C++ at build time: tlab_embed_shaders(TARGET file1.glsl file2.comp ...)
# produces a translation unit defining tlab::gpu::embeddedShader(name) -> source text, where name
# is the path relative to the owning folder (e.g. "buffer/fill.frag").
function(tlab_embed_shaders target base_dir)
  set(out_cpp ${CMAKE_CURRENT_BINARY_DIR}/${target}_shaders.cpp)
  set(inputs)
  foreach(f IN LISTS ARGN)
    list(APPEND inputs ${base_dir}/${f})
  endforeach()
  add_custom_command(
    OUTPUT ${out_cpp}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out_cpp} -DBASE=${base_dir} "-DFILES=${ARGN}"
            -P ${CMAKE_SOURCE_DIR}/cmake/EmbedShadersScript.cmake
    DEPENDS ${inputs} ${CMAKE_SOURCE_DIR}/cmake/EmbedShadersScript.cmake
    COMMENT "Embedding shaders for ${target}" VERBATIM)
  target_sources(${target} PRIVATE ${out_cpp})
endfunction()

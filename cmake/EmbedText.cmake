# Embeds text files (the particle presets) in the library as char arrays, so the binary finds them
# from any directory. A build-time step (EmbedTextFiles.cmake) regenerates the .cpp whenever one of
# the files changes; each entry is named after its file, without the extension.
function(lll_embed_text target function header sources)
  set(output ${CMAKE_BINARY_DIR}/generated/${function}.cpp)
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} "-DINPUTS=${sources}" -DOUTPUT=${output} -DFUNCTION=${function}
            -DHEADER=${header} -P ${CMAKE_SOURCE_DIR}/cmake/EmbedTextFiles.cmake
    DEPENDS ${sources} ${CMAKE_SOURCE_DIR}/cmake/EmbedTextFiles.cmake
    COMMENT "embed ${function}"
    VERBATIM)
  target_sources(${target} PRIVATE ${output})
endfunction()

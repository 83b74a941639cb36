# vitrine_embed_text(OUT_CPP SOURCE NAMESPACE FUNCTION)
# Generates OUT_CPP at build time defining `std::string_view NAMESPACE::FUNCTION()` that returns the
# text of SOURCE, so a file edited as itself (the remote control's page) ships inside the binary and
# an edit rebuilds it.
function(vitrine_embed_text out_cpp source namespace function)
  add_custom_command(
    OUTPUT ${out_cpp}
    COMMAND ${CMAKE_COMMAND} -DSOURCE=${source} -DOUTPUT=${out_cpp} -DNAMESPACE=${namespace}
            -DFUNCTION=${function} -P ${CMAKE_SOURCE_DIR}/cmake/embed_text_script.cmake
    DEPENDS ${source} ${CMAKE_SOURCE_DIR}/cmake/embed_text_script.cmake
    COMMENT "Embedding ${source}"
    VERBATIM)
endfunction()

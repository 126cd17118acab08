# Fails when docs/keywords.md differs from what the keyword declarations generate now.
# cmake -DRADX=<radx executable> -DDOC=<docs/keywords.md> -DTMP=<scratch file> -P check_keywords_doc.cmake
execute_process(COMMAND ${RADX} keywords --markdown --output ${TMP} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "radx keywords failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${TMP} ${DOC} RESULT_VARIABLE diff)
if(NOT diff EQUAL 0)
  message(FATAL_ERROR "docs/keywords.md is out of date: run `cmake --build build --target keyword-docs` and commit it")
endif()

# Writes OUT (version.h) from IN with the version and the source tree's git
# revision; rewrites it only when the text changes, so a build after a new
# commit recompiles the one file that uses it. Runs at build time.
set(IGAPREP_GIT_REVISION "unknown")
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} rev-parse --short=12 HEAD
                  OUTPUT_VARIABLE _rev OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE _ok ERROR_QUIET)
  if(_ok EQUAL 0 AND _rev)
    set(IGAPREP_GIT_REVISION "${_rev}")
    execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} diff --quiet HEAD --
                    RESULT_VARIABLE _dirty ERROR_QUIET)
    if(NOT _dirty EQUAL 0)
      string(APPEND IGAPREP_GIT_REVISION "-modified")
    endif()
  endif()
endif()
configure_file(${IN} ${OUT}.tmp @ONLY)
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)

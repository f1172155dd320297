# Writes the generated version header at build time (so the git description is that of the
# code being compiled, not of the last CMake configure). Rewrites it only when it changes, so an
# unchanged tree recompiles nothing.
#   cmake -DSOURCE_DIR=... -DINPUT=version.h.in -DOUTPUT=.../version.h -DPROJECT_VERSION=...
#         -DCMAKE_CXX_COMPILER_ID=... -DCMAKE_CXX_COMPILER_VERSION=... -DCMAKE_BUILD_TYPE=...
#         -P version.cmake
set(CURVBENCH_GIT_DESCRIBE "unknown")
find_package(Git QUIET)
if(GIT_FOUND AND EXISTS "${SOURCE_DIR}/.git")
  execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --tags
                  WORKING_DIRECTORY ${SOURCE_DIR}
                  OUTPUT_VARIABLE _describe OUTPUT_STRIP_TRAILING_WHITESPACE
                  RESULT_VARIABLE _rc ERROR_QUIET)
  if(_rc EQUAL 0 AND _describe)
    set(CURVBENCH_GIT_DESCRIBE "${_describe}")
    # "-dirty" describes the code: changes under results/ (regenerated outputs) do not count.
    execute_process(COMMAND ${GIT_EXECUTABLE} status --porcelain --untracked-files=no -- .
                            ":(exclude)results"
                    WORKING_DIRECTORY ${SOURCE_DIR}
                    OUTPUT_VARIABLE _changes OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(_changes)
      set(CURVBENCH_GIT_DESCRIBE "${CURVBENCH_GIT_DESCRIBE}-dirty")
    endif()
  endif()
endif()
configure_file(${INPUT} ${OUTPUT}.tmp @ONLY)
file(READ ${OUTPUT}.tmp _new)
set(_old "")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} _old)
endif()
if(NOT _new STREQUAL _old)
  file(RENAME ${OUTPUT}.tmp ${OUTPUT})
else()
  file(REMOVE ${OUTPUT}.tmp)
endif()

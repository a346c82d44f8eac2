# Writes the commit the build comes from into two generated sources, at every build and not only
# at configure time, so that a certificate names the commit that produced it (a build dir kept
# across commits used to stamp every certificate with the commit it was configured at).
# "-modified" is appended when tracked files outside proofs/ differ from that commit; proofs/ is
# left out because `make proofs` rewrites it. configure_file rewrites a file only when its text
# changes, so an unchanged commit recompiles nothing.
#   cmake -DSOURCE_DIR=... -DBINARY_DIR=... -DPROJECT_VERSION=... -P cmake/commit.cmake
execute_process(COMMAND git rev-parse --short=12 HEAD WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE SUPERPACK_GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT SUPERPACK_GIT_COMMIT)
  set(SUPERPACK_GIT_COMMIT "unknown")
else()
  execute_process(COMMAND git status --porcelain --untracked-files=no -- . ":(exclude)proofs"
                  WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE changes ERROR_QUIET)
  if(changes)
    string(APPEND SUPERPACK_GIT_COMMIT "-modified")
  endif()
endif()
configure_file(${SOURCE_DIR}/src/cert/version.cpp.in ${BINARY_DIR}/version.cpp @ONLY)
configure_file(${SOURCE_DIR}/checker/build_commit.cpp.in ${BINARY_DIR}/checker_build_commit.cpp @ONLY)

# Script mode, run at every build (not only at configure time): writes OUT, a C++ file defining
# tlab::app::buildRevision() -> the git revision of SOURCE_DIR as it is being built: the short
# commit, with "-dirty" where a tracked file differs from it (what a study then records was built
# from more than that commit), or "unknown" where SOURCE_DIR is no git checkout of its own (a
# tarball, or a folder inside some other repository). OUT is rewritten only when the revision
# changed, so an unchanged tree relinks nothing. Reads the checkout only (no index refresh written).
set(revision unknown)
execute_process(COMMAND git -C ${SOURCE_DIR} rev-parse --show-toplevel
                OUTPUT_VARIABLE top RESULT_VARIABLE rc OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(rc EQUAL 0)
  file(REAL_PATH "${top}" top)
  file(REAL_PATH "${SOURCE_DIR}" source)
endif()
if(rc EQUAL 0 AND top STREQUAL source)
  execute_process(COMMAND git -C ${SOURCE_DIR} rev-parse --short HEAD
                  OUTPUT_VARIABLE commit RESULT_VARIABLE rc OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(rc EQUAL 0 AND NOT commit STREQUAL "")
    set(revision ${commit})
    execute_process(COMMAND git --no-optional-locks -C ${SOURCE_DIR} status --porcelain --untracked-files=no
                    OUTPUT_VARIABLE changes RESULT_VARIABLE rc ERROR_QUIET)
    if(NOT rc EQUAL 0 OR NOT changes STREQUAL "")
      string(APPEND revision "-dirty")
    endif()
  endif()
endif()
string(CONCAT text "// Generated at build time by cmake/RevisionScript.cmake. Do not edit.\n"
                   "#include \"app/build_revision.hpp\"\n"
                   "namespace tlab::app {\n"
                   "std::string_view buildRevision() { return \"${revision}\"; }\n"
                   "}  // namespace tlab::app\n")
file(WRITE ${OUT}.tmp "${text}")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUT}.tmp)

# Writes OUTPUT with RBSIM_COMMIT, the git commit of SOURCE_DIR ("-dirty" with uncommitted
# changes, "unknown" without git), at every build; the file is only rewritten when the commit
# changes, so only the one file that includes it recompiles. Run by app/CMakeLists.txt.
execute_process(COMMAND git -C "${SOURCE_DIR}" describe --always --dirty --abbrev=12
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE failed)
if(failed OR commit STREQUAL "")
  set(commit "unknown")
endif()
set(text "#define RBSIM_COMMIT \"${commit}\"\n")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUTPUT}" "${text}")
endif()

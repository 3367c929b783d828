# Every user-visible string of the wizard has its Norwegian text: lupdate
# reads the sources into a copy of the committed .ts; a string that is new
# (type="unfinished") or whose text lupdate cannot see any more (vanished, so
# lrelease would drop it) fails the test with its source text.
# The project file is the one qt_add_translations writes for auv_ui, so
# lupdate sees the same sources and include paths as the update target.
#   cmake -DLUPDATE=... -DGENERATE=... -DPROJECT_IN=... -DTS=... -DWORK=... -P check_translations.cmake
file(MAKE_DIRECTORY "${WORK}")
set(copy "${WORK}/auvballast_nb_check.ts")
configure_file("${TS}" "${copy}" COPYONLY)
execute_process(COMMAND "${CMAKE_COMMAND}" -DIN_FILE=${PROJECT_IN} -DOUT_FILE=${WORK}/project.json -P "${GENERATE}"
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cannot write the lupdate project from ${PROJECT_IN}")
endif()
execute_process(COMMAND "${LUPDATE}" -silent -project "${WORK}/project.json" -ts "${copy}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "lupdate failed (${rc}): ${out}${err}")
endif()
file(READ "${copy}" ts)
cmake_policy(SET CMP0007 NEW)
string(REGEX MATCHALL "<source>[^<]*</source>[ \n\r\t]*<translation type=\"(unfinished|vanished|obsolete)\"" bad "${ts}")
list(LENGTH bad n)
if(n GREATER 0)
  string(REPLACE ";" "\n" listing "${bad}")
  message(FATAL_ERROR "${n} string(s) without a Norwegian text in ${TS}:\n${listing}\n"
                      "Fix: cmake --build <build> --target update_translations, translate them, commit the .ts.")
endif()
message(STATUS "every wizard string has its Norwegian text")

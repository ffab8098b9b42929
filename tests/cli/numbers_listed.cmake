# Checks that every numeric option (FLOAT, INT or UINT) that `WALKRAD SUBCOMMAND --help` lists,
# for each of SUBCOMMANDS, is among LISTED ("SUBCOMMAND OPTION" entries joined by '|'): a new
# option cannot escape the table of refused values in cli_tests.cmake.
cmake_minimum_required(VERSION 3.25)
string(REPLACE "|" ";" subcommands "${SUBCOMMANDS}")
string(REPLACE "|" ";" listed "${LISTED}")
foreach(subcommand IN LISTS subcommands)
  execute_process(COMMAND ${WALKRAD} ${subcommand} --help OUTPUT_VARIABLE help RESULT_VARIABLE code)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${WALKRAD} ${subcommand} --help: exit code ${code}")
  endif()
  string(REGEX MATCHALL "\n  (--[a-z-]+) (FLOAT|INT|UINT)" numeric "${help}")
  foreach(match IN LISTS numeric)
    string(REGEX REPLACE "\n  (--[a-z-]+) .*" "\\1" option "${match}")
    if(NOT "${subcommand} ${option}" IN_LIST listed)
      message(FATAL_ERROR "walkrad ${subcommand} ${option} takes a number but cli_tests.cmake does not try it")
    endif()
  endforeach()
endforeach()

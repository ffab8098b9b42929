# Runs PREFIX (the command's words joined by '|') followed by OPTION and each of VALUES (joined
# by '|') in turn, and checks each is refused: exit 2 and one line on stderr naming the option.
string(REPLACE "|" ";" values "${VALUES}")
set(EXIT 2)
set(STDERR_REGEX "^walkrad: ${OPTION}: [a-z ]+: ")
foreach(value IN LISTS values)
  message(STATUS "${OPTION} ${value}")
  set(COMMAND "${PREFIX}|${OPTION}|${value}")
  include(${CMAKE_CURRENT_LIST_DIR}/expect_exit.cmake)
endforeach()

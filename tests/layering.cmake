# The module table of DESIGN.md and the engine's sub-folders, checked on the includes: the files
# of a folder include the project's headers only from the folders it may depend on, so arrows
# point one way only. Run as: cmake -DSOURCE=<project source folder> -P layering.cmake
#
# Each folder (its own files, not its sub-folders' files) with the folders it may include from,
# separated by '|'. The program (app/) sees the engine through its public headers only: no
# radiosity/, mesher/ or pxpl5/ include, so the engine stays the one way to mesh and light.
cmake_minimum_required(VERSION 3.25)

set(app_may "app|app/cli|app/gl|app/image|app/window|engine|engine/geometry|engine/io|engine/document|engine/session|shaders|util")

set(layers
  "util"            "util"
  "mesher"          "mesher|util"
  "pxpl5"           "pxpl5|util"
  "radiosity"       "radiosity|pxpl5|util"
  "engine"          "engine|mesher|util"
  "engine/geometry" "engine|engine/geometry|mesher|radiosity|util"
  "engine/io"       "engine|engine/geometry|engine/io|mesher|radiosity|util"
  "engine/document" "engine|engine/geometry|engine/io|engine/document|mesher|radiosity|util"
  "engine/session"  "engine|engine/geometry|engine/io|engine/document|engine/session|mesher|radiosity|util"
  "app"             "${app_may}"
  "app/cli"         "${app_may}"
  "app/gl"          "${app_may}"
  "app/image"       "${app_may}"
  "app/window"      "${app_may}")
# An include naming a file under one of these is the project's; any other is a library's.
set(project_folders app engine mesher pxpl5 radiosity shaders tests util)

set(problems "")
set(listed "")
list(LENGTH layers count)
math(EXPR last "${count} - 1")
foreach(i RANGE 0 ${last} 2)
  math(EXPR j "${i} + 1")
  list(GET layers ${i} folder)
  list(GET layers ${j} allowed)
  string(REPLACE "|" ";" allowed "${allowed}")
  list(APPEND listed ${folder})
  file(GLOB files ${SOURCE}/${folder}/*.h ${SOURCE}/${folder}/*.cpp)
  if(NOT files)
    string(APPEND problems "\n  ${folder}: no files (a folder moved? update tests/layering.cmake)")
  endif()
  foreach(file ${files})
    file(STRINGS ${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach(line ${includes})
      string(REGEX REPLACE "^[^\"]*\"([^\"]*)\".*$" "\\1" header "${line}")
      string(REGEX MATCH "^[^/]+" top "${header}")
      if(NOT top IN_LIST project_folders OR NOT header MATCHES "/")
        continue()
      endif()
      get_filename_component(from ${header} DIRECTORY)
      if(NOT from IN_LIST allowed)
        file(RELATIVE_PATH name ${SOURCE} ${file})
        string(JOIN ", " may ${allowed})
        string(APPEND problems "\n  ${name} includes ${header} (${folder}/ may include from ${may} only)")
      endif()
    endforeach()
  endforeach()
endforeach()

# A sub-folder of the engine or the program that is not listed would go unchecked.
file(GLOB entries LIST_DIRECTORIES true ${SOURCE}/engine/* ${SOURCE}/app/*)
foreach(entry ${entries})
  if(IS_DIRECTORY ${entry})
    file(RELATIVE_PATH name ${SOURCE} ${entry})
    if(NOT name IN_LIST listed)
      string(APPEND problems "\n  ${name}/ is not in tests/layering.cmake's layers")
    endif()
  endif()
endforeach()

# The engine runs without a display (tests drive a session's frames with none): no window
# system, GL or UI library is included anywhere in it.
file(GLOB_RECURSE engine_files ${SOURCE}/engine/*.h ${SOURCE}/engine/*.cpp)
foreach(file ${engine_files})
  file(STRINGS ${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*<(GLFW|glad|GL|EGL|imgui)")
  foreach(line ${includes})
    file(RELATIVE_PATH name ${SOURCE} ${file})
    string(STRIP "${line}" line)
    string(APPEND problems "\n  ${name}: ${line} (engine/ uses no window system, GL or ImGui)")
  endforeach()
endforeach()

if(problems)
  message(FATAL_ERROR "includes against the layering:${problems}")
endif()

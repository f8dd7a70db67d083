# cmake -DSOURCE_DIR=<checkout> -DLUPDATE=<lupdate> -DWORK_DIR=<scratch dir> -P check_translations.cmake
# Every user-visible string of the application is translated: runs lupdate over the sources on
# copies of translations/devsurf_{de,ja}.ts and fails if any entry is then unfinished (a string
# added to the code but not to the translations).
if(NOT SOURCE_DIR OR NOT LUPDATE OR NOT WORK_DIR)
  message(FATAL_ERROR "usage: cmake -DSOURCE_DIR=... -DLUPDATE=... -DWORK_DIR=... -P check_translations.cmake")
endif()
file(GLOB_RECURSE sources
  ${SOURCE_DIR}/app/gui/*.cpp ${SOURCE_DIR}/app/gui/*.h
  ${SOURCE_DIR}/app/text/*.cpp ${SOURCE_DIR}/app/text/*.h
  ${SOURCE_DIR}/views/*.cpp ${SOURCE_DIR}/views/*.h
  ${SOURCE_DIR}/model/document/*.cpp ${SOURCE_DIR}/model/document/*.h)
file(MAKE_DIRECTORY ${WORK_DIR})
string(REPLACE ";" "\n" list "${sources}")
file(WRITE ${WORK_DIR}/sources.lst "${list}\n")
set(failed "")
foreach(language de ja)
  configure_file(${SOURCE_DIR}/translations/devsurf_${language}.ts
                 ${WORK_DIR}/devsurf_${language}.ts COPYONLY)
  execute_process(
    COMMAND ${LUPDATE} -no-obsolete @${WORK_DIR}/sources.lst -ts ${WORK_DIR}/devsurf_${language}.ts
    RESULT_VARIABLE result OUTPUT_QUIET ERROR_QUIET)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "lupdate failed on devsurf_${language}.ts")
  endif()
  file(STRINGS ${WORK_DIR}/devsurf_${language}.ts lines)
  set(previous "")
  foreach(line IN LISTS lines)
    if(line MATCHES "type=\"unfinished\"")
      list(APPEND failed "devsurf_${language}.ts: not translated: ${previous}")
    endif()
    if(line MATCHES "<source>")
      set(previous "${line}")
    endif()
  endforeach()
endforeach()
if(failed)
  string(REPLACE ";" "\n" text "${failed}")
  message(FATAL_ERROR "${text}\nUpdate with: cmake --build build --target update_translations, then translate.")
endif()
message(STATUS "Every string is translated (de, ja).")

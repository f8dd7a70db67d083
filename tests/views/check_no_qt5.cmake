# cmake -DBINARY=<executable> -P check_no_qt5.cmake
# Fails if the executable's shared-library closure contains any Qt 5 library.
execute_process(COMMAND ldd "${BINARY}" OUTPUT_VARIABLE libraries RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "ldd failed on ${BINARY}")
endif()
# ldd must have listed the libraries we do link, or the check below proves nothing.
if(NOT libraries MATCHES "libQt6Widgets" OR NOT libraries MATCHES "libvtkRenderingOpenGL2")
  message(FATAL_ERROR "ldd output of ${BINARY} lacks Qt 6 or VTK:\n${libraries}")
endif()
string(REGEX MATCHALL "libQt5[A-Za-z0-9_]*" qt5 "${libraries}")
if(qt5)
  list(REMOVE_DUPLICATES qt5)
  message(FATAL_ERROR "${BINARY} links Qt 5: ${qt5}")
endif()
message(STATUS "${BINARY}: no Qt 5 libraries")

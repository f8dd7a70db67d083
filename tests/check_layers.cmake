# cmake -DSOURCE_DIR=<checkout> -P check_layers.cmake
# Enforces the layer rules of the architecture on the #include lines of every source file:
#   model/ (outside model/document/)  no Qt, no VTK; nothing of solver/, io/, views/, app/
#   model/document/                   no Qt Widgets, no VTK; nothing of solver/, io/, views/, app/
#   solver/core/                      no Qt, no OpenMesh, no VTK; nothing of io/, views/, app/
#   solver/ (outside solver/worker/)  no Qt, no VTK; nothing of io/, views/, app/
#   solver/worker/                    no Qt Widgets or Gui, no VTK; nothing of io/, views/, app/
#   io/                               no VTK; nothing of views/, app/
#   views/                            nothing of io/, app/
# Fails with one line per offending include.
if(NOT SOURCE_DIR)
  message(FATAL_ERROR "usage: cmake -DSOURCE_DIR=<checkout> -P check_layers.cmake")
endif()

set(qt_any "<Q[A-Za-z]|<Qt[A-Za-z]*/")
set(qt_widgets "<Qt(Widgets|PrintSupport|OpenGLWidgets)/|<Q(Widget|Application|MainWindow|Dialog|MessageBox|Action|Menu|ToolBar|DockWidget|FileDialog|PushButton|Label|LineEdit|SpinBox|DoubleSpinBox|ComboBox|CheckBox|Printer|PrintDialog|PrintPreviewDialog|OpenGLWidget)>")
set(qt_gui "<QtGui/|<Q(Painter|Image|Color|PdfWriter|Font|Pixmap|Icon|GuiApplication)>")
set(vtk "<vtk")
set(openmesh "<OpenMesh/")

cmake_policy(SET CMP0007 NEW)
set(violations "")
set(checked 0)

# check(NAME FOLDER EXCLUDED_SUBFOLDER_OR_EMPTY FORBIDDEN_REGEX...)
function(check name folder excluded)
  string(JOIN "|" forbidden ${ARGN})
  file(GLOB_RECURSE files "${SOURCE_DIR}/${folder}/*.h" "${SOURCE_DIR}/${folder}/*.cpp")
  foreach(file IN LISTS files)
    file(RELATIVE_PATH relative "${SOURCE_DIR}" "${file}")
    if(NOT excluded STREQUAL "" AND relative MATCHES "^${excluded}/")
      continue()
    endif()
    math(EXPR checked "${checked} + 1")
    file(STRINGS "${file}" includes REGEX "^[ \t]*#[ \t]*include")
    foreach(line IN LISTS includes)
      if(line MATCHES "${forbidden}")
        string(STRIP "${line}" line)
        string(APPEND violations "  ${relative} (${name}): ${line}\n")
      endif()
    endforeach()
  endforeach()
  set(checked ${checked} PARENT_SCOPE)
  set(violations "${violations}" PARENT_SCOPE)
endfunction()

set(not_above_model "\"(solver|io|views|app)/")
check(model model model/document "${qt_any}" "${vtk}" "${not_above_model}")
check(model/document model/document "" "${qt_widgets}" "${vtk}" "${not_above_model}")
check(solver/core solver/core "" "${qt_any}" "${openmesh}" "${vtk}" "\"(io|views|app)/")
check(solver solver solver/worker "${qt_any}" "${vtk}" "\"(io|views|app)/")
check(solver/worker solver/worker "" "${qt_widgets}" "${qt_gui}" "${vtk}" "\"(io|views|app)/")
check(io io "" "${vtk}" "\"(views|app)/")
check(views views "" "\"(io|app)/")

# A check that read no files proves nothing.
if(checked LESS 20)
  message(FATAL_ERROR "the layer check read only ${checked} files under ${SOURCE_DIR}")
endif()
if(violations)
  message(FATAL_ERROR "includes that break the layer rules:\n${violations}")
endif()
message(STATUS "layer rules hold in ${checked} files")

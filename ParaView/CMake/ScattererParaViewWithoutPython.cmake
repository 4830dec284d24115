# Lets find_package(ParaView) work when python3-paraview is not installed.
#
# Debian's paraview-dev CMake files import ParaView's Python modules and pvpython,
# whose files come from python3-paraview; that package conflicts with python3-vtk9 /
# libvtk9-dev (which the rest of this project builds against), so it is not installed
# here, and CMake's check of imported files would stop the configure. The plugin uses
# none of those targets: when python3-paraview is missing, they are declared
# beforehand (Python modules as empty interface targets, the tools as imported
# programs), and CMake's targets files then skip themselves ("all targets already
# defined"). Nothing changes when python3-paraview is installed.
if (EXISTS "/usr/lib/python3/dist-packages/paraview/__init__.py")
  return ()
endif ()
set(_scatterer_pv_cmake_dir "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/paraview-5.11")
if (ParaView_DIR)
  set(_scatterer_pv_cmake_dir "${ParaView_DIR}")
endif ()
foreach (_scatterer_targets_file IN ITEMS
    "${_scatterer_pv_cmake_dir}/vtk/VTKPython-targets.cmake"
    "${_scatterer_pv_cmake_dir}/ParaViewPython-targets.cmake"
    "${_scatterer_pv_cmake_dir}/ParaViewTools-targets.cmake")
  if (NOT EXISTS "${_scatterer_targets_file}")
    continue ()
  endif ()
  file(STRINGS "${_scatterer_targets_file}" _scatterer_line
    REGEX "^foreach\\(_cmake_expected_target IN ITEMS ")
  string(REGEX REPLACE "^foreach\\(_cmake_expected_target IN ITEMS (.*)\\)$" "\\1"
    _scatterer_targets "${_scatterer_line}")
  separate_arguments(_scatterer_targets)
  foreach (_scatterer_target IN LISTS _scatterer_targets)
    if (TARGET "${_scatterer_target}")
      continue ()
    endif ()
    if (_scatterer_targets_file MATCHES "Tools-targets")
      # ParaView::pvbatch -> /usr/bin/pvbatch (from the paraview package)
      string(REPLACE "ParaView::" "" _scatterer_tool "${_scatterer_target}")
      add_executable("${_scatterer_target}" IMPORTED)
      set_target_properties("${_scatterer_target}" PROPERTIES
        IMPORTED_LOCATION "/usr/bin/${_scatterer_tool}")
    else ()
      add_library("${_scatterer_target}" INTERFACE IMPORTED)
    endif ()
  endforeach ()
endforeach ()

# ParaView's wrapping hierarchy files (which class derives from which, needed to wrap
# the plugin's classes for the server manager) also come with python3-paraview.
# scripts/build-paraview-plugin.sh unpacks that package, without installing it, into
# SCATTERER_PARAVIEW_PYTHON_ROOT; after find_package(ParaView), this points the
# imported modules' hierarchy files there when they are not installed.
function (scatterer_redirect_paraview_hierarchy)
  get_property(_targets DIRECTORY PROPERTY IMPORTED_TARGETS)
  set(_redirected 0)
  foreach (_target IN LISTS _targets)
    get_property(_file TARGET "${_target}" PROPERTY INTERFACE_vtk_module_hierarchy)
    if (NOT _file OR EXISTS "${_file}")
      continue ()
    endif ()
    set(_unpacked "${SCATTERER_PARAVIEW_PYTHON_ROOT}${_file}")
    if (NOT SCATTERER_PARAVIEW_PYTHON_ROOT OR NOT EXISTS "${_unpacked}")
      message(FATAL_ERROR
        "ParaView's wrapping hierarchy file ${_file} is missing: it comes with "
        "python3-paraview, which conflicts with libvtk9-dev. Unpack it without installing "
        "(scripts/build-paraview-plugin.sh does) and pass "
        "-DSCATTERER_PARAVIEW_PYTHON_ROOT=<folder it was unpacked into>.")
    endif ()
    set_property(TARGET "${_target}" PROPERTY INTERFACE_vtk_module_hierarchy "${_unpacked}")
    math(EXPR _redirected "${_redirected} + 1")
  endforeach ()
  if (_redirected)
    message(STATUS "ParaView hierarchy files of ${_redirected} modules: ${SCATTERER_PARAVIEW_PYTHON_ROOT}")
  endif ()
endfunction ()

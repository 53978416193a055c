# Building MeshLab 2020.09 plugins out of MeshLab's tree, against Debian's binary (meshlab package) and
# the headers of its source (apt-get source meshlab, in .deps/). cmake/MeshLab2025.cmake defines the same
# names for MeshLab 2025.07: meshlab_common, MESHLAB_TEST_PREFIX, MESHLAB_GUI, MESHLAB_BATCH and
# add_meshlab_plugin().
#
# A build-tree prefix (${MESHLAB_TEST_PREFIX}) mirrors MeshLab's install layout: bin/ holds copies of
# meshlab and meshlabserver, lib/x86_64-linux-gnu/meshlab/plugins/ holds links to the stock plugins
# and our freshly built ones. MeshLab looks for plugins relative to its binary, so running the copies
# tests our plugins without touching the system.

set(MESHLAB_SYSTEM_LIB_DIR "/usr/lib/x86_64-linux-gnu/meshlab" CACHE PATH "Debian's MeshLab library folder")
set(MESHLAB_PLUGIN_INSTALL_DIR "lib/x86_64-linux-gnu/meshlab/plugins" CACHE STRING
    "Plugin folder relative to the install prefix (Debian's MeshLab looks in /usr/<this>)")
if(CMAKE_INSTALL_PREFIX_INITIALIZED_TO_DEFAULT)
  set(CMAKE_INSTALL_PREFIX "/usr" CACHE PATH "Install prefix" FORCE)
endif()

find_package(Qt5 REQUIRED COMPONENTS Core Widgets OpenGL Xml XmlPatterns)
find_package(GLEW REQUIRED)
find_package(OpenGL REQUIRED)
set(MESHLAB_API_DIR "${PROJECT_SOURCE_DIR}/meshlab_api/ml2020")

add_library(meshlab_common SHARED IMPORTED GLOBAL)
set_target_properties(meshlab_common PROPERTIES
  IMPORTED_LOCATION "${MESHLAB_SYSTEM_LIB_DIR}/libmeshlab-common.so"
  INTERFACE_COMPILE_DEFINITIONS "MESHLAB_SCALAR=float"
  INTERFACE_INCLUDE_DIRECTORIES "${MESHLAB_SOURCE_DIR}/src;${MESHLAB_SOURCE_DIR}/vcglib")
target_link_libraries(meshlab_common INTERFACE
  Qt5::Core Qt5::Widgets Qt5::OpenGL Qt5::Xml Qt5::XmlPatterns GLEW::GLEW OpenGL::GL)

set(MESHLAB_TEST_PREFIX "${CMAKE_BINARY_DIR}/meshlab-prefix")
set(MESHLAB_TEST_PLUGIN_DIR "${MESHLAB_TEST_PREFIX}/lib/x86_64-linux-gnu/meshlab/plugins")
file(MAKE_DIRECTORY "${MESHLAB_TEST_PREFIX}/bin" "${MESHLAB_TEST_PLUGIN_DIR}")
foreach(exe meshlab meshlabserver)
  if(EXISTS "/usr/bin/${exe}")
    file(COPY "/usr/bin/${exe}" DESTINATION "${MESHLAB_TEST_PREFIX}/bin")
  endif()
endforeach()
file(CREATE_LINK "${MESHLAB_SYSTEM_LIB_DIR}/libmeshlab-common.so"
     "${MESHLAB_TEST_PREFIX}/lib/x86_64-linux-gnu/meshlab/libmeshlab-common.so" SYMBOLIC)
file(GLOB _stock_plugins "${MESHLAB_SYSTEM_LIB_DIR}/plugins/*.so")
foreach(p ${_stock_plugins})
  get_filename_component(_name "${p}" NAME)
  if(NOT _name MATCHES "^lib(filter_segment|filter_primitive_fit|edit_primitive)\\.so$")
    file(CREATE_LINK "${p}" "${MESHLAB_TEST_PLUGIN_DIR}/${_name}" SYMBOLIC)
  endif()
endforeach()
# The batch runner the script tests drive: meshlabserver, with its command line (-i -o -m -s).
set(MESHLAB_BATCH "${MESHLAB_TEST_PREFIX}/bin/meshlabserver" CACHE INTERNAL "")
set(MESHLAB_GUI "${MESHLAB_TEST_PREFIX}/bin/meshlab" CACHE INTERNAL "")

# add_meshlab_plugin(<name> <sources>...): a MeshLab plugin module, built into the test prefix.
function(add_meshlab_plugin name)
  add_library(${name} MODULE ${ARGN})
  set_target_properties(${name} PROPERTIES
    AUTOMOC ON AUTORCC ON
    LIBRARY_OUTPUT_DIRECTORY "${MESHLAB_TEST_PLUGIN_DIR}")
  target_compile_options(${name} PRIVATE ${PRIMITIVE_EDIT_WARNINGS})
  target_link_libraries(${name} PRIVATE meshlab_common primitive_edit_meshlab_api primitive_edit_common)
  install(TARGETS ${name} LIBRARY DESTINATION "${MESHLAB_PLUGIN_INSTALL_DIR}")
endfunction()

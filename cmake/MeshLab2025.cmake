# Building MeshLab 2025.07 plugins out of MeshLab's tree, against MeshLab 2025.07 built from Debian's source
# by scripts/setup-meshlab-2025.sh (cached outside the clone, linked as .deps/meshlab-2025.07). Defines the
# same names as cmake/MeshLab2020.cmake: meshlab_common, MESHLAB_TEST_PREFIX, MESHLAB_GUI, MESHLAB_BATCH
# (here our headless runner, tools/meshlab_runner, since 2025.07 has no meshlabserver) and
# add_meshlab_plugin().
#
# The test prefix holds a copy of the built meshlab binary (MeshLab looks for plugins/ beside it), links to
# its stock plugins and shaders, and our plugins.

set(MESHLAB_2025_BUILD_DIR "${MESHLAB_2025_DIR}/build" CACHE PATH "MeshLab 2025.07 build tree")
# Every MeshLab 2025.07 (AppImage, distribution package, source build) also loads the plugins in the
# user's MeshLabExtraPlugins folder (QStandardPaths' AppDataLocation of organisation VCG, application
# MeshLab_64bit_fp), subfolder 2025.07: `cmake --install` puts them there unless told otherwise.
# A system-wide MeshLab built with its default layout looks in <prefix>/lib/meshlab/plugins:
# -DMESHLAB_PLUGIN_INSTALL_DIR=that.
set(MESHLAB_PLUGIN_INSTALL_DIR "$ENV{HOME}/.local/share/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins/2025.07" CACHE PATH
    "Where cmake --install puts the plugins (absolute, or relative to CMAKE_INSTALL_PREFIX)")
foreach(_f "${MESHLAB_2025_BUILD_DIR}/src/distrib/libmeshlab-common.so" "${MESHLAB_2025_BUILD_DIR}/src/distrib/meshlab")
  if(NOT EXISTS "${_f}")
    message(FATAL_ERROR "${_f} not found: run scripts/setup-meshlab-2025.sh")
  endif()
endforeach()

find_package(Qt5 REQUIRED COMPONENTS Core Widgets OpenGL Xml Network)
find_package(GLEW REQUIRED)
find_package(OpenGL REQUIRED)
set(MESHLAB_API_DIR "${PROJECT_SOURCE_DIR}/meshlab_api/ml2025")

add_library(meshlab_common SHARED IMPORTED GLOBAL)
set_target_properties(meshlab_common PROPERTIES
  IMPORTED_LOCATION "${MESHLAB_2025_BUILD_DIR}/src/distrib/libmeshlab-common.so"
  INTERFACE_COMPILE_DEFINITIONS "MESHLAB_SCALAR=float;MESHLAB_VERSION=2025.07"
  INTERFACE_INCLUDE_DIRECTORIES "${MESHLAB_SOURCE_DIR}/src;${MESHLAB_SOURCE_DIR}/src/vcglib")
target_link_libraries(meshlab_common INTERFACE
  Qt5::Core Qt5::Widgets Qt5::OpenGL Qt5::Xml Qt5::Network GLEW::GLEW OpenGL::GL Eigen3::Eigen)

set(MESHLAB_TEST_PREFIX "${CMAKE_BINARY_DIR}/meshlab-prefix")
set(MESHLAB_TEST_PLUGIN_DIR "${MESHLAB_TEST_PREFIX}/plugins")
file(MAKE_DIRECTORY "${MESHLAB_TEST_PLUGIN_DIR}")
file(COPY "${MESHLAB_2025_BUILD_DIR}/src/distrib/meshlab" DESTINATION "${MESHLAB_TEST_PREFIX}")
file(CREATE_LINK "${MESHLAB_2025_BUILD_DIR}/src/distrib/shaders" "${MESHLAB_TEST_PREFIX}/shaders" SYMBOLIC)
file(GLOB _stock_plugins "${MESHLAB_2025_BUILD_DIR}/src/distrib/plugins/*.so")
foreach(p ${_stock_plugins})
  get_filename_component(_name "${p}" NAME)
  if(NOT _name MATCHES "^lib(filter_segment|filter_primitive_fit|filter_measure_accuracy|edit_primitive)\\.so$")
    file(CREATE_LINK "${p}" "${MESHLAB_TEST_PLUGIN_DIR}/${_name}" SYMBOLIC)
  endif()
endforeach()
set(MESHLAB_GUI "${MESHLAB_TEST_PREFIX}/meshlab" CACHE INTERNAL "")
set(MESHLAB_BATCH "${MESHLAB_TEST_PREFIX}/meshlab_runner" CACHE INTERNAL "")

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

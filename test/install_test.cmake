# Installs the package into WORK_DIR/prefix and builds one example as an outside project would:
# find_package(Mesh_repair) + target_link_libraries(... Mesh_repair::Mesh_repair).
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${WORK_DIR}/prefix
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed")
endif()
if(NOT EXISTS ${WORK_DIR}/prefix/include/CGAL/Mesh_repair/parameters.h)
  message(FATAL_ERROR "headers were not installed")
endif()
# The exported target carries only what every consumer needs (CGAL, Eigen, CGAL_EIGEN3_ENABLED):
# TBB is found by the config on the consumer's side, and CGAL's build-type warning is the
# consumer's choice.
file(GLOB_RECURSE targets_file ${WORK_DIR}/prefix/*/Mesh_repairTargets.cmake)
file(GLOB_RECURSE config_file ${WORK_DIR}/prefix/*/Mesh_repairConfig.cmake)
if(NOT targets_file OR NOT config_file)
  message(FATAL_ERROR "Mesh_repairTargets.cmake or Mesh_repairConfig.cmake was not installed")
endif()
file(READ ${targets_file} targets)
if(targets MATCHES "TBB")
  message(FATAL_ERROR "the exported target names TBB: ${targets_file}")
endif()
file(READ ${config_file} config)
if(config MATCHES "set\\(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE")
  message(FATAL_ERROR "the package config sets CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples -B ${WORK_DIR}/build
  -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring examples/ against the installed package failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build --target parameters_example
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building an example against the installed package failed")
endif()
execute_process(COMMAND ${WORK_DIR}/build/parameters_example RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the example built against the installed package did not run")
endif()
message(STATUS "installed package found, example built and run")

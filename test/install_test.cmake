# Installs the package into WORK_DIR/prefix and builds two examples as an outside project would:
# find_package(Mesh_repair) + target_link_libraries(... Mesh_repair::core), the compiled core.
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
# The compiled core is installed with the headers (this build has it): Mesh_repair::core.
if(NOT targets MATCHES "Mesh_repair::core")
  message(FATAL_ERROR "the installed package has no Mesh_repair::core: ${targets_file}")
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
# examples/ links Mesh_repair::core when the package has it: the operators come compiled.
foreach(example parameters_example fill_holes_example)
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build --target ${example}
    RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "building ${example} against the installed package failed")
  endif()
  execute_process(COMMAND ${WORK_DIR}/build/${example} WORKING_DIRECTORY ${WORK_DIR}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${example} built against the installed package did not run")
  endif()
endforeach()
if(NOT out MATCHES "closed: true")
  message(FATAL_ERROR "fill_holes_example against the installed core did not close its mesh: ${out}")
endif()
# The link line of the Makefile generator (the default here).
file(READ ${WORK_DIR}/build/CMakeFiles/fill_holes_example.dir/link.txt link_line)
if(NOT link_line MATCHES "libmesh_repair_core.a")
  message(FATAL_ERROR "fill_holes_example did not link the installed core: ${link_line}")
endif()
message(STATUS "installed package found, example built and run")

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
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples -B ${WORK_DIR}/build
  -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release
  -DMESH_REPAIR_EXAMPLES_REQUIRE_INSTALLED=ON RESULT_VARIABLE rc)
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

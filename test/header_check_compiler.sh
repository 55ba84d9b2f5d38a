#!/bin/sh
# Compiler launcher of the header check (test/CMakeLists.txt): CMake runs
# `header_check_compiler.sh CHECK_COMPILER PROJECT_COMPILER ARGS...`, and ARGS go to
# CHECK_COMPILER instead of the project's compiler.
compiler=$1
shift 2
exec "$compiler" "$@"

// The unit that compiles the suites' precompiled header (test/CMakeLists.txt).

// Empty: this program only owns the suites' precompiled headers (tests/CMakeLists.txt).

if(EXISTS "/work/main/build-green/tests/green_test_halfspace")
  if(NOT EXISTS "/work/main/build-green/tests/green_test_halfspace[1]_tests.cmake" OR
     NOT "/work/main/build-green/tests/green_test_halfspace[1]_tests.cmake" IS_NEWER_THAN "/work/main/build-green/tests/green_test_halfspace" OR
     NOT "/work/main/build-green/tests/green_test_halfspace[1]_tests.cmake" IS_NEWER_THAN "${CMAKE_CURRENT_LIST_FILE}")
    include("/usr/share/cmake-3.25/Modules/GoogleTestAddTests.cmake")
    gtest_discover_tests_impl(
      TEST_EXECUTABLE [==[/work/main/build-green/tests/green_test_halfspace]==]
      TEST_EXECUTOR [==[]==]
      TEST_WORKING_DIR [==[/work/main/build-green/tests]==]
      TEST_EXTRA_ARGS [==[]==]
      TEST_PROPERTIES [==[]==]
      TEST_PREFIX [==[]==]
      TEST_SUFFIX [==[]==]
      TEST_FILTER [==[]==]
      NO_PRETTY_TYPES [==[FALSE]==]
      NO_PRETTY_VALUES [==[FALSE]==]
      TEST_LIST [==[green_test_halfspace_TESTS]==]
      CTEST_FILE [==[/work/main/build-green/tests/green_test_halfspace[1]_tests.cmake]==]
      TEST_DISCOVERY_TIMEOUT [==[60]==]
      TEST_XML_OUTPUT_DIR [==[]==]
    )
  endif()
  include("/work/main/build-green/tests/green_test_halfspace[1]_tests.cmake")
else()
  add_test(green_test_halfspace_NOT_BUILT green_test_halfspace_NOT_BUILT)
endif()

# CMake generated Testfile for 
# Source directory: /work/main/tests
# Build directory: /work/main/build-green/tests
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
include("/work/main/build-green/tests/scene_test_load[1]_include.cmake")
include("/work/main/build-green/tests/mesh_test_build[1]_include.cmake")
include("/work/main/build-green/tests/mesh_test_locate[1]_include.cmake")
include("/work/main/build-green/tests/mesh_test_surface[1]_include.cmake")
include("/work/main/build-green/tests/mesh_test_vtu_readback[1]_include.cmake")
include("/work/main/build-green/tests/green_test_halfspace[1]_include.cmake")
include("/work/main/build-green/tests/green_test_kfit[1]_include.cmake")
include("/work/main/build-green/tests/green_test_layer_exact[1]_include.cmake")

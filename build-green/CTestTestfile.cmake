# CMake generated Testfile for 
# Source directory: /work/main
# Build directory: /work/main/build-green
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
subdirs("scene")
subdirs("mesh")
subdirs("fem")
subdirs("green")
subdirs("contact")
subdirs("validation")
subdirs("app")
subdirs("tests")

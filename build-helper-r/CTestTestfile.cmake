# CMake generated Testfile for 
# Source directory: /work/main
# Build directory: /work/main/build-helper-r
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
subdirs("common")
subdirs("protocol")
subdirs("server")
subdirs("client")
subdirs("tests")
subdirs("bench")

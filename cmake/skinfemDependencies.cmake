# The packages skinfem's libraries link, found once for the build and again by skinfemConfig.cmake for
# projects that link the installed libraries (they are static: every dependency reaches the final link).
# Four of them have no CMake config on Debian; their imported targets are made here, once per project.

# Eigen first and in CONFIG mode: CGAL and VTK ship their own FindEigen3 modules, which would shadow it.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(CGAL REQUIRED)
find_package(OpenMesh REQUIRED CONFIG)
find_package(VTK 9 REQUIRED COMPONENTS CommonCore CommonDataModel IOXML)
find_package(nlohmann_json 3 REQUIRED)
find_package(Threads REQUIRED)

# HDF5 (Debian libhdf5-dev, serial) has no CMake config; FindHDF5 would need the C language enabled.
if(NOT TARGET HDF5::HDF5)
  find_path(HDF5_INCLUDE_DIR hdf5.h PATH_SUFFIXES hdf5/serial REQUIRED)
  find_library(HDF5_LIBRARY NAMES hdf5_serial hdf5 REQUIRED)
  add_library(HDF5::HDF5 INTERFACE IMPORTED)
  target_include_directories(HDF5::HDF5 SYSTEM INTERFACE "${HDF5_INCLUDE_DIR}")
  target_link_libraries(HDF5::HDF5 INTERFACE "${HDF5_LIBRARY}")
endif()

# TetGen (Debian libtet1.5-dev) has no CMake config; libtet.so is built with TETLIBRARY.
if(NOT TARGET TetGen::TetGen)
  find_path(TETGEN_INCLUDE_DIR tetgen.h REQUIRED)
  find_library(TETGEN_LIBRARY NAMES tet REQUIRED)
  add_library(TetGen::TetGen UNKNOWN IMPORTED)
  set_target_properties(TetGen::TetGen PROPERTIES
    IMPORTED_LOCATION "${TETGEN_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${TETGEN_INCLUDE_DIR}"
    INTERFACE_COMPILE_DEFINITIONS TETLIBRARY)
endif()

# SuiteSparse 5.12 has no CMake config either; headers live in include/suitesparse.
if(NOT TARGET SuiteSparse::CHOLMOD)
  find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
  find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
  find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
  add_library(SuiteSparse::CHOLMOD INTERFACE IMPORTED)
  target_include_directories(SuiteSparse::CHOLMOD SYSTEM INTERFACE "${CHOLMOD_INCLUDE_DIR}")
  target_link_libraries(SuiteSparse::CHOLMOD INTERFACE
    "${CHOLMOD_LIBRARY}" "${SUITESPARSECONFIG_LIBRARY}")
endif()

# MUMPS 5 sequential (Debian libmumps-seq-dev): symmetric-indefinite LDLᵀ for the saddle-point system.
if(NOT TARGET MUMPS::dmumps)
  find_path(MUMPS_INCLUDE_DIR dmumps_c.h REQUIRED)
  find_path(MUMPS_SEQ_MPI_INCLUDE_DIR mpi.h PATH_SUFFIXES mumps_seq REQUIRED NO_DEFAULT_PATH PATHS /usr/include)
  find_library(DMUMPS_LIBRARY dmumps_seq REQUIRED)
  find_library(MUMPS_COMMON_LIBRARY mumps_common_seq REQUIRED)
  find_library(MUMPS_MPISEQ_LIBRARY mpiseq_seq REQUIRED)
  find_library(MUMPS_PORD_LIBRARY pord_seq REQUIRED)
  add_library(MUMPS::dmumps INTERFACE IMPORTED)
  target_include_directories(MUMPS::dmumps SYSTEM INTERFACE "${MUMPS_INCLUDE_DIR}" "${MUMPS_SEQ_MPI_INCLUDE_DIR}")
  target_link_libraries(MUMPS::dmumps INTERFACE
    "${DMUMPS_LIBRARY}" "${MUMPS_COMMON_LIBRARY}" "${MUMPS_MPISEQ_LIBRARY}" "${MUMPS_PORD_LIBRARY}")
endif()


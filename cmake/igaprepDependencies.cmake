# Finds igaprep's third-party dependencies (all Debian 12 packages) and makes
# imported targets for those that ship no usable CMake package.
# Used by the build (everything) and by the installed igaprepConfig.cmake,
# which sets IGAPREP_NEEDED_DEPENDENCIES to what the asked components need
# (eigen, cgal, tetgen, hdf5, ceres, cholmod, hypre, json, openssl).
include(CMakeFindDependencyMacro)
if(NOT DEFINED IGAPREP_NEEDED_DEPENDENCIES)
  set(IGAPREP_NEEDED_DEPENDENCIES eigen cgal tetgen hdf5 ceres cholmod hypre json openssl)
endif()
macro(igaprep_needs dependency result)
  list(FIND IGAPREP_NEEDED_DEPENDENCIES ${dependency} _igaprep_at)
  if(_igaprep_at EQUAL -1)
    set(${result} OFF)
  else()
    set(${result} ON)
  endif()
endmacro()

find_dependency(Eigen3 3.3 NO_MODULE)
# OpenMP (core's parallel_for): CMake's own FindOpenMP, no package to install.
find_package(OpenMP COMPONENTS CXX QUIET)
igaprep_needs(cgal _igaprep_need)
if(_igaprep_need)
  find_dependency(CGAL)
endif()
igaprep_needs(json _igaprep_need)
if(_igaprep_need)
  find_dependency(nlohmann_json 3)
endif()
igaprep_needs(openssl _igaprep_need)
if(_igaprep_need)
  find_dependency(OpenSSL)
endif()
# Ceres Solver (libceres-dev): the L-BFGS of spline/'s joint Jacobian repair.
# BLAS through libblas.so.3, which Debian's alternatives point at the best
# BLAS installed (OpenBLAS), never ATLAS's libf77blas: linked first it took
# CHOLMOD's dgemm_ to ATLAS's untuned build (the validation study's
# factorization 3 times slower). FindBLAS (run by Ceres for SuiteSparse)
# picks ATLAS by default, and Debian's Ceres names it in its link interface
# though Ceres calls LAPACK only.
igaprep_needs(ceres _igaprep_need)
if(_igaprep_need AND NOT DEFINED BLA_VENDOR)
  set(BLA_VENDOR Generic)
endif()
if(_igaprep_need)
  find_dependency(Ceres)
endif()
if(TARGET Ceres::ceres)
  get_target_property(_igaprep_ceres_links Ceres::ceres INTERFACE_LINK_LIBRARIES)
  list(FILTER _igaprep_ceres_links EXCLUDE REGEX "lib(f77blas|atlas)\\.so$")
  set_target_properties(Ceres::ceres PROPERTIES INTERFACE_LINK_LIBRARIES "${_igaprep_ceres_links}")
  unset(_igaprep_ceres_links)
endif()
# FindHDF5 test-compiles a C program: a C++-only consumer needs C enabled.
igaprep_needs(hdf5 _igaprep_need)
if(_igaprep_need)
  if(NOT CMAKE_C_COMPILER_LOADED)
    enable_language(C)
  endif()
  find_dependency(HDF5 COMPONENTS C)
endif()

# TetGen (libtet1.5-dev): header tetgen.h, library libtet.so, needs TETLIBRARY.
igaprep_needs(tetgen _igaprep_need)
if(_igaprep_need AND NOT TARGET igaprep_dep_tetgen)
  find_path(IGAPREP_TETGEN_INCLUDE_DIR tetgen.h REQUIRED)
  find_library(IGAPREP_TETGEN_LIBRARY NAMES tet REQUIRED)
  add_library(igaprep_dep_tetgen INTERFACE IMPORTED)
  set_target_properties(igaprep_dep_tetgen PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${IGAPREP_TETGEN_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${IGAPREP_TETGEN_LIBRARY}"
    INTERFACE_COMPILE_DEFINITIONS TETLIBRARY)
endif()

# HDF5 (serial), its C API only: export/ calls H5F/H5G/H5D/H5A directly
# (export/src/hdf5_handle.h), not the C++ wrapper.
igaprep_needs(hdf5 _igaprep_need)
if(_igaprep_need AND NOT TARGET igaprep_dep_hdf5)
  add_library(igaprep_dep_hdf5 INTERFACE IMPORTED)
  set_target_properties(igaprep_dep_hdf5 PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${HDF5_INCLUDE_DIRS}"
    INTERFACE_LINK_LIBRARIES "${HDF5_C_LIBRARIES}")
endif()

# CHOLMOD (libsuitesparse-dev) is optional: Eigen's simplicial LDLT otherwise.
igaprep_needs(cholmod _igaprep_need)
if(_igaprep_need AND NOT TARGET igaprep_dep_cholmod)
  find_path(IGAPREP_CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
  find_library(IGAPREP_CHOLMOD_LIBRARY NAMES cholmod)
  find_library(IGAPREP_SUITESPARSECONFIG_LIBRARY NAMES suitesparseconfig)
  add_library(igaprep_dep_cholmod INTERFACE IMPORTED)
  if(IGAPREP_CHOLMOD_INCLUDE_DIR AND IGAPREP_CHOLMOD_LIBRARY)
    set(IGAPREP_HAVE_CHOLMOD ON)
    set_target_properties(igaprep_dep_cholmod PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${IGAPREP_CHOLMOD_INCLUDE_DIR}"
      INTERFACE_LINK_LIBRARIES "${IGAPREP_CHOLMOD_LIBRARY};${IGAPREP_SUITESPARSECONFIG_LIBRARY}"
      INTERFACE_COMPILE_DEFINITIONS IGAPREP_HAVE_CHOLMOD)
  else()
    set(IGAPREP_HAVE_CHOLMOD OFF)
  endif()
endif()

# hypre (libhypre-dev): BoomerAMG for the elasticity solver's large
# problems. Debian builds it on Open MPI; igaprep runs it in one process
# (MPI_COMM_SELF) and never needs the MPI C++ bindings.
igaprep_needs(hypre _igaprep_need)
if(_igaprep_need AND NOT TARGET igaprep_dep_hypre)
  if(NOT CMAKE_C_COMPILER_LOADED)
    enable_language(C)
  endif()
  find_dependency(MPI COMPONENTS C)
  find_path(IGAPREP_HYPRE_INCLUDE_DIR HYPRE.h PATH_SUFFIXES hypre REQUIRED)
  find_library(IGAPREP_HYPRE_LIBRARY NAMES HYPRE REQUIRED)
  add_library(igaprep_dep_hypre INTERFACE IMPORTED)
  set_target_properties(igaprep_dep_hypre PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${IGAPREP_HYPRE_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${IGAPREP_HYPRE_LIBRARY};MPI::MPI_C"
    INTERFACE_COMPILE_DEFINITIONS OMPI_SKIP_MPICXX)
endif()

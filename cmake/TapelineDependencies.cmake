# Dependencies of the header-only modules, shared by the build tree and the installed package
# config. Everything comes from Debian 12 packages; nothing is downloaded.
include(CMakeFindDependencyMacro)
find_dependency(Threads)
find_dependency(nlohmann_json 3.10)
find_dependency(SQLite3)
find_dependency(zstd)
find_dependency(PNG)
find_dependency(CGAL 5.5)
find_dependency(TBB)
include(CGAL_TBB_support)
if(NOT TARGET CGAL::TBB_support)
  message(FATAL_ERROR "tapeline: oneTBB not found (Debian package libtbb-dev)")
endif()
find_dependency(Eigen3 3.3 NO_MODULE)
# Optional: only tapeline::geodesic_ceres needs it (Debian package libceres-dev).
find_package(Ceres 2.1 QUIET)
# Optional: only tapeline::grading needs it (Debian package libpagmo-dev; NSGA-II).
find_package(Pagmo QUIET NAMES pagmo)
# Optional: only tapeline::garment_gltf needs it (Debian package libtinygltf-dev).
find_package(TinyGLTF CONFIG QUIET)
include(CGAL_Eigen3_support)
if(NOT TARGET CGAL::Eigen3_support)
  message(FATAL_ERROR "tapeline: Eigen 3 not found (Debian package libeigen3-dev)")
endif()

# CHOLMOD (Debian package libsuitesparse-dev): the supernodal sparse Cholesky factorisation of the
# garment solver's static solve (DrapeSolver::relax). It ships no CMake config; wrap it in a target.
if(NOT TARGET tapeline::CHOLMOD)
  find_path(TAPELINE_CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
  find_library(TAPELINE_CHOLMOD_LIBRARY cholmod)
  if(TAPELINE_CHOLMOD_INCLUDE_DIR AND TAPELINE_CHOLMOD_LIBRARY)
    add_library(tapeline::CHOLMOD UNKNOWN IMPORTED)
    set_target_properties(tapeline::CHOLMOD PROPERTIES
      IMPORTED_LOCATION "${TAPELINE_CHOLMOD_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${TAPELINE_CHOLMOD_INCLUDE_DIR}")
  else()
    message(FATAL_ERROR "tapeline: CHOLMOD not found (Debian package libsuitesparse-dev)")
  endif()
endif()

# Optional: only tapeline::surfaces needs it (Debian package libgeographiclib-dev), which ships a
# find module but no config file; wrap it in a target.
if(NOT TARGET tapeline::GeographicLib)
  find_path(TAPELINE_GEOGRAPHICLIB_INCLUDE_DIR GeographicLib/GeodesicExact.hpp)
  find_library(TAPELINE_GEOGRAPHICLIB_LIBRARY GeographicLib)
  if(TAPELINE_GEOGRAPHICLIB_INCLUDE_DIR AND TAPELINE_GEOGRAPHICLIB_LIBRARY)
    add_library(tapeline::GeographicLib UNKNOWN IMPORTED)
    set_target_properties(tapeline::GeographicLib PROPERTIES
      IMPORTED_LOCATION "${TAPELINE_GEOGRAPHICLIB_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${TAPELINE_GEOGRAPHICLIB_INCLUDE_DIR}")
  endif()
endif()

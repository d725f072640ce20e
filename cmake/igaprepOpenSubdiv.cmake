# OpenSubdiv 3.5 (libosd-dev): the limit surfaces of spline/'s T-NURCCs.
# Used inside spline/src only: spline links this target in the build and,
# installed, the shared library alone (spline/CMakeLists.txt), so the
# installed package config does not look for OpenSubdiv.
# Debian's OpenSubdivConfig.cmake names static libraries that are not
# installed, so the shared CPU library is found by hand.
if(NOT TARGET igaprep_dep_osd)
  find_path(IGAPREP_OSD_INCLUDE_DIR opensubdiv/far/topologyRefiner.h REQUIRED)
  find_library(IGAPREP_OSD_LIBRARY NAMES osdCPU REQUIRED)
  add_library(igaprep_dep_osd INTERFACE IMPORTED)
  set_target_properties(igaprep_dep_osd PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${IGAPREP_OSD_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${IGAPREP_OSD_LIBRARY}")
endif()

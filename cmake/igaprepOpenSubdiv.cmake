# OpenSubdiv 3.5 (libosd-dev), a required dependency of the project for the
# T-spline / T-NURCC work in spline/ (ARCHITECTURE.md). No module uses it
# yet, so nothing links igaprep_dep_osd and the installed package config
# does not look for it; the first module that uses it links it and moves
# this block into igaprepDependencies.cmake (a static library's link
# dependencies reach its consumers).
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

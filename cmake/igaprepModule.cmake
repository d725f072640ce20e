# igaprep_add_module(NAME DEPS...): a library target igaprep_NAME (alias
# igaprep::NAME) from NAME/src/*.cpp with public headers NAME/include/igaprep/NAME.
# A module without sources yet is an INTERFACE library with the same name.
function(igaprep_add_module name)
  file(GLOB _src CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
  set(_tgt igaprep_${name})
  if(_src)
    add_library(${_tgt} STATIC ${_src})
    set(_scope PUBLIC)
    target_compile_options(${_tgt} PRIVATE -Wall -Wextra)
  else()
    add_library(${_tgt} INTERFACE)
    set(_scope INTERFACE)
  endif()
  add_library(igaprep::${name} ALIAS ${_tgt})
  set_target_properties(${_tgt} PROPERTIES EXPORT_NAME ${name})
  target_include_directories(${_tgt} ${_scope}
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${_tgt} ${_scope} cxx_std_17)
  if(ARGN)
    target_link_libraries(${_tgt} ${_scope} ${ARGN})
  endif()
  install(TARGETS ${_tgt} EXPORT igaprepTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()

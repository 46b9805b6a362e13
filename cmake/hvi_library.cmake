# hvi_add_library(<name> SOURCES <files...> [PUBLIC <deps...>] [PRIVATE <deps...>])
#
# One place for what every library of the project needs: the target hvi_<name> and its alias
# hvi::<name> (the name other projects link after find_package(hvi)), public headers in the
# folder's include/ (src/ is a private include path), the project's warnings (build only), and
# the install export set (README.md, "Using the libraries from another project").
function(hvi_add_library name)
  cmake_parse_arguments(PARSE_ARGV 1 L "" "" "SOURCES;PUBLIC;PRIVATE")
  if(L_UNPARSED_ARGUMENTS OR NOT L_SOURCES)
    message(FATAL_ERROR "hvi_add_library(${name}): give SOURCES, PUBLIC and PRIVATE lists only")
  endif()
  set(target hvi_${name})
  add_library(${target} ${L_SOURCES})
  add_library(hvi::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  target_include_directories(${target}
    PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  if(IS_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/src)
    target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  endif()
  target_link_libraries(${target} PUBLIC ${L_PUBLIC}
                                  PRIVATE ${L_PRIVATE} $<BUILD_INTERFACE:hvi_warnings>)
  install(TARGETS ${target} EXPORT hviTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  # Two libraries may share a folder (verify, verify_solver): install its headers once.
  get_property(done DIRECTORY PROPERTY HVI_HEADERS_INSTALLED)
  if(NOT done AND IS_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include)
    install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
    set_property(DIRECTORY PROPERTY HVI_HEADERS_INSTALLED TRUE)
  endif()
endfunction()

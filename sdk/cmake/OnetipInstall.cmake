# Installs the public library, headers, the CMake package (find_package(onetip)
# gives onetip::onetip), a relocatable pkg-config file, the user reference and
# the shipped scenarios (share/onetip). The Python module and Onetip.dll are
# installed by bindings/python and bindings/csharp.
include(CMakePackageConfigHelpers)

install(TARGETS onetip EXPORT onetipTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/sdk/include/onetip ${PROJECT_BINARY_DIR}/sdk/include/onetip
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h" PATTERN "*.hpp")
install(EXPORT onetipTargets NAMESPACE onetip:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/onetip)

write_basic_package_version_file(${PROJECT_BINARY_DIR}/onetipConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
file(WRITE ${PROJECT_BINARY_DIR}/onetipConfig.cmake
  "include(\${CMAKE_CURRENT_LIST_DIR}/onetipTargets.cmake)\n")
install(FILES ${PROJECT_BINARY_DIR}/onetipConfig.cmake ${PROJECT_BINARY_DIR}/onetipConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/onetip)

# onetip.pc names its prefix relative to its own folder (${pcfiledir}), so the
# installed tree can be moved or installed anywhere with --prefix.
file(RELATIVE_PATH ONETIP_PC_PREFIX_FROM_PCDIR /p/${CMAKE_INSTALL_LIBDIR}/pkgconfig /p)
string(REGEX REPLACE "/$" "" ONETIP_PC_PREFIX_FROM_PCDIR "${ONETIP_PC_PREFIX_FROM_PCDIR}")
configure_file(${PROJECT_SOURCE_DIR}/sdk/cmake/onetip.pc.in ${PROJECT_BINARY_DIR}/onetip.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/onetip.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

install(FILES ${PROJECT_SOURCE_DIR}/docs/reference.md DESTINATION ${CMAKE_INSTALL_DATADIR}/onetip/docs)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/samples/scenarios DESTINATION ${CMAKE_INSTALL_DATADIR}/onetip
  FILES_MATCHING PATTERN "*.yaml")

# cmake --install: library, header, tool, CMake package (lifthull::lifthull) and pkg-config file.
include(CMakePackageConfigHelpers)
set(LH_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/lifthull)

install(TARGETS lifthull lifthull_shared EXPORT lifthullTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  PUBLIC_HEADER DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS lifthull_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT lifthullTargets NAMESPACE lifthull:: DESTINATION ${LH_CMAKE_DIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/lifthullConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/lifthullConfig.cmake INSTALL_DESTINATION ${LH_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/lifthullConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/lifthullConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/lifthullConfigVersion.cmake DESTINATION ${LH_CMAKE_DIR})

# Relocatable: the prefix is found from the .pc file's own place (lib/pkgconfig/..).
file(RELATIVE_PATH LH_PC_UP "/root/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/root")
configure_file(${CMAKE_CURRENT_LIST_DIR}/lifthull.pc.in ${CMAKE_CURRENT_BINARY_DIR}/lifthull.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/lifthull.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# The manual page of the tool.
install(FILES ${CMAKE_CURRENT_LIST_DIR}/../docs/lifthull.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)

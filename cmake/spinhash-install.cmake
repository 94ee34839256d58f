# Install rules and the CMake/pkg-config package (docs/firmware.md).
# Installed: the core (spinhash::core, static, no host dependencies), the
# public headers without internal/, the spinhash command where built, docs.
# The host library (spinhash_host) is not exported: its headers are the
# host-tools tree and the unversioned internal interface, and it drags in
# Assimp, Embree and CLI11; host users run the spinhash command instead.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SPINHASH_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/spinhash)
set(SPINHASH_PKGCONFIG_DIR ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

set_target_properties(spinhash_core PROPERTIES EXPORT_NAME core)
install(TARGETS spinhash_core EXPORT spinhashTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/spinhash DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        PATTERN internal EXCLUDE)
if(TARGET spinhash)
  install(TARGETS spinhash RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
file(GLOB SPINHASH_DOC_FILES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/*.md)
install(FILES ${SPINHASH_DOC_FILES} DESTINATION ${CMAKE_INSTALL_DOCDIR})

install(EXPORT spinhashTargets NAMESPACE spinhash:: DESTINATION ${SPINHASH_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/spinhashConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/spinhashConfig.cmake
                              INSTALL_DESTINATION ${SPINHASH_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/spinhashConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/spinhashConfig.cmake ${PROJECT_BINARY_DIR}/spinhashConfigVersion.cmake
        DESTINATION ${SPINHASH_CMAKE_DIR})

# pkg-config: prefix relative to the .pc file, so the tree stays relocatable
# (cmake --install --prefix elsewhere). The core is C++ without exceptions or
# RTTI and needs no C++ runtime: a C program links it with libm (examples/c).
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}" OR IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
  set(SPINHASH_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH SPINHASH_PC_UP /${SPINHASH_PKGCONFIG_DIR} /)
  string(REGEX REPLACE "/$" "" SPINHASH_PC_UP "${SPINHASH_PC_UP}")
  set(SPINHASH_PC_PREFIX "\${pcfiledir}/${SPINHASH_PC_UP}")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/spinhash.pc.in ${PROJECT_BINARY_DIR}/spinhash.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/spinhash.pc DESTINATION ${SPINHASH_PKGCONFIG_DIR})

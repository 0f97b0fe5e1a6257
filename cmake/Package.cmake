# The installed library (docs/guide/library.md): libtsis.so, made of the
# static modules with only the public API (include/tsis/) exported, the public
# headers and a CMake package, so that another project does
#   find_package(tsis REQUIRED)
#   target_link_libraries(app PRIVATE tsis::tsis)
# Kernels and shaders are embedded (cmake/Embed.cmake): the install needs no
# file of the source tree.
include(CMakePackageConfigHelpers)
include(GNUInstallDirs)

add_library(tsis_lib SHARED ${CMAKE_SOURCE_DIR}/cmake/empty.cpp)
target_link_libraries(tsis_lib PRIVATE "$<LINK_LIBRARY:WHOLE_ARCHIVE,tsis_api>")
target_link_options(tsis_lib PRIVATE "LINKER:--version-script=${CMAKE_SOURCE_DIR}/cmake/tsis.map"
                    "LINKER:--no-undefined")
set_target_properties(tsis_lib PROPERTIES OUTPUT_NAME tsis EXPORT_NAME tsis
                      VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}
                      LINK_DEPENDS ${CMAKE_SOURCE_DIR}/cmake/tsis.map)
target_include_directories(tsis_lib INTERFACE
                           $<BUILD_INTERFACE:${CMAKE_SOURCE_DIR}/include>
                           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
target_compile_features(tsis_lib INTERFACE cxx_std_20)

install(TARGETS tsis_lib EXPORT tsisTargets LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS tsis RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/include/tsis DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT tsisTargets NAMESPACE tsis:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/tsis)
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/tsisConfig.cmake
     "include(\${CMAKE_CURRENT_LIST_DIR}/tsisTargets.cmake)\n")
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/tsisConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/tsisConfig.cmake
        ${CMAKE_CURRENT_BINARY_DIR}/tsisConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/tsis)

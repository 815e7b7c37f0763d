# `cmake --install build [--prefix DIR]`: the grotto command, the libraries, the
# public headers alone (include/grotto/: grotto.h and the few beside it) and a
# CMake package, so another project embeds the renderer with find_package(Grotto)
# and links Grotto::engine (examples/). The libraries behind the API are linked
# for it, their headers not installed; the shaders are built into the libraries.
include(CMakePackageConfigHelpers)

set_target_properties(grotto_common PROPERTIES EXPORT_NAME common)
set_target_properties(grotto_voxel PROPERTIES EXPORT_NAME voxel)
set_target_properties(grotto_vdb_read PROPERTIES EXPORT_NAME vdb_read)
set_target_properties(grotto_vk PROPERTIES EXPORT_NAME vk)
set_target_properties(grotto_engine PROPERTIES EXPORT_NAME frame)
set_target_properties(grotto_api PROPERTIES EXPORT_NAME engine)
set_target_properties(grotto_shaders PROPERTIES EXPORT_NAME shaders)
set_target_properties(grotto_image_io PROPERTIES EXPORT_NAME image_io)
set_target_properties(grotto_vdb_deps PROPERTIES EXPORT_NAME vdb_deps)

# The installed grotto finds the image codec module (installed beside the
# libraries, engine/image_codec/) relative to itself, wherever the tree is moved.
set_target_properties(grotto PROPERTIES INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}/grotto")
install(TARGETS grotto RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS grotto_api grotto_common grotto_vdb_read grotto_voxel grotto_vk grotto_engine grotto_shaders grotto_image_io grotto_vdb_deps
        EXPORT GrottoTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY include/grotto DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")

set(package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/Grotto)
install(EXPORT GrottoTargets NAMESPACE Grotto:: DESTINATION ${package_dir})
configure_package_config_file(cmake/GrottoConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/GrottoConfig.cmake
                              INSTALL_DESTINATION ${package_dir})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/GrottoConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/GrottoConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/GrottoConfigVersion.cmake
        DESTINATION ${package_dir})

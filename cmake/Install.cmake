# `cmake --install build --prefix P` (GNUInstallDirs): P/bin/pond; the example scenes in
# P/share/pond/scenes; the README and docs/ in P/share/doc/pond (so the README's links into docs/
# resolve there); the discrete-GPU test layer and its manifest in P/share/pond/layers, a directory
# the Vulkan loader never searches, so the layer is on only where VK_LAYER_PATH names it. The
# installed pond reads nothing from the source or build tree: shaders and the default scene are
# embedded, and the manifest names its library relative to itself.
include(GNUInstallDirs)
# cpack, like cmake --install, packs what is built and builds nothing: without this its preinstall
# step builds every target (tests, benchmarks, the IA-32 pond), in CI while other tests run.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)
install(TARGETS pond RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/pond/scenes
        FILES_MATCHING PATTERN "*.json")
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
if(POND_WITH_VULKAN)
  install(TARGETS VkLayer_POND_discrete_gpu LIBRARY DESTINATION ${CMAKE_INSTALL_DATADIR}/pond/layers)
  install(FILES $<TARGET_FILE_DIR:VkLayer_POND_discrete_gpu>/VkLayer_POND_discrete_gpu.json  # beside the library
          DESTINATION ${CMAKE_INSTALL_DATADIR}/pond/layers)
endif()

# Third-party packages, all from Debian (scripts/setup.sh installs them).
find_package(Threads REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED CONFIG)
if(POND_BUILD_TESTS AND NOT TARGET GTest::gtest)  # IA-32 and cross builds compile their own (GTestFromSource.cmake)
  find_package(GTest REQUIRED)
endif()
if(POND_BUILD_BENCH AND NOT POND_IA32 AND NOT CMAKE_CROSSCOMPILING)
  find_package(benchmark REQUIRED)
endif()
if(POND_WITH_VULKAN)
  find_package(Vulkan REQUIRED)
  find_package(glfw3 3.3 REQUIRED)
  find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)
  find_program(SPIRV_VAL spirv-val REQUIRED)
endif()
find_path(STB_INCLUDE_DIR stb/stb_image_write.h REQUIRED)  # core/png.cpp
find_path(GLM_INCLUDE_DIR glm/glm.hpp REQUIRED)            # view/view_projection.cpp

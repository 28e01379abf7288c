# Every third-party package, found once (Debian 12 names; pitfalls noted where they bite).
find_package(Threads REQUIRED)
find_package(glm REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(Vulkan REQUIRED COMPONENTS glslangValidator)
find_package(glfw3 3.3 REQUIRED)
if(MATEVO_BUILD_TESTS)
    find_package(GTest REQUIRED)
endif()
find_package(TinyGLTF REQUIRED)
find_package(PNG REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)

# OpenImageIO through pkg-config: Debian 12's CMake config names files that its -dev package
# does not install (/usr/include/opencv4, the tools, PyImath) and fails at generate time.
pkg_check_modules(OIIO REQUIRED IMPORTED_TARGET OpenImageIO)

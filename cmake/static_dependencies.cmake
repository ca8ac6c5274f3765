# The dependencies of a fully static build (CEREBELLUM_STATIC: the robot's build, whose glibc is
# older than the build machine's; docs/robot-build.md). Debian's CMake packages of yaml-cpp and
# toml++ name shared libraries, so their targets are made here: yaml-cpp from its archive
# (libyaml-cpp-dev ships libyaml-cpp.a), toml++ header-only (the same headers, no library). LCM's
# own dependencies (glib) are named in lcm/CMakeLists.txt.
find_library(CEREBELLUM_YAML_CPP_ARCHIVE libyaml-cpp.a REQUIRED)
find_path(CEREBELLUM_YAML_CPP_INCLUDE_DIR yaml-cpp/yaml.h REQUIRED)
add_library(yaml-cpp STATIC IMPORTED)
set_target_properties(yaml-cpp PROPERTIES
  IMPORTED_LOCATION "${CEREBELLUM_YAML_CPP_ARCHIVE}"
  INTERFACE_INCLUDE_DIRECTORIES "${CEREBELLUM_YAML_CPP_INCLUDE_DIR}")

find_path(CEREBELLUM_TOMLPLUSPLUS_INCLUDE_DIR toml++/toml.h REQUIRED)
add_library(tomlplusplus::tomlplusplus INTERFACE IMPORTED)
set_target_properties(tomlplusplus::tomlplusplus PROPERTIES
  INTERFACE_INCLUDE_DIRECTORIES "${CEREBELLUM_TOMLPLUSPLUS_INCLUDE_DIR}"
  INTERFACE_COMPILE_DEFINITIONS "TOML_HEADER_ONLY=1")

# every program: no shared library at all, the C library included
add_link_options(-static)

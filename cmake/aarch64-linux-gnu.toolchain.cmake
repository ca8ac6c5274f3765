# Cross-compiling for the robot's board (the CyberDog2's NX: aarch64) with Debian's cross toolchain
# (crossbuild-essential-arm64). The arm64 libraries come from a folder of unpacked Debian arm64
# -dev packages and static builds of Debian sources (CEREBELLUM_AARCH64_SYSROOT, filled by
# scripts/build_robot.sh): installing arm64 -dev packages system-wide would remove the build
# machine's own where they are not Multi-Arch: same (libyaml-cpp-dev). docs/robot-build.md.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
# the arithmetic of the x86 build, which the tests' exact values and every benchmark judged: no
# a * b + c fused into one rounding (aarch64 has FMA in its base instruction set, and GCC contracts
# by default in C++; x86-64's baseline has none)
set(CMAKE_C_FLAGS_INIT "-ffp-contract=off")
set(CMAKE_CXX_FLAGS_INIT "-ffp-contract=off")
set(CEREBELLUM_AARCH64_SYSROOT "" CACHE PATH "unpacked arm64 -dev packages, a /usr inside (scripts/build_robot.sh)")
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES CEREBELLUM_AARCH64_SYSROOT)
# find_library and find_package look in <sysroot>/usr/lib/aarch64-linux-gnu and never in the build
# machine's /usr/lib/x86_64-linux-gnu; header-only packages (Eigen, toml++) and the programs found
# (lcm-gen, python3) are the build machine's
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)
list(APPEND CMAKE_PREFIX_PATH "${CEREBELLUM_AARCH64_SYSROOT}/usr")
set(CMAKE_IGNORE_PATH /usr/lib/x86_64-linux-gnu /usr/lib/x86_64-linux-gnu/cmake)
# pkg-config answers with the sysroot's .pc files, their /usr paths moved into it
set(ENV{PKG_CONFIG_LIBDIR} "${CEREBELLUM_AARCH64_SYSROOT}/usr/lib/aarch64-linux-gnu/pkgconfig:${CEREBELLUM_AARCH64_SYSROOT}/usr/lib/pkgconfig:${CEREBELLUM_AARCH64_SYSROOT}/usr/share/pkgconfig")
set(ENV{PKG_CONFIG_SYSROOT_DIR} "${CEREBELLUM_AARCH64_SYSROOT}")
# ctest runs the aarch64 test programs through qemu's user-mode emulator (qemu-user-static): no
# binfmt registration needed
find_program(CEREBELLUM_QEMU_AARCH64 qemu-aarch64-static)
if(CEREBELLUM_QEMU_AARCH64)
  set(CMAKE_CROSSCOMPILING_EMULATOR "${CEREBELLUM_QEMU_AARCH64}")
endif()

# Toolchain for the WebAssembly build (samples/web, scripts/run-web.sh): Debian's clang-14 with its
# wasm32 target, wasi-libc as the C library and lld's wasm-ld as the linker
# (scripts/install-deps.sh web installs them: clang, wasi-libc, lld-14, libclang-rt-14-dev-wasm32).
#
# Debian puts wasi-libc's headers and libraries in /usr/include/wasm32-wasi and
# /usr/lib/wasm32-wasi. clang given --sysroot=/usr would look there but also in /usr/include, the
# host's headers, where a header wasi-libc lacks (pthread.h) would be found and fail deep inside;
# a sysroot of two links in the build tree holds wasi-libc alone.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR wasm32)

find_program(TUMBLE_WASM_CLANG NAMES clang-14 clang REQUIRED)
set(CMAKE_C_COMPILER ${TUMBLE_WASM_CLANG})
set(CMAKE_CXX_COMPILER ${TUMBLE_WASM_CLANG})
set(CMAKE_C_COMPILER_TARGET wasm32-wasi)
set(CMAKE_CXX_COMPILER_TARGET wasm32-wasi)

set(TUMBLE_WASI_SYSROOT ${CMAKE_BINARY_DIR}/wasi-sysroot)
if(NOT EXISTS /usr/include/wasm32-wasi/stdlib.h)
	message(FATAL_ERROR "wasi-libc is missing: scripts/install-deps.sh web (apt-get install wasi-libc lld-14 libclang-rt-14-dev-wasm32)")
endif()
file(MAKE_DIRECTORY ${TUMBLE_WASI_SYSROOT}/include ${TUMBLE_WASI_SYSROOT}/lib)
file(CREATE_LINK /usr/include/wasm32-wasi ${TUMBLE_WASI_SYSROOT}/include/wasm32-wasi SYMBOLIC)
file(CREATE_LINK /usr/lib/wasm32-wasi ${TUMBLE_WASI_SYSROOT}/lib/wasm32-wasi SYMBOLIC)
set(CMAKE_SYSROOT ${TUMBLE_WASI_SYSROOT})

# Try-compiles link nothing: a WASI program without main is a reactor, set on the module itself.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)

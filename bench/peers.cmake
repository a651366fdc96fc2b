# tumble-bench: the scene benchmark (bench/tumble_bench.c) with peer adapters for Box2D 2.4.1,
# Box2D v3 and Chipmunk 7, each compiled only when its engine is found. Included by
# bench/CMakeLists.txt. Peer headers are SYSTEM includes: their warnings are not ours.
if(NOT TARGET tumble_scenes)
	message(STATUS "tumble-bench: the scene catalogue (tumble_scenes) is missing, not built")
	return()
endif()

add_executable(tumble-bench ${CMAKE_CURRENT_SOURCE_DIR}/tumble_bench.c ${CMAKE_CURRENT_SOURCE_DIR}/peers.h)
target_include_directories(tumble-bench PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(tumble-bench PRIVATE tumble_scenes tumble m)

# Box2D v3: an installed package (find_package(box2d 3 CONFIG); point TUMBLE_BOX2D3_DIR or
# CMAKE_PREFIX_PATH at its install prefix) or its source tree (TUMBLE_BOX2D3_SOURCE_DIR, built
# here without its samples, tests and benchmark). Box2D 2.4 and v3 both install box2d/box2d.h, so
# the v3 adapter is a library of its own: only peer_box2d3.c sees v3's include directory, and
# tumble-bench links v3's library without its include path. The two libraries' symbols do not
# clash: 2.4 is C++ (mangled names, b2_version and a few counters unmangled), v3 is C (b2* functions).
set(TUMBLE_BOX2D3_DIR "" CACHE PATH "Install prefix of Box2D v3 for the tumble-bench peer (optional)")
set(TUMBLE_BOX2D3_SOURCE_DIR "" CACHE PATH "Source tree of Box2D v3 to build for the tumble-bench peer (optional)")
set(TUMBLE_BOX2D3_TARGET "")
if(TUMBLE_BOX2D3_SOURCE_DIR)
	if(NOT EXISTS ${TUMBLE_BOX2D3_SOURCE_DIR}/src/body.c)
		message(FATAL_ERROR "TUMBLE_BOX2D3_SOURCE_DIR=${TUMBLE_BOX2D3_SOURCE_DIR} is not a Box2D v3 source tree")
	endif()
	# Added below the top level, v3's CMakeLists leaves out its samples, tests, benchmark and docs.
	add_subdirectory(${TUMBLE_BOX2D3_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/box2d3 EXCLUDE_FROM_ALL)
	target_compile_options(box2d PRIVATE -w) # Tumble's warning flags (and -Werror) are not for v3's code
	set_property(TARGET box2d PROPERTY SYSTEM TRUE) # its headers as system headers (CMake >= 3.25)
	set(TUMBLE_BOX2D3_TARGET box2d)
	message(STATUS "tumble-bench: Box2D v3 peer built from ${TUMBLE_BOX2D3_SOURCE_DIR}")
else()
	find_package(box2d 3 CONFIG QUIET HINTS ${TUMBLE_BOX2D3_DIR})
	if(box2d_FOUND AND TARGET box2d::box2d)
		set(TUMBLE_BOX2D3_TARGET box2d::box2d)
		message(STATUS "tumble-bench: Box2D v3 peer ${box2d_VERSION} from ${box2d_DIR}")
	endif()
endif()
if(TUMBLE_BOX2D3_TARGET)
	add_library(tumble_peer_box2d3 STATIC ${CMAKE_CURRENT_SOURCE_DIR}/peer_box2d3.c)
	target_include_directories(tumble_peer_box2d3 PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
	target_link_libraries(tumble_peer_box2d3 PRIVATE ${TUMBLE_BOX2D3_TARGET} tumble_scenes tumble)
	target_link_libraries(tumble-bench PRIVATE tumble_peer_box2d3)
	target_compile_definitions(tumble-bench PRIVATE TUMBLE_HAVE_BOX2D3)
	# The broad-phase micro-benchmark times v3's own tree on the same moves (a fifth method).
	if(TARGET tumble-bench-broadphase)
		target_link_libraries(tumble-bench-broadphase PRIVATE tumble_peer_box2d3)
		target_compile_definitions(tumble-bench-broadphase PRIVATE TUMBLE_HAVE_BOX2D3)
	endif()
endif()

# Box2D 2.4: found by a header v3 does not have (box2d/b2_world.h), its library next to it, so a
# v3 install on CMAKE_PREFIX_PATH is never taken for 2.4.
find_path(TUMBLE_BOX2D_INCLUDE_DIR box2d/b2_world.h)
if(TUMBLE_BOX2D_INCLUDE_DIR)
	get_filename_component(box2d_prefix ${TUMBLE_BOX2D_INCLUDE_DIR} DIRECTORY)
	find_library(TUMBLE_BOX2D_LIBRARY box2d
		PATHS ${box2d_prefix}/lib/${CMAKE_LIBRARY_ARCHITECTURE} ${box2d_prefix}/lib NO_DEFAULT_PATH)
endif()
if(TUMBLE_BOX2D_INCLUDE_DIR AND TUMBLE_BOX2D_LIBRARY)
	target_sources(tumble-bench PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/peer_box2d.cpp)
	target_include_directories(tumble-bench SYSTEM PRIVATE ${TUMBLE_BOX2D_INCLUDE_DIR})
	target_link_libraries(tumble-bench PRIVATE ${TUMBLE_BOX2D_LIBRARY})
	target_compile_definitions(tumble-bench PRIVATE TUMBLE_HAVE_BOX2D)
	message(STATUS "tumble-bench: Box2D peer ${TUMBLE_BOX2D_LIBRARY}")
endif()

find_path(TUMBLE_CHIPMUNK_INCLUDE_DIR chipmunk/chipmunk.h)
find_library(TUMBLE_CHIPMUNK_LIBRARY chipmunk)
if(TUMBLE_CHIPMUNK_INCLUDE_DIR AND TUMBLE_CHIPMUNK_LIBRARY)
	target_sources(tumble-bench PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/peer_chipmunk.c)
	target_include_directories(tumble-bench SYSTEM PRIVATE ${TUMBLE_CHIPMUNK_INCLUDE_DIR})
	target_link_libraries(tumble-bench PRIVATE ${TUMBLE_CHIPMUNK_LIBRARY})
	target_compile_definitions(tumble-bench PRIVATE TUMBLE_HAVE_CHIPMUNK)
	# chipmunk_private.h (for the arbiter count) uses anonymous structs and unused static functions
	set_source_files_properties(${CMAKE_CURRENT_SOURCE_DIR}/peer_chipmunk.c PROPERTIES COMPILE_OPTIONS
		"-Wno-pedantic;-Wno-unused-parameter;-Wno-unused-function;-Wno-missing-prototypes")
	message(STATUS "tumble-bench: Chipmunk peer ${TUMBLE_CHIPMUNK_LIBRARY}")
endif()

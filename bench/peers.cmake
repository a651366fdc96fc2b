# tumble-bench: the scene benchmark (bench/tumble_bench.c) with peer adapters for Box2D 2.4.1 and
# Chipmunk 7, each compiled only when its development package is found. Included by
# bench/CMakeLists.txt. Peer headers are SYSTEM includes: their warnings are not ours.
if(NOT TARGET tumble_scenes)
	message(STATUS "tumble-bench: the scene catalogue (tumble_scenes) is missing, not built")
	return()
endif()

add_executable(tumble-bench ${CMAKE_CURRENT_SOURCE_DIR}/tumble_bench.c ${CMAKE_CURRENT_SOURCE_DIR}/peers.h)
target_include_directories(tumble-bench PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(tumble-bench PRIVATE tumble_scenes tumble m)

find_path(TUMBLE_BOX2D_INCLUDE_DIR box2d/box2d.h)
find_library(TUMBLE_BOX2D_LIBRARY box2d)
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

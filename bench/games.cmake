# tumble-bench-games (bench/bench_games.c, made by the bench_*.c loop in bench/CMakeLists.txt):
# the game scenes of bench/game_scenes.c are one source compiled twice, once against Tumble and once
# against Box2D v3.2 (when bench/peers.cmake found it: TUMBLE_BOX2D3_TARGET), each into a library
# of its own so that each compilation sees only its engine's headers and its own GAME_* switch.
if(NOT TARGET tumble-bench-games)
	return()
endif()
add_library(tumble_games_tumble STATIC ${CMAKE_CURRENT_SOURCE_DIR}/game_scenes.c ${CMAKE_CURRENT_SOURCE_DIR}/game_scenes.h)
target_compile_definitions(tumble_games_tumble PRIVATE GAME_TUMBLE)
target_link_libraries(tumble_games_tumble PRIVATE tumble m)
target_link_libraries(tumble-bench-games PRIVATE tumble_games_tumble)
if(TUMBLE_BOX2D3_TARGET)
	add_library(tumble_games_box2d3 STATIC ${CMAKE_CURRENT_SOURCE_DIR}/game_scenes.c)
	target_compile_definitions(tumble_games_box2d3 PRIVATE GAME_BOX2D3)
	target_link_libraries(tumble_games_box2d3 PRIVATE ${TUMBLE_BOX2D3_TARGET} m)
	target_link_libraries(tumble-bench-games PRIVATE tumble_games_box2d3)
	target_compile_definitions(tumble-bench-games PRIVATE TUMBLE_HAVE_BOX2D3)
endif()

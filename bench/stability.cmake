# tumble-stability: the stress scenes under each position method (scripts/stability.sh runs it
# and writes docs/stability.md and bench/results/stability.csv).
if(TARGET tumble_scenes)
	add_executable(tumble-stability ${CMAKE_CURRENT_LIST_DIR}/stability.c)
	target_link_libraries(tumble-stability PRIVATE tumble_scenes tumble m)
endif()

# Every internal header of src/ is described in docs/architecture.md's table of internal headers,
# named with its layer (`world/draw.h`) or, in a row that lists several of one folder, by its file
# name in backticks (`spatial_hash.h`). A header added without a line there fails, named.
#
#   cmake -DSRC=<src folder> -DDOC=<architecture.md> -P check_headers_documented.cmake
file(READ "${DOC}" doc)
file(GLOB_RECURSE headers RELATIVE "${SRC}" "${SRC}/*.h")
list(SORT headers)
set(missing "")
foreach(header IN LISTS headers)
	get_filename_component(name "${header}" NAME)
	string(FIND "${doc}" "`${header}`" withLayer)
	string(FIND "${doc}" "`${name}`" byName)
	if(withLayer EQUAL -1 AND byName EQUAL -1)
		string(APPEND missing "\n    ${header}")
	endif()
endforeach()
list(LENGTH headers count)
if(missing)
	message(FATAL_ERROR "check_headers_documented: internal headers ${DOC} does not describe:${missing}")
endif()
message(STATUS "check_headers_documented: ${count} internal headers, each described in ${DOC}")

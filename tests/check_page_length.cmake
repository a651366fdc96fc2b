# A reference page stays a page: FILE has at most MAX lines (history goes to the CHANGELOG and
# commit messages, raw output to bench/results/).
#
#   cmake -DFILE=<page> -DMAX=<lines> -P check_page_length.cmake
file(READ "${FILE}" text)
# Count the line ends (file(STRINGS) would split the page's ';' too, as list separators).
string(REGEX MATCHALL "\n" ends "${text}")
list(LENGTH ends count)
if(count GREATER MAX)
	message(FATAL_ERROR "check_page_length: ${FILE} has ${count} lines, more than ${MAX}")
endif()
message(STATUS "check_page_length: ${FILE}: ${count} lines (at most ${MAX})")

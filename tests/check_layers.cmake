# The layering of src/: each folder is a layer, and a file may include only headers of its own
# layer, of the layers below it, and the public headers (tumble/...).
#
#   core          allocation, errors, containers, arena, tasks, SIMD, sorting: nothing above it
#   collision     geometry and queries on shapes, usable without a world: core
#   broad_phase   the four pair-finding methods and the proxy table: core, collision
#   world, solver, joints
#                 the simulation: these three depend on one another and on everything below
#
# A header of another folder is named with its folder ("core/array.h"); a bare name must be a
# header of the including file's own folder. Run: cmake -DSRC=<dir> -P check_layers.cmake
# (exit status 0 when every include keeps to its layer; otherwise each offending line is listed).
cmake_minimum_required(VERSION 3.22)
if(NOT SRC)
	message(FATAL_ERROR "check_layers: give -DSRC=<the src directory>")
endif()

set(allowed_core core)
set(allowed_collision core collision)
set(allowed_broad_phase core collision broad_phase)
set(allowed_world core collision broad_phase world solver joints)
set(allowed_solver ${allowed_world})
set(allowed_joints ${allowed_world})
set(layers core collision broad_phase world solver joints)

set(violations "")
set(checked 0)
file(GLOB_RECURSE files RELATIVE ${SRC} ${SRC}/*.c ${SRC}/*.h)
foreach(file ${files})
	get_filename_component(folder ${file} DIRECTORY)
	if(NOT folder IN_LIST layers)
		string(APPEND violations "  ${file}: not in a layer folder (${layers})\n")
		continue()
	endif()
	file(STRINGS ${SRC}/${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
	set(number 0)
	foreach(line ${lines})
		string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" header "${line}")
		math(EXPR checked "${checked} + 1")
		if(header MATCHES "^tumble/")
			continue()
		endif()
		if(header MATCHES "/")
			string(REGEX REPLACE "/.*" "" target "${header}")
			if(NOT target IN_LIST layers)
				string(APPEND violations "  ${file}: \"${header}\" is not a header of a layer folder\n")
				continue()
			endif()
			if(NOT EXISTS ${SRC}/${header})
				string(APPEND violations "  ${file}: \"${header}\" does not exist\n")
				continue()
			endif()
		else()
			set(target ${folder})
			if(NOT EXISTS ${SRC}/${folder}/${header})
				string(APPEND violations
					"  ${file}: \"${header}\" is not in ${folder}/ (name another layer's header with its folder)\n")
				continue()
			endif()
		endif()
		if(NOT target IN_LIST allowed_${folder})
			string(REPLACE ";" " " may "${allowed_${folder}}")
			string(APPEND violations "  ${file}: includes \"${header}\": ${folder} may include only ${may}\n")
		endif()
	endforeach()
endforeach()

if(violations)
	message(FATAL_ERROR "check_layers: includes that break the layering of ${SRC}:\n${violations}")
endif()
list(LENGTH files count)
message(STATUS "check_layers: ${count} files, ${checked} includes, every one within its layer")

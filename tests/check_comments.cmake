# Comments in src/ and include/ say why, with their sources (papers, Box2D, the tests); what was
# measured, when and on which scene lives in docs/ (performance.md, methods.md, stability.md),
# where it can be dated and re-measured. A number in a comment goes stale without anyone seeing;
# the reason does not. This check fails on a comment line that holds
#
#   a date            2026-11-24, or a month with a year: November 2026, 24 Nov. 2026
#   a timing          a number followed by ms, µs, us or ns: 1.3 ms, 40us
#   a share           a number followed by % or "per cent": 9 %, 12%
#   a speed ratio     a number followed at once by × or x and then no digit or letter: 1.5×, 2x
#                     faster, (×1.3); maths is left alone: 2x2, 4×4, 3 × 3, 0.1 × linear slop,
#                     x = 3, 0x1F
#
# A comment is what follows // or lies between /* and */, once string and character literals are
# taken out of the line. Run: cmake -DROOT=<source tree> -P check_comments.cmake (checks
# ROOT/src and ROOT/include; exit status 0 when no comment holds one, otherwise each line is
# listed as file:line: what it holds: the comment).
cmake_minimum_required(VERSION 3.22)
if(NOT ROOT)
	message(FATAL_ERROR "check_comments: give -DROOT=<the source tree holding src/ and include/>")
endif()

set(month "(January|February|March|April|May|June|July|August|September|October|November|December|Jan|Feb|Mar|Apr|Jun|Jul|Aug|Sept|Sep|Oct|Nov|Dec)")
set(pattern_date_iso "(^|[^0-9])(19|20)[0-9][0-9]-[01][0-9]-[0-3][0-9]")
set(pattern_date_month "(^|[^A-Za-z])${month}[.]?( [0-9][0-9]?(st|nd|rd|th)?,?)? (19|20)[0-9][0-9]([^0-9]|$)")
set(pattern_timing "[0-9] ?(ms|µs|μs|us|ns)([^A-Za-z0-9_]|$)")
set(pattern_share "[0-9] ?(%|per ?cent)")
set(pattern_ratio "[0-9](×|x)([^0-9A-Za-z_]|$)|(^|[ (])×[0-9]")
set(kinds date_iso date_month timing share ratio)
set(what_date_iso "a date")
set(what_date_month "a date")
set(what_timing "a timing")
set(what_share "a share in per cent")
set(what_ratio "a speed ratio")

# The comment text of `line`, given whether a /* comment is open (`open`, updated). The code is read
# from the left: string and character literals are skipped whole, so a "//" inside one starts
# nothing, and the first // or /* outside them starts a comment.
function(comment_of line open_var out_var)
	set(open ${${open_var}})
	set(text "")
	set(code "${line}")
	while(NOT code STREQUAL "")
		if(open)
			string(FIND "${code}" "*/" end)
			if(end EQUAL -1)
				string(APPEND text " ${code}")
				break()
			endif()
			string(SUBSTRING "${code}" 0 ${end} part)
			string(APPEND text " ${part}")
			math(EXPR end "${end} + 2")
			string(SUBSTRING "${code}" ${end} -1 code)
			set(open FALSE)
			continue()
		endif()
		string(REGEX REPLACE "^[^\"'/]+" "" code "${code}")
		if(code MATCHES "^//")
			string(REGEX REPLACE "^//[/!<]*" "" part "${code}") # and the rest of /// or //!
			string(APPEND text " ${part}")
			break()
		elseif(code MATCHES "^/[*]")
			string(SUBSTRING "${code}" 2 -1 code)
			set(open TRUE)
		elseif(code MATCHES "^\"")
			string(REGEX REPLACE "^\"([^\"\\\\]|\\\\.)*\"?" "" code "${code}")
		elseif(code MATCHES "^'")
			string(REGEX REPLACE "^'([^'\\\\]|\\\\.)*'?" "" code "${code}")
		elseif(NOT code STREQUAL "")
			string(SUBSTRING "${code}" 1 -1 code) # a lone /: division
		endif()
	endwhile()
	set(${open_var} ${open} PARENT_SCOPE)
	set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

# Lists are split at ';', and '[' ']' hold a split back: stand-ins keep each line one element.
string(ASCII 1 semicolon)
string(ASCII 2 open_bracket)
string(ASCII 3 close_bracket)
set(violations "")
set(checked 0)
set(files "")
foreach(dir src include)
	if(EXISTS ${ROOT}/${dir})
		file(GLOB_RECURSE found RELATIVE ${ROOT} ${ROOT}/${dir}/*.c ${ROOT}/${dir}/*.h)
		list(APPEND files ${found})
	endif()
endforeach()
foreach(file ${files})
	math(EXPR checked "${checked} + 1")
	file(READ ${ROOT}/${file} content)
	set(candidate FALSE)
	foreach(kind ${kinds}) # CMake's regular expressions take ten groups: a pattern at a time
		if(content MATCHES "${pattern_${kind}}")
			set(candidate TRUE)
		endif()
	endforeach()
	if(NOT candidate)
		continue() # no candidate anywhere in the file, code included
	endif()
	string(REPLACE ";" "${semicolon}" content "${content}")
	string(REPLACE "[" "${open_bracket}" content "${content}")
	string(REPLACE "]" "${close_bracket}" content "${content}")
	string(REPLACE "\n" ";" lines "${content}")
	set(number 0)
	set(open FALSE)
	foreach(line IN LISTS lines)
		math(EXPR number "${number} + 1")
		if(NOT open AND NOT line MATCHES "/[/*]")
			continue()
		endif()
		comment_of("${line}" open text)
		foreach(kind ${kinds})
			if(text MATCHES "${pattern_${kind}}")
				string(STRIP "${text}" shown)
				string(REPLACE "${semicolon}" ";" shown "${shown}")
				string(REPLACE "${open_bracket}" "[" shown "${shown}")
				string(REPLACE "${close_bracket}" "]" shown "${shown}")
				string(APPEND violations "  ${file}:${number}: ${what_${kind}}: ${shown}\n")
				break()
			endif()
		endforeach()
	endforeach()
endforeach()

if(violations)
	message(FATAL_ERROR "check_comments: comments holding a date or a measurement (say why in the "
		"comment, put the figure in docs/):\n${violations}")
endif()
message(STATUS "check_comments: ${checked} files, no comment holds a date or a measurement")

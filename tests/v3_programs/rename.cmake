# A Box2D v3.2 program renamed for Tumble and nothing else: b2 → tb and B2_ → TB_ at the start of a
# name, and the include of box2d/box2d.h → tumble/tumble.h (as a game would port it).
#   cmake -DIN=program.c -DOUT=renamed.c -P rename.cmake
file(READ ${IN} text)
# A name starts after a character that cannot be part of an identifier (or at the start of the file).
string(REGEX REPLACE "([^A-Za-z0-9_])b2" "\\1tb" text "\n${text}")
string(REGEX REPLACE "([^A-Za-z0-9_])B2_" "\\1TB_" text "${text}")
string(REPLACE "\"box2d/box2d.h\"" "\"tumble/tumble.h\"" text "${text}")
string(SUBSTRING "${text}" 1 -1 text)
file(WRITE ${OUT} "${text}")

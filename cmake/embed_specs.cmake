# SPDX-License-Identifier: GPL-3.0-or-later
# Writes OUT, a C++ fragment holding each TOML file of FILES (figure specs, themes) (a ;-list) as
# {"stem", R"toml(...)toml"}, so that the built-in specs are compiled into the program.
# FILES is |-separated, as a ;-list would be split on the command line.
string(REPLACE "|" ";" FILES "${FILES}")
set(text "// generated from TOML files by cmake/embed_specs.cmake; do not edit\n")
foreach(file IN LISTS FILES)
  get_filename_component(stem "${file}" NAME_WE)
  file(READ "${file}" content)
  string(FIND "${content}" ")toml\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${file} contains the raw-string delimiter )toml\"")
  endif()
  string(APPEND text "{\"${stem}\", R\"toml(${content})toml\"},\n")
endforeach()
file(WRITE "${OUT}.tmp" "${text}")
file(COPY_FILE "${OUT}.tmp" "${OUT}" ONLY_IF_DIFFERENT)

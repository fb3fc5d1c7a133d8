# Writes the bytes of INPUT into OUTPUT as a C++ array named SYMBOL (and SYMBOL##Size) in
# namespace ensil::geo::embedded. Run by add_custom_command with cmake -P.
file(READ "${INPUT}" hex HEX)
string(LENGTH "${hex}" hex_length)
math(EXPR size "${hex_length} / 2")
# 32 bytes a line keeps the generated file readable and the compiler's line buffer small.
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
string(REGEX REPLACE "((0x[0-9a-f][0-9a-f],){32})" "\\1\n" bytes "${bytes}")
file(WRITE "${OUTPUT}"
"// Generated from ${INPUT} by geo/embed_file.cmake; do not edit.\n"
"#include <cstddef>\n"
"namespace ensil::geo::embedded {\n"
"extern const unsigned char ${SYMBOL}[];\n"
"extern const std::size_t ${SYMBOL}Size;\n"
"const unsigned char ${SYMBOL}[] = {\n${bytes}\n};\n"
"const std::size_t ${SYMBOL}Size = ${size};\n"
"}  // namespace ensil::geo::embedded\n")

# cmake -DIN=file -DOUT=file.cpp -DNAME=symbol -P embed_text.cmake
# Writes a C++ source that defines alp85::NAME as the text of IN (Intel HEX, listings).
file(READ "${IN}" content)
file(WRITE "${OUT}.tmp" "// Generated from ${IN} by emu/embed_text.cmake.\nnamespace alp85 {\nextern const char ${NAME}[];\nconst char ${NAME}[] = R\"embed(${content})embed\";\n}  // namespace alp85\n")
file(RENAME "${OUT}.tmp" "${OUT}")

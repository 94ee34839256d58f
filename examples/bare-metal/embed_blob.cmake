# cmake -DINPUT=blob.shdb -DOUTPUT=blob.c -P embed_blob.cmake
# Writes the blob as a 64-byte-aligned const array (flash) for the bare-metal example.
file(READ ${INPUT} hex HEX)
string(LENGTH "${hex}" chars)
math(EXPR bytes "${chars} / 2")
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," body "${hex}")
string(REGEX REPLACE "(0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,)" "\\1\n" body "${body}")
file(WRITE ${OUTPUT} "/* Generated from ${INPUT} by embed_blob.cmake. */\n#include <stddef.h>\n"
  "const unsigned char spinhash_blob[${bytes}] __attribute__((aligned(64), section(\".rodata.spinhash_blob\"))) = {\n"
  "${body}};\nconst size_t spinhash_blob_size = ${bytes};\n")

// A file copied into the program's read-only data by the assembler (.incbin): no megabyte C
// array for the compiler to parse. The path is a string literal the build defines; the source
// file that uses the macro lists the file in OBJECT_DEPENDS so it is rebuilt when the file
// changes (src/report/embed_plotly.cmake, src/studio/embed_page.cmake). Defines the hidden
// symbols NAME_begin and NAME_end (followed by a NUL byte) at namespace scope.
#pragma once

#define TRIBOLAB_INCBIN(NAME, PATH)         \
  asm(".section .rodata\n"                  \
      ".balign 16\n"                        \
      ".globl " #NAME "_begin\n"            \
      ".hidden " #NAME "_begin\n"           \
      #NAME "_begin:\n"                     \
      ".incbin \"" PATH "\"\n"              \
      ".globl " #NAME "_end\n"              \
      ".hidden " #NAME "_end\n"             \
      #NAME "_end:\n"                       \
      ".byte 0\n"                           \
      ".previous\n");                       \
  extern "C" const char NAME##_begin[];     \
  extern "C" const char NAME##_end[]

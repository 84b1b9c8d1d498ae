# Embeds src/studio/page.html into tribolab_studio the way src/report/embed_plotly.cmake embeds
# Plotly.js (report/incbin.hpp): the assembler's .incbin, rebuilt when the page changes.
set(studio_page ${CMAKE_SOURCE_DIR}/src/studio/page.html)
set_source_files_properties(${CMAKE_SOURCE_DIR}/src/studio/page.cpp PROPERTIES
  OBJECT_DEPENDS ${studio_page}
  COMPILE_DEFINITIONS "TRIBOLAB_STUDIO_PAGE_PATH=\"${studio_page}\"")

#include "studio/page.hpp"

#include "report/incbin.hpp"

#ifndef TRIBOLAB_STUDIO_PAGE_PATH
#error "build through CMake: src/studio/embed_page.cmake defines the page's path"
#endif

TRIBOLAB_INCBIN(tribolab_studio_page, TRIBOLAB_STUDIO_PAGE_PATH);

namespace tribolab::studio {

std::string_view page_html() {
  return {tribolab_studio_page_begin, static_cast<std::size_t>(tribolab_studio_page_end - tribolab_studio_page_begin)};
}

}  // namespace tribolab::studio

// The studio's page (src/studio/page.html: HTML and plain JavaScript, nothing fetched from
// the net), embedded in the binary like Plotly.js (report/incbin.hpp, embed_page.cmake).
#pragma once

#include <string_view>

namespace tribolab::studio {

std::string_view page_html();

}  // namespace tribolab::studio

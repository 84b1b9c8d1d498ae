#include "report/report.hpp"

#include <algorithm>
#include <initializer_list>
#include <string>

namespace tribolab::report {
namespace {

std::string sizes_differ(const std::string& what_a, std::size_t a, const std::string& what_b,
                         std::size_t b) {
  return what_a + " has " + std::to_string(a) + " values, " + what_b + " has " +
         std::to_string(b);
}

std::string validate_series(const Series& s) {
  const std::string prefix = "series '" + s.name + "': ";
  if (s.x.size() != s.y.size()) return prefix + sizes_differ("x", s.x.size(), "y", s.y.size());
  if (!s.x_error.empty() && s.x_error.size() != s.x.size()) {
    return prefix + sizes_differ("x_error", s.x_error.size(), "x", s.x.size());
  }
  if (!s.y_error.empty() && s.y_error.size() != s.y.size()) {
    return prefix + sizes_differ("y_error", s.y_error.size(), "y", s.y.size());
  }
  return {};
}

std::string validate_heatmap(const HeatMap& h) {
  if (h.z.size() != h.y.size()) {
    return "heat map: " + sizes_differ("z (rows)", h.z.size(), "y", h.y.size());
  }
  for (std::size_t i = 0; i < h.z.size(); ++i) {
    if (h.z[i].size() != h.x.size()) {
      return "heat map: " +
             sizes_differ("z row " + std::to_string(i), h.z[i].size(), "x", h.x.size());
    }
  }
  if (h.z_mid && !std::isfinite(*h.z_mid)) return "heat map: z_mid must be finite";
  return {};
}

}  // namespace

std::string Figure::validate() const {
  if (height_px < 100 || height_px > 4000) {
    return "height_px must be in [100, 4000], got " + std::to_string(height_px);
  }
  if (heatmap) {
    if (auto e = validate_heatmap(*heatmap); !e.empty()) return e;
  }
  for (const Series& s : series) {
    if (auto e = validate_series(s); !e.empty()) return e;
  }
  return {};
}

Section& Section::add_paragraph(std::string text) {
  blocks.emplace_back(Paragraph{std::move(text)});
  return *this;
}

Section& Section::add_subheading(std::string text) {
  blocks.emplace_back(Subheading{std::move(text)});
  return *this;
}

Section& Section::add_list(std::vector<std::string> items) {
  blocks.emplace_back(List{std::move(items)});
  return *this;
}

Section& Section::add_equation(std::string text, std::string source, std::string note) {
  blocks.emplace_back(Equation{std::move(text), std::move(source), std::move(note)});
  return *this;
}

Section& Section::add_table(Table table) {
  blocks.emplace_back(std::move(table));
  return *this;
}

Section& Section::add_figure(Figure figure) {
  blocks.emplace_back(std::move(figure));
  return *this;
}

Section& Section::add_gallery(Gallery gallery) {
  blocks.emplace_back(std::move(gallery));
  return *this;
}

std::string image_mime(const std::vector<unsigned char>& d) {
  auto starts = [&d](std::initializer_list<unsigned char> sig) {
    return d.size() >= sig.size() && std::equal(sig.begin(), sig.end(), d.begin());
  };
  if (starts({0xFF, 0xD8, 0xFF})) return "image/jpeg";
  if (starts({0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A})) return "image/png";
  return {};
}

int Section::figure_count() const {
  int n = 0;
  for (const Block& b : blocks) n += std::holds_alternative<Figure>(b) ? 1 : 0;
  return n;
}

Section& Report::add_section(std::string heading) {
  sections.push_back(Section{std::move(heading), {}});
  return sections.back();
}

int Report::figure_count() const {
  int n = 0;
  for (const Section& s : sections) n += s.figure_count();
  return n;
}

bool is_relative_link(const std::string& href) {
  if (href.empty() || href.front() == '/') return false;
  for (char c : href) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                    c == '_' || c == '-' || c == '/' || c == '%';
    if (!ok) return false;
  }
  return true;
}

std::string Report::validate() const {
  for (const Section& s : sections) {
    const std::string where = "section '" + s.heading + "', ";
    for (const Block& b : s.blocks) {
      if (const auto* f = std::get_if<Figure>(&b)) {
        if (auto e = f->validate(); !e.empty()) return where + "figure '" + f->title + "': " + e;
      } else if (const auto* g = std::get_if<Gallery>(&b)) {
        for (std::size_t i = 0; i < g->images.size(); ++i) {
          if (image_mime(g->images[i].data).empty()) {
            return where + "gallery '" + g->caption + "', image " + std::to_string(i + 1) + " ('" +
                   g->images[i].caption + "'): not a JPEG or PNG file (" + std::to_string(g->images[i].data.size()) +
                   " bytes)";
          }
        }
      } else if (const auto* t = std::get_if<Table>(&b)) {
        if (!t->links.empty() && t->links.size() != t->rows.size()) {
          return where + "table '" + t->caption + "': " + std::to_string(t->links.size()) + " links for " +
                 std::to_string(t->rows.size()) + " rows";
        }
        for (const std::string& href : t->links) {
          if (!href.empty() && !is_relative_link(href))
            return where + "table '" + t->caption + "': link '" + href + "' is not a relative path";
        }
        for (std::size_t r = 0; r < t->rows.size(); ++r) {
          if (t->rows[r].size() != t->header.size()) {
            return where + "table '" + t->caption + "': row " + std::to_string(r + 1) + " has " +
                   std::to_string(t->rows[r].size()) + " cells, the header has " +
                   std::to_string(t->header.size());
          }
        }
      }
    }
  }
  return {};
}

}  // namespace tribolab::report

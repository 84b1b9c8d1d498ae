#include "app/common/film_options.hpp"

#include "numerics/error.hpp"

#include <stdexcept>

namespace tribolab::app {

std::pair<int, int> parse_frame_size(const std::string& text) {
  const auto x = text.find_first_of("xX");
  int w = 0, h = 0;
  std::size_t used_w = 0, used_h = 0;
  try {
    if (x == std::string::npos) throw std::invalid_argument("no x");
    w = std::stoi(text.substr(0, x), &used_w);
    h = std::stoi(text.substr(x + 1), &used_h);
  } catch (const std::exception&) {
    throw InputError(field("size"), "expected WIDTHxHEIGHT in pixels (e.g. 640x480), got '" + text + "'");
  }
  if (used_w != x || used_h != text.size() - x - 1) {
    throw InputError(field("size"), "expected WIDTHxHEIGHT in pixels (e.g. 640x480), got '" + text + "'");
  }
  return {w, h};
}

void apply_background(const std::string& name, video::RenderOptions& r) {
  using B = video::RenderOptions::Background;
  if (name == "plain") r.background = B::plain;
  else if (name == "gradient") r.background = B::gradient;
  else if (name == "texture") r.background = B::texture;
  else throw InputError(field("background"), "unknown background '" + name + "' (plain, gradient, texture)");
  r.background_colour = r.background == B::texture ? cv::Scalar(180, 185, 190) : cv::Scalar(200, 200, 200);
}

}  // namespace tribolab::app

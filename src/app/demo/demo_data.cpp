#include "app/demo/demo_data.hpp"

#include <filesystem>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace tribolab::app {

std::vector<DemoFile> demo_files() {
  std::vector<DemoFile> files;
  for (const detail::EmbeddedFile* f = detail::kDemoFiles; f->name != nullptr; ++f) {
    files.push_back({f->name, {f->begin, static_cast<std::size_t>(f->end - f->begin)}});
  }
  return files;
}

std::string_view demo_file(std::string_view name) {
  for (const detail::EmbeddedFile* f = detail::kDemoFiles; f->name != nullptr; ++f) {
    if (name == f->name) return {f->begin, static_cast<std::size_t>(f->end - f->begin)};
  }
  throw std::logic_error("demo data file '" + std::string(name) +
                         "' is not embedded (is it in data/demo/? re-run cmake)");
}

std::string write_demo_file(std::string_view name, const std::string& dir) {
  const std::string_view content = demo_file(name);
  const std::filesystem::path path = std::filesystem::path(dir) / name;
  std::filesystem::create_directories(path.parent_path());
  io::AtomicFile out(path.string());
  out.stream().write(content.data(), static_cast<std::streamsize>(content.size()));
  out.commit();
  return path.string();
}

}  // namespace tribolab::app

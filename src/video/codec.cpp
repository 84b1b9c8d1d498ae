// Loading libtribolab_codec.so on first use (codec.hpp).
#include "video/codec.hpp"

#include "numerics/error.hpp"
#include "video/codec_api.hpp"

#include <dlfcn.h>

#include <mutex>

namespace tribolab::video {
namespace {

using codec_detail::CodecApi;

/// The codec library's table, loaded once per process and never unloaded (the objects it
/// makes carry its code). dlopen by file name searches the calling program's run path: the
/// build tree's bin/ for the build's programs, the installed lib/tribolab for installed ones,
/// the package folder for the Python module (CMakeLists.txt).
const CodecApi& api() {
  static std::once_flag once;
  static const CodecApi* table = nullptr;
  static std::string failure;
  std::call_once(once, [] {
    void* lib = ::dlopen(kCodecLibrary, RTLD_LAZY | RTLD_LOCAL);  // lazy binding as when linked
    if (lib == nullptr) {
      const char* why = ::dlerror();
      failure = std::string("cannot be loaded (") + (why ? why : "unknown reason") +
                "): it holds tribolab's video and image codecs; rebuild or reinstall tribolab";
      return;
    }
    using Entry = const CodecApi* (*)();
    const auto entry = reinterpret_cast<Entry>(::dlsym(lib, "tribolab_codec_api"));
    const CodecApi* t = entry ? entry() : nullptr;
    if (t == nullptr || t->version != codec_detail::kCodecApiVersion) {
      failure = "is not this version's codec library (a stale file left from another build?); "
                "rebuild or reinstall tribolab";
      return;
    }
    table = t;
  });
  if (table == nullptr) throw Error(kCodecLibrary, failure);
  return *table;
}

}  // namespace

std::unique_ptr<VideoFileReader> open_video_file(const std::string& path) {
  return std::unique_ptr<VideoFileReader>(api().open_reader(path));
}

std::unique_ptr<VideoFileWriter> create_video_file(const std::string& path, int fourcc, double fps,
                                                   cv::Size size) {
  return std::unique_ptr<VideoFileWriter>(api().create_writer(path, fourcc, fps, size));
}

std::vector<unsigned char> encode_image(const std::string& ext, const cv::Mat& image,
                                        const std::vector<int>& params) {
  std::vector<unsigned char> out;
  if (!api().encode(ext, image, params, out)) out.clear();
  return out;
}

cv::Mat decode_image(const std::vector<unsigned char>& bytes, int flags) { return api().decode(bytes, flags); }

}  // namespace tribolab::video

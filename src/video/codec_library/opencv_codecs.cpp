// libtribolab_codec.so: OpenCV's videoio (FFmpeg) and imgcodecs behind the table of
// codec_api.hpp. The only file linked against those two modules (codec.hpp says why).
#include "video/codec_api.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

namespace tribolab::video::codec_detail {
namespace {

class OpenCvReader final : public VideoFileReader {
 public:
  bool open(const std::string& path) { return cap_.open(path, cv::CAP_FFMPEG) && cap_.isOpened(); }
  bool grab() override { return cap_.grab(); }
  bool read(cv::Mat& bgr) override { return cap_.read(bgr); }
  double get(int property) const override { return cap_.get(property); }

 private:
  mutable cv::VideoCapture cap_;  // get() is not const in OpenCV's interface
};

class OpenCvWriter final : public VideoFileWriter {
 public:
  bool open(const std::string& path, int fourcc, double fps, cv::Size size) {
    return writer_.open(path, cv::CAP_FFMPEG, fourcc, fps, size) && writer_.isOpened();
  }
  void write(const cv::Mat& bgr) override { writer_.write(bgr); }
  void close() override { writer_.release(); }

 private:
  cv::VideoWriter writer_;
};

VideoFileReader* open_reader(const std::string& path) {
  auto r = std::make_unique<OpenCvReader>();
  return r->open(path) ? r.release() : nullptr;
}

VideoFileWriter* create_writer(const std::string& path, int fourcc, double fps, cv::Size size) {
  auto w = std::make_unique<OpenCvWriter>();
  return w->open(path, fourcc, fps, size) ? w.release() : nullptr;
}

bool encode(const std::string& ext, const cv::Mat& image, const std::vector<int>& params,
            std::vector<unsigned char>& out) {
  return cv::imencode(ext, image, out, params);
}

cv::Mat decode(const std::vector<unsigned char>& bytes, int flags) { return cv::imdecode(bytes, flags); }

const CodecApi kApi{kCodecApiVersion, open_reader, create_writer, encode, decode};

}  // namespace
}  // namespace tribolab::video::codec_detail

extern "C" __attribute__((visibility("default"))) const tribolab::video::codec_detail::CodecApi*
tribolab_codec_api() {
  return &tribolab::video::codec_detail::kApi;
}

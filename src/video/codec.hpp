// Video files and image encodings: OpenCV's videoio (FFmpeg) and imgcodecs, behind a library
// loaded on first use (docs/design.md#video-codecs).
//
// Those two OpenCV modules bring about 240 shared libraries into a process (FFmpeg's codecs,
// GStreamer, GDAL, ...): linked into the program, the dynamic loader spent 110 of the 135 ms
// every `tribolab` command took to start, most of it for commands that read no video. They
// are linked into libtribolab_codec.so only, which the first call below opens with dlopen,
// found through the calling program's run path like any shared library. Everything else in
// src/video needs OpenCV's core and imgproc alone.
#pragma once

#include <opencv2/core.hpp>

#include <memory>
#include <string>
#include <vector>

namespace tribolab::video {

/// A video file opened for reading with FFmpeg (a cv::VideoCapture inside the codec library).
/// Reading may throw cv::Exception, as cv::VideoCapture does.
class VideoFileReader {
 public:
  virtual ~VideoFileReader() = default;
  /// Demuxes the next frame without converting it; false at the end.
  virtual bool grab() = 0;
  /// Decodes the next frame into `bgr` (8-bit BGR); false at the end.
  virtual bool read(cv::Mat& bgr) = 0;
  /// A cv::CAP_PROP_* property (frame count, fps, fourcc, the last frame's time in ms).
  virtual double get(int property) const = 0;
};

/// A video file being written with FFmpeg (a cv::VideoWriter inside the codec library).
class VideoFileWriter {
 public:
  virtual ~VideoFileWriter() = default;
  virtual void write(const cv::Mat& bgr) = 0;
  /// Finishes the file (also done by the destructor).
  virtual void close() = 0;
};

/// Opens `path` with FFmpeg: nullptr when FFmpeg cannot open it (OpenCV may also throw
/// cv::Exception for some unreadable inputs). Throws std::runtime_error when the codec
/// library itself cannot be loaded.
std::unique_ptr<VideoFileReader> open_video_file(const std::string& path);

/// Creates `path` with FFmpeg's encoder for `fourcc` (see fourcc()): nullptr when it cannot.
std::unique_ptr<VideoFileWriter> create_video_file(const std::string& path, int fourcc, double fps,
                                                   cv::Size size);

/// The image encoded as `ext` (".jpg", ".png") with cv::IMWRITE_* `params`; empty on failure.
std::vector<unsigned char> encode_image(const std::string& ext, const cv::Mat& image,
                                        const std::vector<int>& params = {});

/// An encoded image decoded with cv::IMREAD_* `flags`; empty on failure.
cv::Mat decode_image(const std::vector<unsigned char>& bytes, int flags);

/// A four-character code as cv::VideoWriter::fourcc makes it.
constexpr int fourcc(char c1, char c2, char c3, char c4) {
  return (c1 & 255) | ((c2 & 255) << 8) | ((c3 & 255) << 16) | ((c4 & 255) << 24);
}

/// The codec library's file name, for messages (and how a program finds it: its run path).
inline constexpr const char* kCodecLibrary = "libtribolab_codec.so";

}  // namespace tribolab::video

// The table of functions libtribolab_codec.so exports (codec_opencv.cpp) and codec.cpp loads.
// Both sides are built in one tree by one compiler, so C++ types cross the boundary; the
// version guards against a stale library left beside a newer program.
#pragma once

#include "video/codec.hpp"

namespace tribolab::video::codec_detail {

inline constexpr int kCodecApiVersion = 1;

struct CodecApi {
  int version = 0;
  VideoFileReader* (*open_reader)(const std::string& path) = nullptr;
  VideoFileWriter* (*create_writer)(const std::string& path, int fourcc, double fps, cv::Size size) = nullptr;
  bool (*encode)(const std::string& ext, const cv::Mat& image, const std::vector<int>& params,
                 std::vector<unsigned char>& out) = nullptr;
  cv::Mat (*decode)(const std::vector<unsigned char>& bytes, int flags) = nullptr;
};

}  // namespace tribolab::video::codec_detail

/// The one symbol the codec library exports.
extern "C" const tribolab::video::codec_detail::CodecApi* tribolab_codec_api();

// film::ParallelScaler: the frame cut into bands of rows converts to exactly the bytes one swscale
// context over the whole frame gives, for every subsampling and depth a film uses.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "film/parallel_scaler.h"

extern "C" {
#include <libavutil/imgutils.h>
}

namespace vitrine::film {
namespace {

FramePtr frameOf(AVPixelFormat format, int width, int height) {
  FramePtr frame = makeFrame();
  frame->format = format;
  frame->width = width;
  frame->height = height;
  EXPECT_GE(av_frame_get_buffer(frame.get(), 0), 0);
  return frame;
}

// Rows of `a` and `b` that differ, over every plane.
int differingRows(const AVFrame& a, const AVFrame& b, AVPixelFormat format) {
  int rows = 0;
  const AVPixFmtDescriptor* desc = av_pix_fmt_desc_get(format);
  for (int p = 0; p < av_pix_fmt_count_planes(format); ++p) {
    const int height = (p == 1 || p == 2) ? AV_CEIL_RSHIFT(a.height, desc->log2_chroma_h) : a.height;
    const int bytes = av_image_get_linesize(format, a.width, p);  // the padding after is not the picture
    for (int y = 0; y < height; ++y)
      rows += std::memcmp(a.data[p] + y * a.linesize[p], b.data[p] + y * b.linesize[p], size_t(bytes)) != 0;
  }
  return rows;
}

struct Case {
  AVPixelFormat target;
  bool deep;
  bool fullRange;
};

TEST(ParallelScaler, BandsGiveTheWholeFramesBytes) {
  const int width = 96, height = 300;  // 300 rows: bands of 80 (multiples of 16) and a short last one
  for (const Case& c : {Case{AV_PIX_FMT_YUV420P, false, false}, Case{AV_PIX_FMT_YUV420P, false, true},
                        Case{AV_PIX_FMT_YUV422P, false, false}, Case{AV_PIX_FMT_YUV444P, false, false},
                        Case{AV_PIX_FMT_YUV422P10LE, true, false}, Case{AV_PIX_FMT_YUV444P10LE, true, false}}) {
    const AVPixelFormat source = c.deep ? AV_PIX_FMT_RGB48 : AV_PIX_FMT_RGB24;
    const size_t stride = size_t(width) * (c.deep ? 6 : 3);
    std::vector<uint8_t> rgb(stride * height);
    std::mt19937 random(7);
    for (uint8_t& byte : rgb) byte = uint8_t(random());  // noise: every filter tap shows at a band's edge
    ParallelScaler one(source, c.target, width, height, c.fullRange, "test", 1);
    ParallelScaler banded(source, c.target, width, height, c.fullRange, "test", 4);
    ASSERT_EQ(one.bands(), 1u);
    ASSERT_EQ(banded.bands(), 4u);
    FramePtr whole = frameOf(c.target, width, height), bands = frameOf(c.target, width, height);
    one.scale(rgb.data(), stride, *whole);
    banded.scale(rgb.data(), stride, *bands);
    EXPECT_EQ(differingRows(*whole, *bands, c.target), 0) << av_get_pix_fmt_name(c.target);
  }
}

}  // namespace
}  // namespace vitrine::film

#include "film/parallel_scaler.h"

#include "core/error.h"

extern "C" {
#include <libavutil/imgutils.h>
}

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <thread>

namespace vitrine::film {
namespace {

constexpr uint32_t kAlign = 16;    // band edges: the chroma rows' 2:1 and the ordered dither's 8 rows
constexpr uint32_t kMargin = 32;   // rows read beyond a band's own: wider than bicubic's 2:1 chroma filter
constexpr uint32_t kMinRows = 64;  // narrower bands cost more in margins than they save

}  // namespace

ParallelScaler::ParallelScaler(AVPixelFormat source, AVPixelFormat target, uint32_t width, uint32_t height,
                               bool fullRange, const std::string& film, uint32_t bands)
    : target_(target), width_(width) {
  if (bands == 0) bands = std::max(1u, std::thread::hardware_concurrency());
  bands = std::clamp(height / kMinRows, 1u, bands);
  const uint32_t step = (height / bands + kAlign - 1) / kAlign * kAlign;
  for (uint32_t first = 0; first < height; first += step) {
    Band band;
    band.first = first;
    band.rows = std::min(step, height - first);
    band.from = first >= kMargin ? first - kMargin : 0;
    band.height = std::min(height, first + band.rows + kMargin) - band.from;
    band.scaler = rgbToYuv(width, band.height, source, target, fullRange, film);
    bands_.push_back(std::move(band));
  }
  if (bands_.size() == 1) return;
  for (Band& band : bands_) {
    band.frame = makeFrame();
    band.frame->format = target;
    band.frame->width = int(width);
    band.frame->height = int(band.height);
    checkAv(av_frame_get_buffer(band.frame.get(), 0), film, "allocating a frame");
  }
}

void ParallelScaler::scale(const uint8_t* packed, size_t stride, AVFrame& out) {
  auto run = [&](Band& band) {
    const uint8_t* planes[1] = {packed + size_t(band.from) * stride};
    const int strides[1] = {int(stride)};
    AVFrame& into = band.frame ? *band.frame : out;
    sws_scale(band.scaler.get(), planes, strides, 0, int(band.height), into.data, into.linesize);
  };
  if (bands_.size() == 1) return run(bands_[0]);
  std::vector<std::jthread> threads;
  for (size_t i = 1; i < bands_.size(); ++i) threads.emplace_back([&, i] { run(bands_[i]); });
  run(bands_[0]);
  threads.clear();  // joined
  const AVPixFmtDescriptor* desc = av_pix_fmt_desc_get(target_);
  const int planes = av_pix_fmt_count_planes(target_);
  for (const Band& band : bands_) {
    for (int p = 0; p < planes; ++p) {
      const int shift = (p == 1 || p == 2) ? desc->log2_chroma_h : 0;
      const uint32_t first = band.first >> shift, rows = (band.first + band.rows + (1u << shift) - 1) >> shift;
      const uint32_t skip = band.from >> shift;
      const int bytes = av_image_get_linesize(target_, int(width_), p);
      for (uint32_t y = first; y < rows; ++y)
        std::memcpy(out.data[p] + size_t(y) * size_t(out.linesize[p]),
                    band.frame->data[p] + size_t(y - skip) * size_t(band.frame->linesize[p]), size_t(bytes));
    }
  }
}

}  // namespace vitrine::film

// The encoder choice (src/film/hardware_encoder.h): NVENC and VAAPI fail cleanly where the machine
// has neither, with their reasons in the sentence, and the software encoder tuned for latency gives a
// packet for every frame at once, a keyframe every second, within its bit rate.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "film/hardware_encoder.h"

namespace vitrine::film {
namespace {

EncoderRequest streamRequest(std::vector<EncoderKind> order) {
  EncoderRequest request;
  request.width = 64;
  request.height = 36;
  request.fps = 10;
  request.bitrate = 200'000;
  request.lowLatency = true;
  request.order = std::move(order);
  return request;
}

std::string refusal(const EncoderRequest& request) {
  try {
    HardwareEncoder encoder(request, "test");
  } catch (const Error& e) {
    return e.what();
  }
  return "opened";
}

bool hasNvidiaDriver() { return std::filesystem::exists("/dev/nvidiactl"); }

TEST(HardwareEncoder, NvencWithoutAnNvidiaDriverSaysWhy) {
  if (hasNvidiaDriver()) GTEST_SKIP() << "this machine has an NVIDIA driver: NVENC may open";
  const std::string why = refusal(streamRequest({EncoderKind::Nvenc}));
  EXPECT_NE(why.find("Cannot write test: no h264 encoder would start; h264_nvenc: "), std::string::npos) << why;
}

TEST(HardwareEncoder, VaapiWithoutARenderNodeSaysWhy) {
  EncoderRequest request = streamRequest({EncoderKind::Vaapi});
  request.renderNode = "/nonexistent/renderD128";
  const std::string why = refusal(request);
  EXPECT_NE(why.find("h264_vaapi: /nonexistent/renderD128 would not open"), std::string::npos) << why;
  if (!std::filesystem::exists("/dev/dri")) {
    request.renderNode.clear();
    EXPECT_NE(refusal(request).find("h264_vaapi: no render node in /dev/dri"), std::string::npos);
  }
}

TEST(HardwareEncoder, FallsBackToSoftwareSayingWhyTheOthersWereNot) {
  if (hasNvidiaDriver()) GTEST_SKIP() << "this machine has an NVIDIA driver: NVENC may open";
  EncoderRequest request = streamRequest({EncoderKind::Nvenc, EncoderKind::Vaapi, EncoderKind::Software});
  request.renderNode = "/nonexistent/renderD128";
  HardwareEncoder encoder(request, "test");
  EXPECT_EQ(encoder.kind(), EncoderKind::Software);
  EXPECT_EQ(encoder.name(), "libx264");
  const std::string& choice = encoder.choice();
  EXPECT_EQ(choice.rfind("encoding h264 with libx264 (software, tuned for latency); h264_nvenc: ", 0), 0u) << choice;
  EXPECT_NE(choice.find("; h264_vaapi: /nonexistent/renderD128 would not open"), std::string::npos) << choice;
}

TEST(HardwareEncoder, OnlyH264AndHevcAreLive) {
  EncoderRequest request = streamRequest({EncoderKind::Software});
  request.codec = Codec::Prores;
  EXPECT_EQ(refusal(request), "Cannot write test: only h264 and hevc are encoded live, not prores.");
}

// Tuned for latency: each frame comes out as it goes in (no lookahead, no B-frames), a keyframe every
// keyframeSeconds, and the stream stays near its bit rate.
TEST(HardwareEncoder, SoftwareTunedForLatencyHasNoDelay) {
  EncoderRequest request = streamRequest({EncoderKind::Software});
  request.keyframeSeconds = 0.5;  // every 5 frames at 10 fps
  HardwareEncoder encoder(request, "test");
  AVCodecContext& codec = encoder.codec();
  EXPECT_EQ(codec.pix_fmt, AV_PIX_FMT_YUV420P);
  EXPECT_EQ(codec.color_trc, AVCOL_TRC_IEC61966_2_1);
  PacketPtr packet = makePacket();
  std::vector<uint8_t> rgba(64 * 36 * 4);
  std::vector<int64_t> keyframes;
  int64_t bytes = 0;
  for (int64_t i = 0; i < 20; ++i) {
    // Noise sliding a pixel a frame: costly to code, yet no scene cut.
    for (uint32_t p = 0; p < 64 * 36; ++p)
      for (uint32_t k = 0; k < 3; ++k) rgba[p * 4 + k] = uint8_t(((p - uint32_t(i)) * 2654435761u >> (8 * k + 5)) & 0xff);
    ASSERT_EQ(avcodec_send_frame(&codec, &encoder.frame(rgba.data(), i)), 0);
    ASSERT_EQ(avcodec_receive_packet(&codec, packet.get()), 0) << "frame " << i << " gave no packet at once";
    EXPECT_EQ(packet->pts, i);
    if (packet->flags & AV_PKT_FLAG_KEY) keyframes.push_back(i);
    bytes += packet->size;
    av_packet_unref(packet.get());
  }
  EXPECT_EQ(keyframes, (std::vector<int64_t>{0, 5, 10, 15}));
  // 2 s at 200 kbit/s with a one-second buffer: at most 3 s of the rate, however noisy the frames.
  EXPECT_LE(bytes * 8, 3 * 200'000);
}

}  // namespace
}  // namespace vitrine::film

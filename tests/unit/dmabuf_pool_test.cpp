// The DMA-BUF hand-over's bookkeeping between PipeWire's thread and the frame thread: a buffer the
// consumer holds is never written, a copy goes to the consumer only once its submission has finished,
// the newest finished copy wins and the ones it replaces are counted, and a frame that finds no free
// buffer is refused (and wakes PipeWire's thread to look for returned ones), never waited for.
#include "rig/dmabuf_pool.h"

#include <gtest/gtest.h>

#include "gpu/dmabuf_export.h"

namespace vitrine::rig {
namespace {

constexpr VkExtent2D kSize{64, 36};
const int kBuffers[3] = {};  // their addresses stand for the stream's buffers

class DmaBufPoolTest : public ::testing::Test {
 protected:
  DmaBufPoolTest() : pool([this] { ++wakes; }) {
    for (const int& key : kBuffers) pool.add(&key, nullptr, kSize, VK_FORMAT_B8G8R8A8_UNORM);
    pool.setActive(true);
  }
  int wakes = 0;
  DmaBufPool pool;
};

TEST_F(DmaBufPoolTest, BuffersTheConsumerHoldsAreNotTaken) {
  EXPECT_TRUE(pool.active());
  EXPECT_EQ(pool.take(kSize), std::nullopt) << "every buffer starts with the stream";
  EXPECT_EQ(wakes, 1) << "a frame that finds none wakes PipeWire's thread to dequeue returned ones";
  pool.given(&kBuffers[1]);
  const auto target = pool.take(kSize);
  ASSERT_TRUE(target);
  EXPECT_EQ(target->format, VK_FORMAT_B8G8R8A8_UNORM);
  EXPECT_EQ(pool.take({32, 18}), std::nullopt) << "no buffer of another size";
}

TEST_F(DmaBufPoolTest, ACopyGoesToTheConsumerOnlyOnceItsSubmissionFinished) {
  pool.given(&kBuffers[0]);
  const auto target = pool.take(kSize);
  ASSERT_TRUE(target);
  pool.submitted(target->id, 7, 100, 1.5);
  uint64_t superseded = 0;
  EXPECT_FALSE(pool.markFinished(6));
  EXPECT_EQ(pool.takeDone(superseded), std::nullopt) << "submission 7 has not finished";
  EXPECT_TRUE(pool.markFinished(7));
  const auto done = pool.takeDone(superseded);
  ASSERT_TRUE(done);
  EXPECT_EQ(done->key, &kBuffers[0]);
  EXPECT_EQ(done->index, 100u);
  EXPECT_DOUBLE_EQ(done->time, 1.5);
  EXPECT_EQ(superseded, 0u);
  EXPECT_EQ(pool.take(kSize), std::nullopt) << "queued to the consumer: not written again until given back";
}

TEST_F(DmaBufPoolTest, TheNewestFinishedCopyWinsAndTheOthersAreCounted) {
  for (const int& key : kBuffers) pool.given(&key);
  for (uint64_t frame = 0; frame < 3; ++frame) {
    const auto target = pool.take(kSize);
    ASSERT_TRUE(target);
    pool.submitted(target->id, 10 + frame, frame, double(frame));
  }
  pool.markFinished(12);
  uint64_t superseded = 0;
  const auto done = pool.takeDone(superseded);
  ASSERT_TRUE(done);
  EXPECT_EQ(done->index, 2u);
  EXPECT_EQ(superseded, 2u);
  EXPECT_TRUE(pool.take(kSize)) << "the superseded ones are free again";
}

TEST_F(DmaBufPoolTest, ATakenImageNotCopiedIntoIsFreeAtTheNextTake) {
  pool.given(&kBuffers[0]);
  ASSERT_TRUE(pool.take(kSize));
  EXPECT_TRUE(pool.take(kSize)) << "the frame that took it was not drawn";
}

TEST_F(DmaBufPoolTest, ARemovedBufferIsForgottenAndItsLateSubmissionIgnored) {
  pool.given(&kBuffers[2]);
  const auto target = pool.take(kSize);
  ASSERT_TRUE(target);
  pool.remove(&kBuffers[2]);
  pool.submitted(target->id, 3, 0, 0.0);
  EXPECT_FALSE(pool.markFinished(3));
  EXPECT_EQ(pool.size(), 2u);
  pool.setActive(false);
  EXPECT_FALSE(pool.active());
}

}  // namespace
}  // namespace vitrine::rig

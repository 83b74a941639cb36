#include "core/atomic_file.h"
#include "core/error.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace vitrine {
namespace {

// A fresh, empty folder per test, removed afterwards (ctest may run the tests side by side).
class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = std::filesystem::temp_directory_path() /
              folderName(::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_);
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }
  static std::string folderName(const char* test) {
    return std::string("vitrine-atomic-") + test + "-" + std::to_string(::getpid());
  }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder_)) names.push_back(entry.path().filename());
    return names;
  }
  std::filesystem::path folder_;
};

std::string readAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw Error("test writer failed for " + path.string());
}

// What several headless runs with the same --out do: every write must land whole, none may fail.
TEST_F(AtomicFile, ConcurrentWritersToOnePathAllSucceedAndOneWins) {
  const auto target = folder_ / "out.exr";
  constexpr int kThreads = 8, kWrites = 20;
  auto contentFor = [](int thread, int write) {
    std::ostringstream text;  // large enough that interleaved writes would show
    for (int line = 0; line < 2000; ++line)
      text << "thread " << thread << " write " << write << " line " << line << '\n';
    return text.str();
  };
  std::set<std::string> written;
  for (int t = 0; t < kThreads; ++t)
    for (int w = 0; w < kWrites; ++w) written.insert(contentFor(t, w));

  std::atomic<int> failures{0};
  std::vector<std::string> errors(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int w = 0; w < kWrites; ++w) {
        try {
          replaceAtomically(target, [&](const std::filesystem::path& temporary) {
            writeText(temporary, contentFor(t, w));
          });
        } catch (const std::exception& e) {
          ++failures;
          errors[t] = e.what();
        }
      }
    });
  for (auto& thread : threads) thread.join();

  EXPECT_EQ(failures.load(), 0) << "e.g. " << [&] {
    for (const auto& e : errors)
      if (!e.empty()) return e;
    return std::string();
  }();
  EXPECT_TRUE(written.count(readAll(target))) << "the file is not any one writer's whole content";
  EXPECT_EQ(entries(), std::vector<std::string>{"out.exr"}) << "temporary files were left behind";
}

TEST_F(AtomicFile, TemporaryKeepsTheExtensionLastAndSitsBesideTheTarget) {
  const auto target = folder_ / "frame.exr";
  std::filesystem::path seen;
  replaceAtomically(target, [&](const std::filesystem::path& temporary) {
    seen = temporary;
    writeText(temporary, "x");
  });
  EXPECT_EQ(seen.parent_path(), folder_);
  EXPECT_EQ(seen.extension(), ".exr");
  EXPECT_EQ(seen.filename().string().front(), '.');  // hidden
  EXPECT_NE(seen.filename(), target.filename());
  EXPECT_EQ(readAll(target), "x");
}

TEST_F(AtomicFile, LongTargetNamesGetATemporaryNameTheFileSystemTakes) {
  const auto target = folder_ / (std::string(247, 'n') + "\xc3\xa9.png");  // 253 bytes, ends in a 2-byte character
  ASSERT_LE(target.filename().string().size(), 255u);
  std::filesystem::path seen;
  replaceAtomically(target, [&](const std::filesystem::path& temporary) {
    seen = temporary;
    writeText(temporary, "long");
  });
  EXPECT_LE(seen.filename().string().size(), 255u);
  EXPECT_EQ(seen.extension(), ".png");
  EXPECT_EQ(readAll(target), "long");
  EXPECT_EQ(entries().size(), 1u);
}

TEST_F(AtomicFile, ReportsTheOperatingSystemsReason) {
  const auto target = folder_ / "no-such-folder" / "x.exr";
  try {
    replaceAtomically(target, [](const std::filesystem::path& temporary) { std::ofstream(temporary) << "x"; });
    FAIL() << "expected an error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(target.string()), std::string::npos) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
    EXPECT_EQ(message.find("Success"), std::string::npos) << message;
  }
}

TEST_F(AtomicFile, AFailingWriterLeavesTheOldFileAndNoTemporary) {
  const auto target = folder_ / "keep.txt";
  writeText(target, "old");
  EXPECT_THROW(replaceAtomically(target,
                                 [](const std::filesystem::path& temporary) {
                                   writeText(temporary, "half");
                                   throw Error("writer gave up");
                                 }),
               Error);
  EXPECT_EQ(readAll(target), "old");
  EXPECT_EQ(entries(), std::vector<std::string>{"keep.txt"});
}

}  // namespace
}  // namespace vitrine

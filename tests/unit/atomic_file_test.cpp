#include "core/atomic_file.h"
#include "core/error.h"
#include "support/temp_folder.h"
#include "support/files.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>

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

class AtomicFile : public test::TempFolderTest {
 protected:
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder_)) names.push_back(entry.path().filename());
    return names;
  }
};

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
  EXPECT_TRUE(written.count(test::readFile(target))) << "the file is not any one writer's whole content";
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
  EXPECT_EQ(test::readFile(target), "x");
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
  EXPECT_EQ(test::readFile(target), "long");
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
  EXPECT_EQ(test::readFile(target), "old");
  EXPECT_EQ(entries(), std::vector<std::string>{"keep.txt"});
}

TEST_F(AtomicFile, WriteFileAtomicallyPutsEveryByteInPlace) {
  const auto target = folder_ / "bytes.bin";
  writeText(target, "old");
  std::vector<unsigned char> bytes(100000);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<unsigned char>(i * 7);
  writeFileAtomically(target, bytes);
  const std::string back = test::readFile(target);
  ASSERT_EQ(back.size(), bytes.size());
  EXPECT_TRUE(std::equal(bytes.begin(), bytes.end(), back.begin(),
                         [](unsigned char a, char b) { return a == static_cast<unsigned char>(b); }));
  EXPECT_EQ(entries(), std::vector<std::string>{"bytes.bin"});
}

// A writer killed between creating its temporary and renaming it (SIGKILL, a power cut) leaves the
// temporary: the next run removes it, but never the temporary of a writer that is still alive.
TEST_F(AtomicFile, StaleTemporariesOfDeadWritersAreRemovedAndLiveOnesKept) {
  const auto target = folder_ / "frame_000001.exr";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // dies in the middle of its write, as a killed recording does
    replaceAtomically(target, [](const std::filesystem::path& temporary) {
      std::ofstream(temporary) << "half a frame";
      ::_exit(0);
    });
    ::_exit(1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_EQ(WEXITSTATUS(status), 0);
  ASSERT_EQ(entries().size(), 1u) << "the dead writer left its temporary";
  writeText(folder_ / ".notes.txt", "not a temporary");  // a hidden file of someone else's: kept
  std::vector<std::filesystem::path> removedWhileAlive;
  replaceAtomically(folder_ / "frame_000002.exr", [&](const std::filesystem::path& temporary) {
    writeText(temporary, "a whole frame");
    removedWhileAlive = removeStaleTemporaries(folder_);  // this writer is alive: its temporary stays
    EXPECT_TRUE(std::filesystem::exists(temporary));
  });
  ASSERT_EQ(removedWhileAlive.size(), 1u);
  EXPECT_EQ(removedWhileAlive[0].parent_path(), folder_);
  EXPECT_TRUE(removedWhileAlive[0].filename().string().starts_with(".frame_000001.exr."));
  std::vector<std::string> names = entries();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{".notes.txt", "frame_000002.exr"}));
  EXPECT_TRUE(removeStaleTemporaries(folder_).empty());
}

// A hidden file shaped like this machine's temporaries but with a process number longer than any
// system's is someone else's file: it is kept, and the folder stays usable.
TEST_F(AtomicFile, ALookAlikeWithAnImpossibleProcessNumberIsKept) {
  std::string name;  // ".probe.exr.HOST-PID-COUNTER-RANDOM.tmp.exr": this machine's host word
  replaceAtomically(folder_ / "probe.exr", [&](const std::filesystem::path& temporary) {
    name = temporary.filename().string();
    writeText(temporary, "x");
  });
  std::string host = name.substr(std::string(".probe.exr.").size());
  for (int dashes = 0; dashes < 3; ++dashes) host.erase(host.rfind('-'));
  const auto lookAlike = folder_ / fmt::format(".x.{}-{}-3-deadbeef.tmp.exr", host, std::string(40, 'f'));
  writeText(lookAlike, "not a temporary");
  std::vector<std::filesystem::path> removed;
  EXPECT_NO_THROW(removed = removeStaleTemporaries(folder_));
  EXPECT_TRUE(removed.empty());
  EXPECT_TRUE(std::filesystem::exists(lookAlike));
}

TEST_F(AtomicFile, AFolderThatCannotBeWrittenIsFoundBeforeAnyWork) {
  EXPECT_NO_THROW(checkWritableFolder(folder_));
  EXPECT_TRUE(entries().empty()) << "the probe was left behind";
  try {
    checkWritableFolder(folder_ / "missing");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vitrine

// Hot reload: editing a shader rebuilds the pipelines that use it; a compile error keeps the old
// pipeline and reports the file and line.
#include "gpu/program.h"
#include "support/gpu_test.h"

#include <fstream>
#include <sstream>

namespace vitrine::test {
namespace {

class HotReload : public GpuTest {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    // One folder per test: ctest -j runs the tests of this fixture side by side.
    root_ = std::filesystem::temp_directory_path() /
            (std::string("vitrine-hot-reload-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(root_);
    std::filesystem::copy(VITRINE_SHADER_SOURCE_DIR, root_, std::filesystem::copy_options::recursive);
  }
  void TearDown() override {
    std::filesystem::remove_all(root_);
    GpuTest::TearDown();
  }
  // Rewrites a shader with one substitution and moves its time forward (mtime granularity).
  void edit(const std::string& name, const std::string& from, const std::string& to) {
    const auto path = root_ / name;
    std::stringstream text;
    text << std::ifstream(path).rdbuf();
    std::string source = text.str();
    const auto at = source.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    source.replace(at, from.size(), to);
    std::ofstream(path) << source;
    std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now() + std::chrono::seconds(++tick_));
  }
  std::filesystem::path root_;
  int tick_ = 0;
};

TEST_F(HotReload, RebuildsOnChangeAndKeepsThePipelineOnError) {
  gpu::ProgramLibrary library(device(), root_);
  gpu::ComputeProgram program(library, "host/present.comp",
                              {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, 4});
  EXPECT_EQ(library.reloadChanged(), 0);  // nothing changed yet

  edit("host/present.comp", "colour.rgb = linearToSrgb(colour.rgb);", "colour.rgb = linearToSrgb(colour.bgr);");
  EXPECT_EQ(library.reloadChanged(), 1) << library.error();
  EXPECT_TRUE(library.error().empty()) << library.error();
  const VkPipeline rebuilt = program.pipeline();
  EXPECT_NE(rebuilt, VK_NULL_HANDLE);
  EXPECT_NE(library.spirv("host/present.comp").size(), 0u);

  edit("host/present.comp", "imageStore(destination, pixel, colour);", "imageStore(destination, pixel, colour)");
  EXPECT_EQ(library.reloadChanged(), 0);
  EXPECT_EQ(program.pipeline(), rebuilt);  // the old pipeline stays
  EXPECT_NE(library.error().find("present.comp:"), std::string::npos) << library.error();

  edit("host/present.comp", "imageStore(destination, pixel, colour)", "imageStore(destination, pixel, colour);");
  EXPECT_EQ(library.reloadChanged(), 0);  // back to code already running: nothing to rebuild
  EXPECT_TRUE(library.error().empty()) << library.error();
}

TEST_F(HotReload, AnIncludedFileRebuildsItsUsers) {
  gpu::ProgramLibrary library(device(), root_);
  gpu::ComputeProgram program(library, "kifs/kifs.comp", {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, 40});
  edit("kifs/field.glsl", "const float CORE_RADIUS = 0.44;", "const float CORE_RADIUS = 0.5;");
  EXPECT_EQ(library.reloadChanged(), 1);
  EXPECT_TRUE(library.error().empty()) << library.error();
}

}  // namespace
}  // namespace vitrine::test

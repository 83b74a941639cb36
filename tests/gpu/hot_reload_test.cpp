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
  gpu::ComputeProgram program(library, "host/present.comp");
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
  gpu::ComputeProgram program(library, "kifs/kifs.comp");
  edit("kifs/field.glsl", "const float CORE_RADIUS = 0.44;", "const float CORE_RADIUS = 0.5;");
  EXPECT_EQ(library.reloadChanged(), 1);
  EXPECT_TRUE(library.error().empty()) << library.error();
}

// The interface is the shader's: an edit that adds a binding rebuilds the program's layouts with it.
TEST_F(HotReload, AnEditedInterfaceRebuildsTheLayout) {
  gpu::ProgramLibrary library(device(), root_);
  gpu::ComputeProgram program(library, "kifs/kifs.comp");
  ASSERT_EQ(program.interface().bindings.size(), 1u);
  const VkPipelineLayout before = program.layout();
  edit("kifs/kifs.comp", "layout(push_constant) uniform Push { KifsMarchPush pc; };",
       "layout(push_constant) uniform Push { KifsMarchPush pc; };\n"
       "layout(binding = 1, std430) readonly buffer Exposure { float exposure; };");
  edit("kifs/kifs.comp", "vec3 glow = vec3(0.0);", "vec3 glow = vec3(0.0 * exposure);");
  EXPECT_EQ(library.reloadChanged(), 1) << library.error();
  ASSERT_EQ(program.interface().bindings.size(), 2u);
  EXPECT_EQ(program.interface().bindings[1].name, "Exposure");
  EXPECT_NE(program.layout(), before);
}

// A scene that is not showing has no programs: its shaders' edits are taken when it opens.
TEST_F(HotReload, AShaderNotInUseTakesItsEditWhenFirstUsed) {
  gpu::ProgramLibrary library(device(), root_);
  const std::vector<uint32_t> builtIn(library.spirv("host/present.comp").begin(), library.spirv("host/present.comp").end());
  edit("host/present.comp", "colour.rgb = linearToSrgb(colour.rgb);", "colour.rgb = linearToSrgb(colour.bgr);");
  EXPECT_EQ(library.reloadChanged(), 0);  // nothing in use to rebuild
  EXPECT_TRUE(library.takeReloaded().empty());
  gpu::ComputeProgram program(library, "host/present.comp");
  const auto used = library.spirv("host/present.comp");
  EXPECT_FALSE(std::equal(used.begin(), used.end(), builtIn.begin(), builtIn.end()));
  EXPECT_EQ(library.takeReloaded(), std::vector<std::string>{"host/present.comp"});
  EXPECT_TRUE(library.takeReloaded().empty());  // said once
}

// The gallery run from a source tree edited after the build uses the sources; headless runs never do.
TEST_F(HotReload, SourcesNewerThanTheBinaryAreUsedAtStartOnlyWhenPreferred) {
  const auto lastWeek = std::filesystem::file_time_type::clock::now() - std::chrono::hours(24 * 7);
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root_))  // as old as a checkout
    if (entry.is_regular_file()) std::filesystem::last_write_time(entry.path(), lastWeek);
  edit("host/present.comp", "colour.rgb = linearToSrgb(colour.rgb);", "colour.rgb = linearToSrgb(colour.bgr);");
  std::filesystem::last_write_time(root_ / "host/present.comp",
                                   std::filesystem::file_time_type::clock::now() + std::chrono::hours(1));
  gpu::ProgramLibrary headless(device(), root_);
  gpu::ProgramLibrary gallery(device(), root_, /*preferNewerSources=*/true);
  const auto a = headless.spirv("host/present.comp");
  const auto b = gallery.spirv("host/present.comp");
  EXPECT_FALSE(std::equal(a.begin(), a.end(), b.begin(), b.end()));
  EXPECT_TRUE(headless.takeReloaded().empty());
  EXPECT_EQ(gallery.takeReloaded(), std::vector<std::string>{"host/present.comp"});
  const auto kifs = gallery.spirv("kifs/kifs.comp");  // unedited: compiles to what is built in
  const auto kifsBuiltIn = headless.spirv("kifs/kifs.comp");
  EXPECT_TRUE(std::equal(kifs.begin(), kifs.end(), kifsBuiltIn.begin(), kifsBuiltIn.end()));
  EXPECT_TRUE(gallery.takeReloaded().empty());
}

}  // namespace
}  // namespace vitrine::test

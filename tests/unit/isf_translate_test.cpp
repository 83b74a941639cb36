// The GLSL translation: what the preamble declares, what the rewrite changes and keeps, and the one
// table of the uniform block's layout against what glslang lays out.
#include "isf/isf_compile.h"
#include "isf/isf_translate.h"

#include "gpu/shader_reflection.h"
#include "isf_test_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace vitrine::isf {
namespace {

using test::isfFile;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(IsfTranslate, TheFrameBlockTableIsStd140) {
  const BlockLayout layout = frameBlock(loadDocument(isfFile("every_input.fs")));
  std::vector<std::pair<std::string, uint32_t>> offsets;
  for (const auto& m : layout.members) offsets.emplace_back(m.name, m.offset);
  const std::vector<std::pair<std::string, uint32_t>> expected = {
      {"TIME", 0},    {"TIMEDELTA", 4}, {"FRAMEINDEX", 8}, {"DATE", 16},   {"flash", 32},
      {"invert", 36}, {"bands", 40},    {"speed", 44},     {"centre", 48}, {"tint", 64}};
  EXPECT_EQ(offsets, expected);
  EXPECT_EQ(layout.size, 80u);
  EXPECT_EQ(layout.members[4].source, BlockMember::Source::Input);
  EXPECT_EQ(layout.members[4].input, 0);
}

// Whatever glslang lays out is what the table says: every member at its offset, every sampler at its
// binding, the pass's push constants within their block. The host fills the block from the table.
class IsfLayoutAgrees : public testing::TestWithParam<const char*> {};

TEST_P(IsfLayoutAgrees, WithTheCompiledShader) {
  const Document doc = loadDocument(isfFile(GetParam()));
  const CompiledIsf compiled = compileIsf(doc, loadVertexFile(isfFile(GetParam())));
  for (const auto* spirv : {&compiled.fragment, &compiled.vertex}) {
    const gpu::ShaderInterface shader = gpu::reflectShader(*spirv, GetParam());
    const auto block = std::find_if(shader.structs.begin(), shader.structs.end(),
                                    [](const gpu::ReflectedStruct& s) { return s.name == "ISFFrame"; });
    ASSERT_NE(block, shader.structs.end());
    for (const BlockMember& member : compiled.translation.frame.members) {
      const auto found = std::find_if(block->members.begin(), block->members.end(),
                                      [&](const gpu::ReflectedMember& m) { return m.name == member.name; });
      ASSERT_NE(found, block->members.end()) << member.name;
      EXPECT_EQ(found->offset, member.offset) << member.name;
      EXPECT_EQ(found->size, member.size) << member.name;
    }
    EXPECT_LE(block->size, compiled.translation.frame.size);
    EXPECT_LE(shader.pushConstantBytes, kPassBlockBytes);
    for (const SamplerBinding& sampler : compiled.translation.samplers) {
      const auto found = std::find_if(shader.bindings.begin(), shader.bindings.end(),
                                      [&](const gpu::ReflectedBinding& b) { return b.name == sampler.name; });
      if (found == shader.bindings.end()) continue;  // a sampler the stage never reads is compiled out
      EXPECT_EQ(found->binding, sampler.binding) << sampler.name;
      EXPECT_EQ(found->type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Files, IsfLayoutAgrees,
                         testing::Values("every_input.fs", "multipass.fs", "rotate.fs", "events.fs", "audio.fs"));

TEST(IsfTranslate, SamplersInInputThenImportedThenTargetOrder) {
  const auto doc = parseDocument(R"(/*{"INPUTS": [{"NAME": "inputImage", "TYPE": "image"}, {"NAME": "f", "TYPE": "float"},
      {"NAME": "snd", "TYPE": "audioFFT"}], "IMPORTED": {"pic": {"PATH": "p.png"}},
      "PASSES": [{"TARGET": "buf", "PERSISTENT": true}, {}]}*/ void main() {})", "s.fs");
  const auto samplers = samplerBindings(doc);
  ASSERT_EQ(samplers.size(), 4u);
  const char* names[] = {"inputImage", "snd", "pic", "buf"};
  for (uint32_t i = 0; i < 4; ++i) {
    EXPECT_EQ(samplers[i].name, names[i]);
    EXPECT_EQ(samplers[i].binding, i + 1);
  }
  EXPECT_EQ(samplers[3].source, SamplerBinding::Source::Target);
}

TEST(IsfTranslate, RewritesGlesCodeAndKeepsTheRest) {
  const Translation t = translate(loadDocument(isfFile("gles_style.fs")));
  EXPECT_FALSE(has(t.fragment, "texture2D("));
  EXPECT_FALSE(has(t.fragment, "gl_FragColor"));
  EXPECT_TRUE(has(t.fragment, "vec4 source = texture(inputImage, isf_FragNormCoord);"));
  EXPECT_TRUE(has(t.fragment, "isf_texture2DRect(inputImage, gl_FragCoord.xy + vec2(2.0, 0.0))"));
  EXPECT_TRUE(has(t.fragment, "precision highp float;"));
  EXPECT_TRUE(has(t.fragment, "mediump vec3 desaturate(mediump vec3 c, float by) {"));
  EXPECT_TRUE(has(t.fragment, "#line 8 1\n"));  // the body starts on the line of "}*/"
  EXPECT_EQ(t.fragment.rfind("#version", 0), 0u);
}

TEST(IsfTranslate, KeepsEveryLineOfTheBodyWhereItWas) {
  for (const char* name : {"every_input.fs", "gl3_style.fs", "rotate.fs", "multipass.fs"}) {
    const Document doc = loadDocument(isfFile(name));
    const Translation t = translate(doc, loadVertexFile(isfFile(name)));
    const std::string marker = "#line " + std::to_string(doc.glslFirstLine) + " 1\n";
    const size_t start = t.fragment.find(marker) + marker.size();
    const size_t end = t.fragment.find("\n#line ", start);
    const std::string body = t.fragment.substr(start, end - start);
    EXPECT_EQ(std::count(body.begin(), body.end(), '\n'), std::count(doc.glsl.begin(), doc.glsl.end(), '\n') - 1) << name;
  }
}

// Every loop whose trip count its text does not fix has its condition guarded, whatever its form; one
// whose count it fixes is charged as it enters; the code around keeps its text and lines.
TEST(IsfTranslate, GuardsEveryLoop) {
  const std::string body =
      "void main() {\n"
      "  float s = 0.0;\n"
      "  for (int i = 0; i < f(1, 2); ++i) s += 1.0;\n"
      "  for (;;) { break; }\n"
      "  while (s > 0.0) s -= 1.0;\n"
      "  do { s += 1.0; } while (s < 3.0 /* ) */);\n"
      "  for (int j = 0;\n"
      "       j < 2;\n"
      "       ++j) {}\n"
      "  gl_FragColor = vec4(s);\n"
      "}\n";
  const Document doc = parseDocument("/*{}*/\nfloat f(int a, int b) { return float(a + b); }\n" + body, "loops.fs");
  const Translation t = translate(doc);
  EXPECT_TRUE(has(t.fragment, "for (int i = 0;( i < f(1, 2)) && isf_guard(); ++i) s += 1.0;")) << t.fragment;
  EXPECT_TRUE(has(t.fragment, "for (;isf_guard();) { break; }"));
  EXPECT_TRUE(has(t.fragment, "while ((s > 0.0) && isf_guard()) s -= 1.0;"));
  EXPECT_TRUE(has(t.fragment, "while ((s < 3.0 /* ) */) && isf_guard());"));
  EXPECT_TRUE(has(t.fragment, "{ if (isf_enter(2)) for (int j = 0;\n       j < 2;\n       ++j) {} }")) << t.fragment;
  EXPECT_TRUE(has(t.fragment, "bool isf_guard() { return ++isf_guardCount <= 65536; }"));
  EXPECT_TRUE(has(t.fragment, "bool isf_enter(int trips) {"));
  // Lines kept: "gl_FragColor" is still on the body's 10th line, the file's 12th.
  const size_t start = t.fragment.find("#line 1 1\n");
  ASSERT_NE(start, std::string::npos);
  const std::string after = t.fragment.substr(start + std::string("#line 1 1\n").size());
  const size_t colour = after.find("isf_FragColor = vec4(s);");
  EXPECT_EQ(std::count(after.begin(), after.begin() + std::ptrdiff_t(colour), '\n'), 11);
  EXPECT_NO_THROW(compileIsf(doc));
}

// Where every loop is fixed and all of them together fit the budget, none is charged or guarded: the
// code is the author's, as a native shader would have it.
TEST(IsfTranslate, FixedLoopsWithinTheBudgetAreLeftAsWritten) {
  const std::string body =
      "float fbm(vec2 p) {\n  float s = 0.0;\n  for (int i = 0; i < 6; ++i) { s += sin(p.x); p *= 2.0; }\n"
      "  return s;\n}\n"
      "void main() {\n  float s = fbm(isf_FragNormCoord) + fbm(isf_FragNormCoord.yx);\n  gl_FragColor = vec4(s);\n}\n";
  const Translation t = translate(parseDocument("/*{}*/\n" + body, "fixed.fs"));
  EXPECT_TRUE(has(t.fragment, "  for (int i = 0; i < 6; ++i) { s += sin(p.x); p *= 2.0; }\n")) << t.fragment;
  EXPECT_FALSE(has(t.fragment, "isf_enter(6)"));
  EXPECT_FALSE(has(t.fragment, "&& isf_guard()"));
}

// A charged loop (here, as the file has a loop that is not fixed) is wrapped in braces, so an `else`
// after it keeps the `if` it had, and nested ones close in their order.
TEST(IsfTranslate, AChargedLoopKeepsTheStatementsAroundIt) {
  const Document doc = parseDocument(
      "/*{}*/\nvoid main() {\n  float s = 0.0;\n"
      "  if (isf_FragNormCoord.x > 0.5) for (int i = 0; i < 3; i++) { for (int j = 0; j < 4; j++) { s += 1.0; } }\n"
      "  else s = -1.0;\n  while (s > 100.0) s -= 1.0;\n  gl_FragColor = vec4(s);\n}\n",
      "charged.fs");
  const Translation t = translate(doc);
  EXPECT_TRUE(has(t.fragment, "if (isf_FragNormCoord.x > 0.5) { if (isf_enter(3)) for (int i = 0; i < 3; i++) "
                              "{ { if (isf_enter(4)) for (int j = 0; j < 4; j++) { s += 1.0; } } } }\n  else s = -1.0;"))
      << t.fragment;
  EXPECT_NO_THROW(compileIsf(doc));
}

TEST(IsfTranslate, RenamesWordsVulkanGlslReserves) {
  const Translation t = translate(loadDocument(isfFile("every_input.fs")));
  EXPECT_TRUE(has(t.fragment, "float isf_r_sample = IMG_NORM_PIXEL(wave"));
  EXPECT_TRUE(has(t.fragment, "void isf_main() {"));
}

TEST(IsfTranslate, GivesEachVaryingOneLocationInBothStages) {
  const Document doc = loadDocument(isfFile("rotate.fs"));
  const Translation t = translate(doc, loadVertexFile(isfFile("rotate.fs")));
  EXPECT_TRUE(has(t.vertex, "layout(location = 1) out vec2 turned;"));
  EXPECT_TRUE(has(t.vertex, "layout(location = 2) out vec2 neighbours[2];"));
  EXPECT_TRUE(has(t.fragment, "layout(location = 1) in vec2 turned;"));
  EXPECT_TRUE(has(t.fragment, "layout(location = 2) in vec2 neighbours[2];"));
  EXPECT_TRUE(has(t.vertex, "#line 1 2\n"));
}

TEST(IsfTranslate, AFragmentOutputOfItsOwnTakesLocationZero) {
  const Translation t = translate(loadDocument(isfFile("gl3_style.fs")));
  EXPECT_TRUE(has(t.fragment, "layout(location = 0) out vec4 fragColour;"));
  EXPECT_FALSE(has(t.fragment, "out vec4 isf_FragColor"));
  EXPECT_FALSE(has(t.fragment, "#version 330"));
}

TEST(IsfTranslate, RefusesWhatTheHostCannotGiveAtItsLine) {
  const Document doc = parseDocument("/*{}*/\nvarying vec2 uv;\nvoid main() { gl_FragColor = vec4(uv, 0.0, 1.0); }", "v.fs");
  try {
    translate(doc);
    FAIL();
  } catch (const IsfError& e) {
    EXPECT_EQ(e.line, 2);
    EXPECT_NE(e.why.find("no vertex shader writes"), std::string::npos);
  }
  const Document plain = parseDocument("/*{}*/ void main() { gl_FragColor = vec4(1.0); }", "p.fs");
  try {
    translate(plain, VertexFile{"// positions\nattribute vec2 position;\nvoid main() { isf_vertShaderInit(); }\n", "p.vs"});
    FAIL();
  } catch (const IsfError& e) {
    EXPECT_EQ(e.file, "p.vs");
    EXPECT_EQ(e.line, 2);
    EXPECT_NE(e.why.find("no vertex buffer"), std::string::npos);
  }
}

}  // namespace
}  // namespace vitrine::isf

// Every one of the project's ISF files compiles to SPIR-V with no GPU; a compile error names the
// author's file and line.
#include "isf/isf_compile.h"

#include "isf_test_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace vitrine::isf {
namespace {

using test::isfFile;

class IsfCompiles : public testing::TestWithParam<const char*> {};

TEST_P(IsfCompiles, ToSpirvForBothStages) {
  const Document doc = loadDocument(isfFile(GetParam()));
  const CompiledIsf compiled = compileIsf(doc, loadVertexFile(isfFile(GetParam())));
  ASSERT_GT(compiled.fragment.size(), 5u);
  ASSERT_GT(compiled.vertex.size(), 5u);
  EXPECT_EQ(compiled.fragment[0], 0x07230203u);  // the SPIR-V magic number
  EXPECT_EQ(compiled.vertex[0], 0x07230203u);
}

INSTANTIATE_TEST_SUITE_P(Files, IsfCompiles,
                         testing::Values("every_input.fs", "gles_style.fs", "gl3_style.fs", "multipass.fs", "imported.fs",
                                         "rotate.fs", "transition.fs", "audio.fs", "events.fs"),
                         [](const testing::TestParamInfo<const char*>& p) {
                           std::string name = p.param;
                           return name.substr(0, name.find('.'));
                         });

TEST(IsfCompile, AnErrorOnLine12OfTheFileSaysLine12) {
  const Document doc = loadDocument(isfFile("line12_error.fs"));
  try {
    compileIsf(doc);
    FAIL() << "compiled";
  } catch (const IsfError& e) {
    EXPECT_EQ(e.line, 12) << e.what();
    EXPECT_EQ(e.file, isfFile("line12_error.fs").string());
    EXPECT_NE(e.why.find("'brightnes' : undeclared identifier"), std::string::npos) << e.what();
  }
}

TEST(IsfCompile, AnErrorInTheVertexShaderNamesTheVsFile) {
  const Document doc = parseDocument("/*{}*/\nvoid main() { gl_FragColor = vec4(1.0); }\n", "pair.fs");
  try {
    compileIsf(doc, VertexFile{"void main() {\n  isf_vertShaderInit();\n  gl_Position.x += undefinedThing;\n}\n", "pair.vs"});
    FAIL() << "compiled";
  } catch (const IsfError& e) {
    EXPECT_EQ(e.file, "pair.vs");
    EXPECT_EQ(e.line, 3) << e.what();
  }
}

TEST(IsfCompile, OutputsAsGlTwoAndGlThreeWriteThem) {
  // gl_FragData[0] rather than gl_FragColor; an output with its own layout, which the rewrite keeps.
  for (const char* text : {"/*{}*/ void main() { gl_FragData[0] = vec4(1.0); }",
                           "/*{}*/\nlayout(location = 0) out vec4 result;\nvoid main() { result = vec4(TIME); }"}) {
    const CompiledIsf compiled = compileIsf(parseDocument(text, "out.fs"));
    EXPECT_GT(compiled.fragment.size(), 5u) << text;
  }
  const Translation own = translate(parseDocument("/*{}*/\nlayout(location = 0) out vec4 result;\nvoid main() {}", "o.fs"));
  EXPECT_NE(own.fragment.find("\nlayout(location = 0) out vec4 result;\n"), std::string::npos);
  EXPECT_EQ(own.fragment.find("out vec4 isf_FragColor"), std::string::npos);
}

TEST(IsfCompile, AVertexFileThatIsNotTextIsRefusedAtItsLine) {
  const auto dir = std::filesystem::temp_directory_path() / ("vitrine-isf-vs-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "a.fs") << "/*{}*/ void main() { gl_FragColor = vec4(1.0); }\n";
  std::ofstream(dir / "a.vs", std::ios::binary) << "void main() {\n  isf_vertShaderInit(); // caf\xe9\n}\n";
  try {
    loadVertexFile(dir / "a.fs");
    ADD_FAILURE() << "accepted";
  } catch (const IsfError& e) {
    EXPECT_EQ(e.file, (dir / "a.vs").string());
    EXPECT_EQ(e.line, 2);
  }
  EXPECT_FALSE(loadVertexFile(dir / "none.fs").has_value());
  std::filesystem::remove_all(dir);
}

TEST(IsfCompile, ADeclarationOverSeveralLinesKeepsTheLinesAfterIt) {
  // The rewrite writes a varying's declaration again with its location; the newlines it spanned,
  // between the type and the name too, must follow it, or every later line is reported one short.
  const Document doc = parseDocument("/*{}*/\nflat in\n  mat3\n  m;\nvoid main() { gl_FragColor = vec4(m[0], 1.0); }\n", "m.fs");
  try {
    compileIsf(doc, VertexFile{"flat out\n  mat3\n  m;\nvoid main() {\n  isf_vertShaderInit(); m = mat3(1.0) * missing;\n}\n", "m.vs"});
    FAIL() << "compiled";
  } catch (const IsfError& e) {
    EXPECT_EQ(e.file, "m.vs");
    EXPECT_EQ(e.line, 5) << e.what();
  }
}

TEST(IsfCompile, MapsGlslangsLogOntoTheFiles) {
  const auto lines = mappedLog("ERROR: 1:12: 'x' : undeclared identifier\nERROR: 1:12: '' : compilation terminated\n"
                               "WARNING: 2:3: 'y' : something\nERROR: 2 compilation errors.  No code generated.\n",
                               {"<gen>", "a.fs", "a.vs"});
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "a.fs:12: error: 'x' : undeclared identifier");
  EXPECT_EQ(lines[1], "a.vs:3: warning: 'y' : something");
}

}  // namespace
}  // namespace vitrine::isf

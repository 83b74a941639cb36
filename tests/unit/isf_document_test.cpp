// ISF files read into documents: every input type, passes and their sizes, the kinds, and the hostile
// files each refused with the line of the file that is wrong.
#include "isf/isf_document.h"

#include "isf_test_files.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <unistd.h>

namespace vitrine::isf {
namespace {

using test::isfFile;

TEST(IsfDocument, ReadsEveryInputType) {
  const Document doc = loadDocument(isfFile("every_input.fs"));
  EXPECT_EQ(doc.kind, Kind::Generator);  // an image input not named inputImage makes no filter
  EXPECT_EQ(doc.isfVersion, "2.0");
  EXPECT_EQ(doc.vsn, "1.0");
  EXPECT_EQ(doc.credit, "Vitrine tests");
  EXPECT_EQ(doc.categories, (std::vector<std::string>{"Test", "Generator"}));
  ASSERT_EQ(doc.inputs.size(), 9u);
  const InputType types[] = {InputType::Event, InputType::Bool,  InputType::Long,  InputType::Float,   InputType::Point2D,
                             InputType::Color, InputType::Image, InputType::Audio, InputType::AudioFFT};
  for (size_t i = 0; i < 9; ++i) EXPECT_EQ(doc.inputs[i].type, types[i]) << doc.inputs[i].name;
  EXPECT_EQ(doc.inputs[0].label, "Flash");
  EXPECT_EQ(doc.inputs[0].line, 8);
  const Input& bands = doc.inputs[2];
  EXPECT_EQ(bands.values, (std::vector<int>{2, 4, 8}));
  EXPECT_EQ(bands.labels, (std::vector<std::string>{"two", "four", "eight"}));
  EXPECT_EQ(bands.defaultValue[0], 4);
  EXPECT_TRUE(bands.hasIdentity);
  const Input& speed = doc.inputs[3];
  EXPECT_TRUE(speed.hasMin && speed.hasMax);
  EXPECT_EQ(speed.maxValue[0], 4.0);
  EXPECT_EQ(speed.defaultValue[0], 1.0);
  EXPECT_EQ(doc.inputs[4].defaultValue[1], 0.5);
  EXPECT_EQ(doc.inputs[5].defaultValue[1], 0.6);
  EXPECT_EQ(doc.inputs[7].audioSamples, 256);
  EXPECT_EQ(doc.inputs[8].audioSamples, 64);
  ASSERT_EQ(doc.passes.size(), 1u);  // no PASSES: one pass to the output
  EXPECT_TRUE(doc.passes[0].target.empty());
  EXPECT_EQ(doc.glslFirstLine, 18);  // the line of "}*/"
  EXPECT_EQ(doc.glsl.substr(0, 2), "\n\n");
}

TEST(IsfDocument, TellsGeneratorsFiltersAndTransitionsApart) {
  EXPECT_EQ(loadDocument(isfFile("gles_style.fs")).kind, Kind::Filter);
  EXPECT_EQ(loadDocument(isfFile("transition.fs")).kind, Kind::Transition);
  EXPECT_EQ(loadDocument(isfFile("audio.fs")).kind, Kind::Generator);
}

TEST(IsfDocument, PassesTheirBuffersAndSizes) {
  const Document doc = loadDocument(isfFile("multipass.fs"));
  ASSERT_EQ(doc.passes.size(), 3u);
  EXPECT_EQ(doc.passes[0].target, "small");
  EXPECT_FALSE(doc.passes[0].persistent);
  EXPECT_TRUE(doc.passes[1].persistent);
  EXPECT_TRUE(doc.passes[1].floatTarget);
  EXPECT_TRUE(doc.passes[2].target.empty());
  ASSERT_EQ(doc.targets().size(), 2u);

  const auto sizes = passSizes(doc, 1920, 1080);
  EXPECT_EQ(sizes[0].width, 960);
  EXPECT_EQ(sizes[0].height, 541);
  EXPECT_EQ(sizes[1].width, 1920);  // max($WIDTH, 12 * 10)
  EXPECT_EQ(sizes[2].width, 1920);
  // An input's value changes a size; one out of bounds is clamped with a note, not refused.
  std::vector<std::string> notes;
  const auto wide = passSizes(doc, 1920, 1080, [](std::string_view name) -> std::optional<double> {
    return name == "blurAmount" ? std::optional<double>(1e6) : std::nullopt;
  }, &notes);
  EXPECT_EQ(wide[1].width, kMaxTargetSide);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("multipass.fs:"), std::string::npos);
  EXPECT_NE(notes[0].find("lowered to 16384"), std::string::npos);
}

TEST(IsfDocument, SaysWhatEachPassReadsFromEachBuffer) {
  const Document doc = loadDocument(isfFile("multipass.fs"));
  EXPECT_EQ(readOf(doc, 1, "small"), PassRead::EarlierPass);
  EXPECT_EQ(readOf(doc, 0, "small"), PassRead::Cleared);        // drawn later in the frame
  EXPECT_EQ(readOf(doc, 0, "trail"), PassRead::PreviousFrame);  // persistent
  EXPECT_EQ(readOf(doc, 1, "trail"), PassRead::PreviousFrame);  // its own pass reads last frame's
  EXPECT_EQ(readOf(doc, 2, "trail"), PassRead::EarlierPass);
  EXPECT_EQ(readOf(doc, 2, "inputImage"), PassRead::NotATarget);
}

TEST(IsfDocument, ImportedImagesInBothForms) {
  const Document object = loadDocument(isfFile("imported.fs"));
  ASSERT_EQ(object.imported.size(), 1u);
  EXPECT_EQ(object.imported[0].name, "stamp");
  EXPECT_EQ(object.imported[0].path, "stamp.png");
  const Document array = parseDocument(R"(/*{ "IMPORTED": [ {"NAME": "a", "PATH": "a.png"},
                                              {"NAME": "b", "PATH": "../b.jpg"} ] }*/ void main() {})", "array.fs");
  ASSERT_EQ(array.imported.size(), 2u);
  EXPECT_EQ(array.imported[1].name, "b");
  EXPECT_EQ(array.imported[1].line, 2);
  EXPECT_EQ(array.isfVersion, "1");  // no ISFVSN: the first version
}

TEST(IsfDocument, ALongInputFromMinAndMax) {
  const Document doc = loadDocument(isfFile("gl3_style.fs"));
  EXPECT_EQ(doc.inputs[0].values.size(), 12u);
  EXPECT_EQ(doc.inputs[0].labels[0], "1");
  EXPECT_EQ(doc.inputs[0].defaultValue[0], 6);
  EXPECT_EQ(doc.inputs[1].defaultValue[3], 1.0);  // a 3-entry colour is opaque
}

struct Hostile {
  const char* file;
  int line;
  const char* says;
};

class IsfHostile : public testing::TestWithParam<Hostile> {};

TEST_P(IsfHostile, IsRefusedAtItsLineWithTheReason) {
  const Hostile& h = GetParam();
  try {
    loadDocument(isfFile(std::string("hostile/") + h.file));
    FAIL() << h.file << " was accepted";
  } catch (const IsfError& e) {
    EXPECT_EQ(e.line, h.line) << e.what();
    EXPECT_NE(e.why.find(h.says), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(std::string(h.file) + ":" + std::to_string(h.line) + ": "), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Files, IsfHostile,
    testing::Values(Hostile{"broken_json.fs", 4, "does not parse"}, Hostile{"unknown_type.fs", 5, "\"quaternion\""},
                    Hostile{"builtin_name.fs", 4, "ISF declares itself"}, Hostile{"keyword_name.fs", 4, "GLSL keyword"},
                    Hostile{"duplicate_name.fs", 7, "given twice"}, Hostile{"huge_size.fs", 4, "outside 1..16384"},
                    Hostile{"negative_size.fs", 4, "gives -1920 pixels"}, Hostile{"too_much_memory.fs", 4, "at most 1 GiB"},
                    Hostile{"recursion.fs", 4, "no pass can"}, Hostile{"unknown_size_variable.fs", 4, "$b, which is not an input"},
                    Hostile{"no_json.fs", 1, "starts with a /* comment"}, Hostile{"unclosed_comment.fs", 1, "never closed"},
                    Hostile{"non_utf8.fs", 3, "0xE9 is not valid UTF-8"}, Hostile{"deep_json.fs", 3, "deeper than 32"},
                    Hostile{"too_many_inputs.fs", 68, "at most 64"}),
    [](const testing::TestParamInfo<Hostile>& p) {
      std::string name = p.param.file;
      return name.substr(0, name.find('.'));
    });

TEST(IsfDocument, ANulByteIsRefused) {
  const std::string text = std::string("/*{}*/\nvoid main() {}\n") + '\0' + "\n";
  try {
    parseDocument(text, "nul.fs");
    FAIL();
  } catch (const IsfError& e) {
    EXPECT_EQ(e.line, 3);
    EXPECT_NE(e.why.find("NUL"), std::string::npos);
  }
}

TEST(IsfDocument, ATenMegabyteFileIsRefusedBeforeItIsRead) {
  const auto path = std::filesystem::temp_directory_path() / ("vitrine-isf-big-" + std::to_string(getpid()) + ".fs");
  {
    std::ofstream out(path, std::ios::binary);
    out << "/*{}*/\n";
    out.seekp(10 * 1024 * 1024);  // sparse: the size is what is refused, not the bytes
    out << '\n';
  }
  try {
    loadDocument(path);
    ADD_FAILURE() << "accepted";
  } catch (const IsfError& e) {
    EXPECT_EQ(e.line, 1);
    EXPECT_NE(e.why.find("1 MiB"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

TEST(IsfDocument, SemanticMistakesNameTheirLine) {
  auto line = [](const std::string& text) {
    try {
      parseDocument(text, "t.fs");
    } catch (const IsfError& e) {
      return e.line;
    }
    return 0;
  };
  EXPECT_EQ(line("/*{\n\"INPUTS\": [\n{\"NAME\": \"a\", \"TYPE\": \"long\",\n \"VALUES\": [1, 2],\n \"LABELS\": [\"x\"]}]}*/"), 5);
  EXPECT_EQ(line("/*{\n\"INPUTS\": [{\"NAME\": \"f\", \"TYPE\": \"float\",\n\"MIN\": 2, \"MAX\": 1}]}*/ void main(){}"), 3);
  EXPECT_EQ(line("/*{\"PASSES\": [{},\n{\"PERSISTENT\": true}]}*/ void main(){}"), 2);
  EXPECT_EQ(line("/*{\"INPUTS\": [{\"NAME\": \"a\", \"TYPE\": \"audio\",\n\"MAX\": 100000}]}*/ void main(){}"), 2);
  EXPECT_EQ(line("/*{\"INPUTS\": [{\"NAME\": \"bad name\", \"TYPE\": \"bool\"}]}*/ void main(){}"), 1);
  EXPECT_EQ(line("/*{\"PERSISTENT_BUFFERS\": []}*/ void main(){}"), 1);
  EXPECT_EQ(line("/*[1, 2]*/ void main(){}"), 1);
  // A number past a double's range is the JSON library's out_of_range, not a parse error.
  EXPECT_EQ(line("/*{\n\"INPUTS\": [{\"NAME\": \"f\", \"TYPE\": \"float\",\n \"MAX\": 1E999}]}*/ void main(){}"), 3);
}

}  // namespace
}  // namespace vitrine::isf

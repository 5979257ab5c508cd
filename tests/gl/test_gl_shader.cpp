// Shader loading: #include expansion (nested, once-only, cycles), #define variants, and
// compile errors reported with the file and line where the mistake is.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "pipelines/gl/context.h"
#include "pipelines/gl/framebuffer.h"
#include "pipelines/gl/program.h"
#include "pipelines/gl/shader_source.h"

namespace fs = std::filesystem;
using mb::gl::expandShaderFile;
using mb::gl::Program;

namespace {

// A scratch folder of shader files, removed at the end of the test.
struct ShaderDir {
  fs::path dir;
  ShaderDir() {
    dir = fs::temp_directory_path() /
          ("mb_shader_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
           "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir / "lib");
  }
  ~ShaderDir() { fs::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  }
};

const char* kFullscreenVs =
    "#version 450 core\n"
    "void main() {\n"
    "  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
    "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n";

// Draws a fullscreen triangle with `program` into a w x h framebuffer; returns top-down RGBA.
std::vector<uint8_t> drawFullscreen(const Program& program, int w, int h) {
  auto fb = mb::gl::Framebuffer::create(w, h);
  EXPECT_TRUE(fb) << fb.error();
  (*fb)->clear(0, 0, 0, 1);
  GLuint vao = 0;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  program.use();
  glDisable(GL_DEPTH_TEST);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<uint8_t> px = (*fb)->readRgba();
  glBindVertexArray(0);
  glDeleteVertexArrays(1, &vao);
  return px;
}

}  // namespace

TEST(ShaderSource, IncludesExpandOnceWithDefinesAfterVersion) {
  ShaderDir d;
  d.write("lib/b.glsl", "float b() { return 2.0; }\n");
  d.write("lib/a.glsl", "#include \"b.glsl\"\nfloat a() { return b(); }\n");
  std::string top = d.write("top.fs", "// comment\n#version 450 core\n#include \"lib/a.glsl\"\n"
                                      "#include \"lib/b.glsl\"\nvoid main() {}\n");
  auto src = expandShaderFile(top, {{"VARIANT", "3"}, {"FLAG", ""}});
  ASSERT_TRUE(src) << src.error();
  ASSERT_EQ(src->files.size(), 3u);
  EXPECT_NE(src->files[1].find("a.glsl"), std::string::npos);
  EXPECT_NE(src->files[2].find("b.glsl"), std::string::npos);
  const std::string& t = src->text;
  size_t version = t.find("#version 450 core\n");
  size_t define = t.find("#define VARIANT 3\n#define FLAG\n");
  ASSERT_NE(version, std::string::npos);
  ASSERT_NE(define, std::string::npos);
  EXPECT_LT(version, define);
  EXPECT_NE(t.find("#line 3 0\n"), std::string::npos);  // top file resumes after #version
  EXPECT_NE(t.find("#line 1 1\n"), std::string::npos);  // a.glsl
  EXPECT_NE(t.find("#line 1 2\n"), std::string::npos);  // b.glsl (from a.glsl)
  EXPECT_NE(t.find("#line 2 1\n"), std::string::npos);  // back in a.glsl
  EXPECT_NE(t.find("#line 4 0\n"), std::string::npos);  // back in top
  // b.glsl appears once although included twice.
  EXPECT_EQ(t.find("float b()"), t.rfind("float b()"));
}

TEST(ShaderSource, IncludeCycleIsAnErrorNamingFileAndLine) {
  ShaderDir d;
  d.write("x.glsl", "#include \"y.glsl\"\n");
  d.write("y.glsl", "\n#include \"x.glsl\"\n");
  std::string top = d.write("top.vs", "#version 450 core\n#include \"x.glsl\"\n");
  auto src = expandShaderFile(top);
  ASSERT_FALSE(src);
  EXPECT_NE(src.error().find("y.glsl:2"), std::string::npos) << src.error();
  EXPECT_NE(src.error().find("cycle"), std::string::npos) << src.error();
}

TEST(ShaderSource, MissingIncludeAndMissingVersion) {
  ShaderDir d;
  std::string top = d.write("top.vs", "#version 450 core\n\n#include \"nope.glsl\"\n");
  auto src = expandShaderFile(top);
  ASSERT_FALSE(src);
  EXPECT_NE(src.error().find("top.vs:3"), std::string::npos) << src.error();
  EXPECT_NE(src.error().find("nope.glsl"), std::string::npos) << src.error();
  std::string noVersion = d.write("bad.vs", "void main() {}\n");
  auto bad = expandShaderFile(noVersion);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("bad.vs:1"), std::string::npos) << bad.error();
  auto missing = expandShaderFile((d.dir / "absent.vs").string());
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("absent.vs"), std::string::npos);
}

TEST(ShaderSource, MapLogRewritesMesaAndNvidiaPositions) {
  std::vector<std::string> files = {"/s/top.fs", "/s/inc.glsl"};
  std::string mesa = mb::gl::mapLog("1:7(12): error: `x' undeclared\nplain line", files);
  EXPECT_EQ(mesa, "/s/inc.glsl:7:12: error: `x' undeclared\nplain line\n");
  std::string nv = mb::gl::mapLog("0(3) : error C1008: undefined variable", files);
  EXPECT_EQ(nv, "/s/top.fs:3: error C1008: undefined variable\n");
  EXPECT_EQ(mb::gl::mapLog("9:1(1): error: far", files), "9:1(1): error: far\n");
}

TEST(ShaderProgram, CompileErrorInIncludedFileNamesThatFileAndLine) {
  ASSERT_TRUE(mb::gl::sharedContext());
  ShaderDir d;
  d.write("ok.glsl", "float ok() { return 1.0; }\n");
  d.write("broken.glsl", "// line 1\nfloat f() {\n  return undeclaredThing;\n}\n");
  std::string vs = d.write("v.vs", kFullscreenVs);
  std::string fs = d.write("f.fs",
                           "#version 450 core\n#include \"ok.glsl\"\n#include \"broken.glsl\"\n"
                           "out vec4 c;\nvoid main() { c = vec4(f()); }\n");
  auto p = Program::fromFiles(vs, fs);
  ASSERT_FALSE(p);
  EXPECT_NE(p.error().find("broken.glsl:3"), std::string::npos) << p.error();
  EXPECT_NE(p.error().find("undeclaredThing"), std::string::npos) << p.error();
}

TEST(ShaderProgram, CompileErrorInTopFileAfterIncludesAndDefines) {
  ASSERT_TRUE(mb::gl::sharedContext());
  ShaderDir d;
  d.write("two.glsl", "float one() { return 1.0; }\nfloat two() { return 2.0; }\n");
  std::string vs = d.write("v.vs", kFullscreenVs);
  std::string fs = d.write("f.fs",
                           "#version 450 core\n#include \"two.glsl\"\nout vec4 c;\n"
                           "void main() {\n  c = vec4(two()) + oops;\n}\n");
  auto p = Program::fromFiles(vs, fs, {{"A", "1"}, {"B", "2"}});
  ASSERT_FALSE(p);
  EXPECT_NE(p.error().find("f.fs:5"), std::string::npos) << p.error();
}

TEST(ShaderProgram, DefinesSelectVariantsAndReadbackIsTopDown) {
  ASSERT_TRUE(mb::gl::sharedContext());
  ShaderDir d;
  std::string vs = d.write("v.vs", kFullscreenVs);
  std::string fs = d.write("f.fs",
                           "#version 450 core\nout vec4 c;\nuniform float u_height;\n"
                           "void main() {\n"
                           "  bool top = gl_FragCoord.y > 0.5 * u_height;\n"
                           "#ifdef GREEN\n  c = vec4(0, 1, 0, 1);\n#else\n"
                           "  c = top ? vec4(1, 0, 0, 1) : vec4(0, 0, 1, 1);\n#endif\n}\n");
  auto plain = Program::fromFiles(vs, fs);
  ASSERT_TRUE(plain) << plain.error();
  (*plain)->use();
  glUniform1f((*plain)->uniform("u_height"), 8.0f);
  std::vector<uint8_t> px = drawFullscreen(**plain, 4, 8);
  EXPECT_EQ(px[0], 255);                  // row 0 (top of the image) is red...
  EXPECT_EQ(px[2], 0);
  EXPECT_EQ(px[7 * 4 * 4 + 2], 255);      // ...and the bottom row is blue
  auto green = Program::fromFiles(vs, fs, {{"GREEN", ""}});
  ASSERT_TRUE(green) << green.error();
  std::vector<uint8_t> g = drawFullscreen(**green, 4, 8);
  EXPECT_EQ(g[1], 255);
  EXPECT_EQ(g[0], 0);
}

TEST(ShaderProgram, RepositoryShadersCompile) {
  ASSERT_TRUE(mb::gl::sharedContext());
  ShaderDir d;
  std::string vs = d.write("passthrough.vs",
                           "#version 450 core\nout vec3 v_worldPosition;\nout vec3 v_worldNormal;\n"
                           "out vec4 v_worldTangent;\nout vec2 v_uv0;\nout vec2 v_uv1;\n"
                           "out vec4 v_color;\nvoid main() {\n  v_worldPosition = vec3(0);\n"
                           "  v_worldNormal = vec3(0, 0, 1);\n  v_worldTangent = vec4(1, 0, 0, 1);\n"
                           "  v_uv0 = vec2(0);\n  v_uv1 = vec2(0);\n  v_color = vec4(1);\n"
                           "  gl_Position = vec4(0, 0, 0, 1);\n}\n");
  auto p = Program::fromFiles(vs, "forward.fs");
  ASSERT_TRUE(p) << p.error();
  EXPECT_GE((*p)->uniform("u_BaseColorFactor"), 0);
  EXPECT_GE((*p)->uniform("u_NormalUV"), 0);
}

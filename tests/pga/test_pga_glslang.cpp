// shaders/pga.glsl is valid GLSL 4.50: compiled inside a minimal vertex shader with
// glslangValidator (skipped when the build found none: MB_GLSLANG_VALIDATOR empty).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs a command, returns its exit status and combined output.
int run(const std::string& cmd, std::string& out) {
  FILE* p = popen((cmd + " 2>&1").c_str(), "r");
  if (!p) return -1;
  char buf[512];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  const int st = pclose(p);
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

}  // namespace

TEST(PgaGlslang, ToolboxCompilesInAVertexShader) {
  const std::string validator = MB_GLSLANG_VALIDATOR;
  if (validator.empty()) GTEST_SKIP() << "glslangValidator not found at configure time";
  const std::string pga = readFile(std::string(MB_SOURCE_DIR) + "/shaders/pga.glsl");
  ASSERT_FALSE(pga.empty());
  // Every function is used, so that a compiler that only checks reachable code checks all.
  const std::string src = "#version 450\n" + pga + R"(
layout(location = 0) in vec4 a0;
layout(location = 1) in vec4 a1;
layout(location = 2) in vec3 pos;
layout(location = 0) out vec3 o0;
layout(location = 1) out vec3 o1;
void main() {
  motor m = motor(a0, a1);
  motor r = motor(a0, vec4(0.0));
  motor t = motor(vec4(1.0, 0.0, 0.0, 0.0), a1);
  motor x = gp_mm(m, gp_rr(r, r));
  x = gp_mm(x, gp_tt(t, t)); x = gp_mm(x, gp_rt(r, t)); x = gp_mm(x, gp_tr(t, r));
  x = gp_mm(x, gp_rm(r, m)); x = gp_mm(x, gp_mr(m, r)); x = gp_mm(x, gp_tm(t, m));
  x = gp_mm(x, gp_mt(m, t)); x = gp_mm(x, gp_vv(pos, a0.xyz)); x = gp_mm(x, reverse_m(m));
  x = gp_mm(normalize_m(x), sqrt_m(m));
  line B = log_m(x);
  x = gp_mm(x, exp_b(B)); x = gp_mm(x, exp_r(0.5, B)); x = gp_mm(x, exp_t(0.5, B));
  mat2x3 nt = extractNormalTangent(x);
  o0 = sw_mp(x, pos) + sw_mp_naive(x, pos) + sw_md(x, pos) + sw_mo(x) + nt[0];
  o1 = sw_mx(x) + sw_my(x) + sw_mz(x) + nt[1];
  gl_Position = project(0.04, 400.0, 0.45, 1.5, o0);
}
)";
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("mb_pga_glslang_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "pga_wrapper.vert";
  std::ofstream(file) << src;
  std::string out;
  const int rc = run("\"" + validator + "\" \"" + file.string() + "\"", out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_EQ(out.find("WARNING"), std::string::npos) << out;
  // And to SPIR-V for OpenGL (what a SPIR-V op count would read).
  out.clear();
  const int rc2 = run("\"" + validator + "\" -G -o \"" + (dir / "pga.spv").string() + "\" \"" +
                          file.string() + "\"", out);
  EXPECT_EQ(rc2, 0) << out;
  std::filesystem::remove_all(dir);
}

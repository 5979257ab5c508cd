// Device selection (--gpu / MB_GPU): parsing, the software rule, and the EGL device platform
// through Mesa's own software device (the path a real GPU takes: eglQueryDevicesEXT, then
// eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT)), which CI has without a GPU.
#include <gtest/gtest.h>

#include <cstdlib>

#include "pipelines/gl/context.h"
#include "pipelines/gl/egl_devices.h"
#include "pipelines/gl/gl_api.h"
#include "pipelines/gl/gpu_choice.h"

namespace {

using mb::gl::GpuChoice;

TEST(GpuChoice, ParsesTheThreeForms) {
  EXPECT_EQ(mb::gl::parseGpuChoice("", "--gpu")->kind, GpuChoice::Kind::Auto);
  EXPECT_EQ(mb::gl::parseGpuChoice("auto", "--gpu")->kind, GpuChoice::Kind::Auto);
  EXPECT_EQ(mb::gl::parseGpuChoice("llvmpipe", "--gpu")->kind, GpuChoice::Kind::Llvmpipe);
  auto three = mb::gl::parseGpuChoice("3", "--gpu");
  ASSERT_TRUE(three);
  EXPECT_EQ(three->kind, GpuChoice::Kind::Device);
  EXPECT_EQ(three->index, 3);
  EXPECT_EQ(three->text(), "3");
}

TEST(GpuChoice, RejectsOtherValuesNamingThem) {
  for (const char* bad : {"-1", "gpu0", "1.5", "256", "nvidia", " 0"}) {
    auto c = mb::gl::parseGpuChoice(bad, "MB_GPU");
    ASSERT_FALSE(c) << bad;
    EXPECT_NE(c.error().find(std::string("MB_GPU ") + bad), std::string::npos) << c.error();
    EXPECT_NE(c.error().find("auto, llvmpipe"), std::string::npos) << c.error();
  }
}

TEST(GpuChoice, SoftwareRule) {
  EXPECT_TRUE(mb::gl::isSoftwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_TRUE(mb::gl::isSoftwareRenderer("softpipe"));
  EXPECT_FALSE(mb::gl::isSoftwareRenderer("NVIDIA H100 80GB HBM3/PCIe/SSE2"));
  EXPECT_FALSE(mb::gl::isSoftwareRenderer("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.6, DRM 3.54)"));
}

TEST(EglDevices, DescribeNamesIndexKindNodeAndName) {
  mb::gl::EglDevice sw, hw;
  sw.index = 0;
  hw.index = 1, hw.software = false, hw.drm = "/dev/dri/renderD128", hw.name = "NVIDIA H100";
  EXPECT_EQ(mb::gl::describeEglDevices({sw, hw}),
            "0 software (Mesa llvmpipe); 1 hardware /dev/dri/renderD128 (NVIDIA H100)");
  EXPECT_EQ(mb::gl::describeEglDevices({}), "none");
}

// Mesa lists its software device on the device platform (EGL_MESA_device_software).
TEST(EglDevices, MesaListsASoftwareDevice) {
  std::string why;
  const auto devices = mb::gl::listEglDevices(&why);
  ASSERT_FALSE(devices.empty()) << why;
  bool software = false;
  for (const auto& d : devices) software = software || d.software;
  EXPECT_TRUE(software) << mb::gl::describeEglDevices(devices);
}

TEST(EglDevices, MissingIndexListsTheDevicesSeen) {
  GpuChoice c;
  c.kind = GpuChoice::Kind::Device, c.index = 200;
  auto d = mb::gl::findEglDevice(c);
  ASSERT_FALSE(d);
  EXPECT_NE(d.error().find("GPU 200"), std::string::npos) << d.error();
  EXPECT_NE(d.error().find("devices seen: 0 "), std::string::npos) << d.error();
}

// MB_GPU=N opens a GL 4.5 core context on EGL device N, here Mesa's software device, and
// records it; realGpu stays false.
TEST(GlContextOnDevice, SoftwareDeviceGivesAGl45CoreContext) {
  std::string why;
  const auto devices = mb::gl::listEglDevices(&why);
  int index = -1;
  for (const auto& d : devices)
    if (d.software && index < 0) index = d.index;
  ASSERT_GE(index, 0) << mb::gl::describeEglDevices(devices);
  setenv("MB_GPU", std::to_string(index).c_str(), 1);
  auto ctx = mb::gl::Context::create();
  unsetenv("MB_GPU");
  ASSERT_TRUE(ctx) << ctx.error();
  const mb::gl::ContextInfo& info = (*ctx)->info();
  EXPECT_EQ(info.backend, "egl-device " + std::to_string(index));
  EXPECT_EQ(info.deviceIndex, index);
  EXPECT_TRUE(info.deviceSoftware);
  EXPECT_FALSE(info.realGpu());
  EXPECT_NE(info.renderer.find("llvmpipe"), std::string::npos) << info.renderer;
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 45);
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
  EXPECT_EQ(info.deviceText(), "egl-device " + std::to_string(index) + ", software");
}

TEST(GlContextOnDevice, AbsentDeviceIsAnErrorListingTheDevices) {
  setenv("MB_GPU", "200", 1);
  auto ctx = mb::gl::Context::create();
  unsetenv("MB_GPU");
  ASSERT_FALSE(ctx);
  EXPECT_NE(ctx.error().find("no such EGL device; devices seen:"), std::string::npos) << ctx.error();
}

TEST(GlContextOnDevice, LlvmpipeChoiceIsSurfacelessSoftware) {
  setenv("MB_GPU", "llvmpipe", 1);
  auto ctx = mb::gl::Context::create();
  unsetenv("MB_GPU");
  ASSERT_TRUE(ctx) << ctx.error();
  EXPECT_TRUE((*ctx)->info().backend == "egl-surfaceless" || (*ctx)->info().backend == "osmesa");
  EXPECT_NE((*ctx)->info().renderer.find("llvmpipe"), std::string::npos);
  EXPECT_EQ((*ctx)->info().deviceIndex, -1);
}

}  // namespace

#include "harness/render/image_metrics.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace mb {
namespace {

// Wraps the bytes without copying (OpenImageIO reads them through the spec).
OIIO::ImageBuf wrap(const RgbaImage& img) {
  OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::UINT8);
  return OIIO::ImageBuf(spec, const_cast<uint8_t*>(img.rgba.data()));
}

std::string sizeText(const RgbaImage& img) {
  return std::to_string(img.width) + "x" + std::to_string(img.height);
}

bool sameSize(const RgbaImage& a, const RgbaImage& b) {
  return a.width == b.width && a.height == b.height && a.width > 0 && a.height > 0 &&
         a.rgba.size() == size_t(a.width) * size_t(a.height) * 4 && b.rgba.size() == a.rgba.size();
}

// Pixels with some channel difference above `threshold` (OpenImageIO counts per pixel).
OIIO::ImageBufAlgo::CompareResults compareAt(const RgbaImage& a, const RgbaImage& b,
                                             double threshold) {
  OIIO::ImageBuf ia = wrap(a), ib = wrap(b);
  return OIIO::ImageBufAlgo::compare(ia, ib, float(threshold), float(threshold));
}

}  // namespace

Status writeImage(const std::string& path, const RgbaImage& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != size_t(image.width) * size_t(image.height) * 4)
    return Status::fail(path + ": image data does not match " + sizeText(image) + " RGBA8");
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return Status::fail(path + ": no image writer for this file type (" + OIIO::geterror() + ")");
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
  if (!out->open(path, spec)) return Status::fail(path + ": cannot open for writing: " + out->geterror());
  bool ok = out->write_image(OIIO::TypeDesc::UINT8, image.rgba.data());
  ok = out->close() && ok;
  if (!ok) return Status::fail(path + ": write failed: " + out->geterror());
  return {};
}

Status writeAnimation(const std::string& path, const std::vector<RgbaImage>& frames, int fps) {
  if (frames.empty()) return Status::fail(path + ": no frames");
  const int w = frames[0].width, h = frames[0].height;
  for (const RgbaImage& f : frames)
    if (f.width != w || f.height != h || f.rgba.size() != size_t(w) * size_t(h) * 4)
      return Status::fail(path + ": frames differ in size or do not match their RGBA8 data");
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return Status::fail(path + ": no image writer for this file type (" + OIIO::geterror() + ")");
  if (!out->supports("multiimage") || !out->supports("appendsubimage"))
    return Status::fail(path + ": this file type holds no animation (use .gif)");
  OIIO::ImageSpec spec(w, h, 4, OIIO::TypeDesc::UINT8);
  const int rate[2] = {fps, 1};
  spec.attribute("FramesPerSecond", OIIO::TypeRational, rate);
  spec.attribute("oiio:LoopCount", 0);  // loop forever
  std::vector<OIIO::ImageSpec> specs(frames.size(), spec);
  bool ok = out->open(path, int(specs.size()), specs.data());
  for (size_t i = 0; ok && i < frames.size(); ++i) {
    if (i > 0) ok = out->open(path, spec, OIIO::ImageOutput::AppendSubimage);
    ok = ok && out->write_image(OIIO::TypeDesc::UINT8, frames[i].rgba.data());
  }
  ok = out->close() && ok;
  if (!ok) return Status::fail(path + ": write failed: " + out->geterror());
  return {};
}

Result<RgbaImage> readImage(const std::string& path, ImageFileInfo* info) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return Result<RgbaImage>::fail(path + ": cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (info) *info = {spec.nchannels, spec.format.c_str()};
  int channels = spec.nchannels;
  std::vector<uint8_t> raw(size_t(spec.width) * size_t(spec.height) * size_t(channels));
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, raw.data()))
    return Result<RgbaImage>::fail(path + ": decode failed: " + in->geterror());
  RgbaImage img{spec.width, spec.height, {}};
  img.rgba.resize(size_t(spec.width) * size_t(spec.height) * 4);
  for (size_t p = 0; p < size_t(spec.width) * size_t(spec.height); ++p)
    for (int c = 0; c < 4; ++c) {
      int from = channels >= 3 ? c : (c < 3 ? 0 : 1);  // grey(+alpha) -> RGBA
      img.rgba[p * 4 + size_t(c)] =
          from < channels ? raw[p * size_t(channels) + size_t(from)] : uint8_t(255);
    }
  return img;
}

Result<ImageMetrics> compareImages(const RgbaImage& a, const RgbaImage& b) {
  if (!sameSize(a, b))
    return Result<ImageMetrics>::fail("cannot compare images of different sizes (" +
                                      sizeText(a) + " vs " + sizeText(b) + ")");
  // Thresholds sit half a byte step above k/255 so a difference of exactly k steps is not
  // "over k/255" despite float rounding.
  auto over = [&](int k) { return compareAt(a, b, (k + 0.5) / 255.0); };
  OIIO::ImageBufAlgo::CompareResults r1 = over(1);
  ImageMetrics m;
  m.width = a.width;
  m.height = a.height;
  const double pixels = double(a.width) * double(a.height);
  m.meanError = r1.meanerror;
  m.rmse = r1.rms_error;
  m.psnr = m.rmse > 0 ? 20.0 * std::log10(1.0 / m.rmse) : std::numeric_limits<double>::infinity();
  m.maxError = r1.maxerror;
  m.maxX = r1.maxx;
  m.maxY = r1.maxy;
  m.maxChannel = r1.maxc;
  m.fractionOver1 = double(r1.nfail) / pixels;
  m.fractionOver2 = double(over(2).nfail) / pixels;
  m.fractionOver4 = double(over(4).nfail) / pixels;
  return m;
}

std::vector<std::string> differenceLines(const ImageMetrics& m) {
  if (m.rmse == 0.0) return {"identical: every byte of the two images agrees"};
  char b[3][256];
  std::snprintf(b[0], sizeof b[0], "PSNR %.2f dB; RMSE %s; mean error %s", m.psnr, differenceText(m.rmse).c_str(),
                differenceText(m.meanError).c_str());
  static const char* const kChannel[] = {"R", "G", "B", "A"};
  std::snprintf(b[1], sizeof b[1], "max error %s at (%d,%d) channel %s", differenceText(m.maxError).c_str(), m.maxX,
                m.maxY, kChannel[std::clamp(m.maxChannel, 0, 3)]);
  std::snprintf(b[2], sizeof b[2], "pixels off by more than 1/255: %.3f %%, 2/255: %.3f %%, 4/255: %.3f %%",
                100 * m.fractionOver1, 100 * m.fractionOver2, 100 * m.fractionOver4);
  return {b[0], b[1], b[2]};
}

int64_t countPixelsOtherThan(const RgbaImage& image, const std::array<uint8_t, 3>& background) {
  int64_t n = 0;
  for (size_t i = 0; i + 3 < image.rgba.size(); i += 4)
    n += image.rgba[i] != background[0] || image.rgba[i + 1] != background[1] || image.rgba[i + 2] != background[2];
  return n;
}

std::string differenceText(double fraction) {
  char buf[96];
  const double steps = fraction * 255.0;
  if (steps >= 0.5 && std::abs(steps - std::round(steps)) < 1e-4)  // OIIO computes in float
    std::snprintf(buf, sizeof buf, "%.0f/255 (%.4g of full scale)", std::round(steps), fraction);
  else
    std::snprintf(buf, sizeof buf, "%.4g/255 (%.4g of full scale)", steps, fraction);
  return buf;
}

Verdict judge(const RgbaImage& a, const RgbaImage& b, const Thresholds& t) {
  Verdict v;
  if (!sameSize(a, b)) {
    v.failed = true;
    v.failPercent = 100.0;
    v.reason = "image sizes differ (" + sizeText(a) + " vs " + sizeText(b) + ")";
    return v;
  }
  auto r = compareAt(a, b, t.fail);
  const double pixels = double(a.width) * double(a.height);
  v.failPercent = 100.0 * double(r.nfail) / pixels;
  char buf[200];
  if (double(r.nfail) > t.failPercent / 100.0 * pixels) {
    // Below half a byte step --fail means "any difference" (the default when only
    // --failpercent is given).
    const std::string by = t.fail < 0.5 / 255.0 ? "at all" : "by more than " + differenceText(t.fail);
    std::snprintf(buf, sizeof buf, "%.4f%% of pixels differ %s (allowed %g%%)", v.failPercent, by.c_str(),
                  t.failPercent);
    v.failed = true;
    v.reason = buf;
  } else if (r.maxerror > t.hardFail) {
    std::snprintf(buf, sizeof buf, "max error %s exceeds --hardfail %s", differenceText(double(r.maxerror)).c_str(),
                  differenceText(t.hardFail).c_str());
    v.failed = true;
    v.reason = buf;
  }
  return v;
}

std::array<uint8_t, 3> heatColour(int steps) {
  // Colour ramp stops (t = 0..1): black, blue, red, yellow, white.
  static const float ramp[5][3] = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}};
  // d = 1 step maps to 0.25 (blue), 64+ steps to 1 (white).
  const float t = 0.25f + 0.75f * std::min(1.0f, std::log2(float(std::max(1, steps))) / 6.0f);
  const float x = t * 4.0f;
  const int i = std::min(3, int(x));
  const float f = x - float(i);
  std::array<uint8_t, 3> rgb{};
  for (int c = 0; c < 3; ++c)
    rgb[size_t(c)] = uint8_t(std::lround(255.0f * (ramp[i][c] + f * (ramp[i + 1][c] - ramp[i][c]))));
  return rgb;
}

RgbaImage diffHeatmap(const RgbaImage& a, const RgbaImage& b) {
  RgbaImage out{a.width, a.height, std::vector<uint8_t>(a.rgba.size(), 0)};
  if (!sameSize(a, b)) return out;
  for (size_t p = 0; p < a.rgba.size(); p += 4) {
    int d = 0;
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c])));
    uint8_t* o = &out.rgba[p];
    o[3] = 255;
    if (d == 0) {
      int grey = (int(a.rgba[p]) * 2 + int(a.rgba[p + 1]) * 5 + int(a.rgba[p + 2])) / 8;
      o[0] = o[1] = o[2] = uint8_t(grey / 4);
      continue;
    }
    const auto rgb = heatColour(d);
    o[0] = rgb[0], o[1] = rgb[1], o[2] = rgb[2];
  }
  return out;
}

const std::vector<int>& heatLegendSteps() {
  static const std::vector<int> steps = {1, 2, 4, 8, 16, 32, 64};
  return steps;
}

RgbaImage heatLegend(std::string* warning) {
  const int block = 32, labels = 16;
  const auto& steps = heatLegendSteps();
  RgbaImage img{block * int(steps.size()), block + labels, {}};
  img.rgba.resize(size_t(img.width) * size_t(img.height) * 4);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const auto rgb = y < block ? heatColour(steps[size_t(x / block)]) : std::array<uint8_t, 3>{32, 32, 32};
      uint8_t* o = &img.rgba[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
      o[0] = rgb[0], o[1] = rgb[1], o[2] = rgb[2], o[3] = 255;
    }
  // Each block's difference in byte steps (/255) under it, white on dark grey.
  OIIO::ImageBuf buf = wrap(img);
  bool drawn = true;
  for (size_t i = 0; i < steps.size(); ++i) {
    const std::string text = std::to_string(steps[i]) + (i + 1 == steps.size() ? "+" : "");
    drawn = drawn && OIIO::ImageBufAlgo::render_text(buf, int(i) * block + block / 2, img.height - 3, text, 13,
                                                     "DejaVuSans", {1.0f, 1.0f, 1.0f, 1.0f}, OIIO::ImageBufAlgo::TextAlignX::Center);
  }
  if (!drawn && warning)
    *warning = "diff_legend.png: no font for its numbers (" + buf.geterror() + "; install fonts-dejavu-core): colours only";
  return img;
}

nlohmann::json heatLegendJson() {
  nlohmann::json stops = nlohmann::json::array();
  for (int s : heatLegendSteps()) {
    const auto rgb = heatColour(s);
    stops.push_back({{"steps", s}, {"maxError", s / 255.0}, {"rgb", {rgb[0], rgb[1], rgb[2]}}});
  }
  return {{"unchanged", "pixels that agree in every channel show the first image as dim grey (1/4 of its luma)"},
          {"scale", "a changed pixel is coloured by its largest channel difference in byte steps (1/255), on a "
                    "log2 scale: 1 step blue, 2 purple, 4 red, 8 orange, 16 yellow, 32 pale yellow, 64 and more white"},
          {"stops", stops},
          {"image", "diff_legend.png: one 32x32 block per stop, left to right, its steps (/255) written under it"}};
}

Status checkImageOutput(const std::string& path, const std::string& option) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.empty()) return Status::fail(option + ": empty file name");
  if (fs::is_directory(path, ec))
    return Status::fail(option + " " + path + ": is a folder; give a file name such as " +
                        (fs::path(path) / "frame.png").string());
  const std::string ext = fs::path(path).extension().string();
  if (ext.empty() || ext == ".")
    return Status::fail(option + " " + path + ": no file extension; name the image format, e.g. " + path + ".png");
  if (!OIIO::ImageOutput::create(path))
    return Status::fail(option + " " + path + ": '" + ext +
                        "' is not an image format OpenImageIO writes here (use .png)");
  return Status();
}

}  // namespace mb

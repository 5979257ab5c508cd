// Image I/O and image-difference metrics (OpenImageIO), with idiff's pass/fail semantics.
// Pixel values are bytes / 255; a channel difference is |a - b| in those units.
#pragma once
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipelines/result.h"

namespace mb {

struct RgbaImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4, top row first
};

// PNG (or any OpenImageIO format) <-> RGBA8. Errors name the file and the reason. Reading
// converts 1-3 channel images to RGBA (grey replicated, alpha 1).
// `info` (optional) receives what the file held before the conversion: its channel count and
// pixel type ("uint8", "uint16", "half", "float").
struct ImageFileInfo {
  int channels = 0;
  std::string pixelType;
};
Status writeImage(const std::string& path, const RgbaImage& image);
Result<RgbaImage> readImage(const std::string& path, ImageFileInfo* info = nullptr);
// An animated image (GIF through OpenImageIO: one subimage per frame, looping forever) of
// `frames`, all the same size, shown at `fps` frames per second. Errors name the file.
Status writeAnimation(const std::string& path, const std::vector<RgbaImage>& frames, int fps);

struct ImageMetrics {
  int width = 0, height = 0;
  double meanError = 0;  // mean |a - b| over every channel of every pixel (RGBA)
  double rmse = 0;       // sqrt(mean (a - b)^2) over every channel of every pixel
  double psnr = std::numeric_limits<double>::infinity();  // 20 log10(1 / rmse); +inf if equal
  double maxError = 0;   // largest channel difference...
  int maxX = 0, maxY = 0, maxChannel = 0;  // ...and where (first such pixel, x right, y down)
  // Fraction of pixels (0..1) with some channel differing by more than 1, 2, 4 byte steps
  // (difference > 1/255, 2/255, 4/255).
  double fractionOver1 = 0, fractionOver2 = 0, fractionOver4 = 0;
};

// idiff thresholds: a pixel fails when some channel differs by more than `fail`; the images
// fail when more than `failPercent` % of the pixels fail, or any difference exceeds `hardFail`.
struct Thresholds {
  double fail = 1e-6;
  double failPercent = 0.0;
  double hardFail = std::numeric_limits<double>::infinity();
};

struct Verdict {
  bool failed = false;
  double failPercent = 0;  // % of pixels over Thresholds::fail
  std::string reason;      // "" when passed, else which threshold and by how much
};

// Pixels of `image` whose RGB differs from `background` (bytes): the pixels some primitive
// covered, for frames cleared to `background` (render_frame.h: drawnPixels).
int64_t countPixelsOtherThan(const RgbaImage& image, const std::array<uint8_t, 3>& background);

// A channel difference as people read it, in both units: "171/255 (0.671 of full scale)".
std::string differenceText(double fraction);

// Compares two images of the same size (error naming both sizes otherwise).
Result<ImageMetrics> compareImages(const RgbaImage& a, const RgbaImage& b);
// The measured differences for people, one quantity per line (PSNR, RMSE and mean error; the
// largest difference and where; the pixels over 1, 2 and 4 byte steps), every channel
// difference in both units; "identical: ..." alone when every byte agrees.
std::vector<std::string> differenceLines(const ImageMetrics& m);

// Applies idiff semantics to `a` vs `b` (same size, else failed with the reason).
Verdict judge(const RgbaImage& a, const RgbaImage& b, const Thresholds& t);

// A heat map of |a - b| for people: unchanged pixels show `a` as dim grey (for context);
// changed pixels are coloured by their largest channel difference on a log scale: 1 byte
// step blue, 4 steps red, 8 orange, 16 yellow, 64 and more white. An empty image when the
// sizes differ.
RgbaImage diffHeatmap(const RgbaImage& a, const RgbaImage& b);

// The heat map's colour for a largest channel difference of `steps` byte steps (>= 1).
std::array<uint8_t, 3> heatColour(int steps);
// The legend of diffHeatmap: one 32x32 block per stop of heatLegendSteps() (1, 2, 4, ... 64
// steps), left to right, each with its number of steps written in a 16 px strip under it
// ("64+" for the last; `warning` set when no font could be loaded: the colours alone); and the
// same as JSON (what unchanged pixels show, the scale, each stop's steps, maxError and rgb) for
// metrics.json and the report.
const std::vector<int>& heatLegendSteps();
RgbaImage heatLegend(std::string* warning = nullptr);
nlohmann::json heatLegendJson();

// Checks an image path for `option` (e.g. "-o") before anything is rendered: not a folder,
// has an extension, OpenImageIO can write that format. Errors name the option, the path and
// what to write instead.
Status checkImageOutput(const std::string& path, const std::string& option = "-o");

}  // namespace mb

// LDR-FLIP (Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom, Fairchild, "FLIP: A
// Difference Evaluator for Alternating Images", HPG 2020): a perceptual difference of two sRGB
// images as a per-pixel error in [0, 1], written from the paper's math:
//  1. both images to the opponent space YyCxCz (linearised CIELAB: Y = 116 Y/Yn - 16,
//     Cx = 500 (X/Xn - Y/Yn), Cz = 200 (Y/Yn - Z/Zn); white = linear RGB (1,1,1));
//  2. each channel filtered by its contrast sensitivity function, a sum of Gaussians in
//     degrees of visual angle, sum(a sqrt(pi/b) exp(-pi^2 r^2 / b)), normalised to sum 1;
//  3. back to linear RGB (clamped to [0,1]), to CIELAB, Hunt-adjusted (a, b scaled by L/100),
//     the HyAB distance |dL| + |d(a,b)|, raised to qc = 0.7 and mapped to [0,1] (values under
//     pc = 0.4 of the green-blue maximum to [0, pt = 0.95], the rest to [0.95, 1]);
//  4. edges and points of the achromatic channel (Y/Yn of the unfiltered image) found with the
//     first and second derivatives of a Gaussian of sigma 0.5 w ppd (w = 0.082 degrees), their
//     largest magnitude difference / sqrt(2) raised to qf = 0.5;
//  5. FLIP = colour^(1 - feature).
// Borders repeat the edge pixel. Alpha is ignored (FLIP judges what is shown: RGB).
#pragma once
#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/render/image_metrics.h"
#include "pipelines/result.h"

namespace mb {

// The viewing conditions the paper defaults to: a 0.7 m wide, 3840 px monitor seen from 0.7 m.
struct FlipViewing {
  double distanceMeters = 0.7;
  double monitorWidthMeters = 0.7;
  double monitorWidthPixels = 3840;
};
// Pixels per degree of visual angle: distance * (pixels / width) * pi / 180 (about 67.02 for
// the defaults), the scale every FLIP filter is built at.
double flipPixelsPerDegree(const FlipViewing& viewing = {});

struct FlipResult {
  int width = 0, height = 0;
  double pixelsPerDegree = 0;
  std::vector<float> error;  // width * height values in [0, 1], top row first
  double mean = 0;           // mean error over every pixel (the FLIP authors' single number)
  double weightedMedian = 0; // flipWeightedMedian(error)
  double max = 0;
  int maxX = 0, maxY = 0;    // first pixel with the largest error (x right, y down)
};

// FLIP of `test` against `reference` (same size, else an error naming both sizes).
Result<FlipResult> computeFlip(const RgbaImage& reference, const RgbaImage& test,
                               double pixelsPerDegree = flipPixelsPerDegree());

// The FLIP tool's "weighted median": each pixel weighted by its own error, the first error (in
// ascending order) at which the running sum of errors exceeds half their total; 0 when every
// error is 0. It tells where most of the error mass lies, not the typical pixel.
double flipWeightedMedian(std::vector<float> errors);

// The error map for people: each error e coloured by magmaMap()[round(255 e)] (the authors' tool).
RgbaImage flipErrorImage(const FlipResult& flip);
const std::array<std::array<float, 3>, 256>& magmaMap();

// {mean, weightedMedian, max, maxAt, pixelsPerDegree, definition} for metrics.json and reports,
// and back (the map stays empty).
nlohmann::json toJson(const FlipResult& flip);
FlipResult flipFromJson(const nlohmann::json& j);
// The image metrics JSON (render_frame.h) with "flip" beside psnr: compare, check, report.
nlohmann::json toJson(const ImageMetrics& metrics, const FlipResult& flip);
// "FLIP mean 0.0123, weighted median 0.25, max 0.6 at (12,40)" (3 significant digits: a mean of
// a few changed pixels stays readable, 2.1e-05); "FLIP 0 (no difference)".
std::string flipText(const FlipResult& flip);

}  // namespace mb

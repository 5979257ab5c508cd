// LDR-FLIP from the HPG 2020 paper's math (flip.h lists the steps). Filters are separable:
// a 2D Gaussian term a sqrt(pi/b) exp(-pi^2 (x^2 + y^2) / b) is the product of two 1D factors
// sqrt(a sqrt(pi/b)) exp(-pi^2 x^2 / b), so each channel is filtered as a sum of products.
#include "harness/render/flip.h"
#include "harness/render/render_frame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace mb {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// The paper's constants: colour pipeline exponent, breakpoint and its mapped value; feature
// filter width (degrees) and exponent.
constexpr float kQc = 0.7f, kPc = 0.4f, kPt = 0.95f, kFeatureWidth = 0.082f, kQf = 0.5f;

struct Vec3 { float x = 0, y = 0, z = 0; };

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

// sRGB primaries, D65 white (IEC 61966-2-1), and the inverse.
Vec3 linearToXyz(Vec3 c) {
  return {0.4124564f * c.x + 0.3575761f * c.y + 0.1804375f * c.z,
          0.2126729f * c.x + 0.7151522f * c.y + 0.0721750f * c.z,
          0.0193339f * c.x + 0.1191920f * c.y + 0.9503041f * c.z};
}
Vec3 xyzToLinear(Vec3 c) {
  return {3.2404542f * c.x - 1.5371385f * c.y - 0.4985314f * c.z,
          -0.9692660f * c.x + 1.8760108f * c.y + 0.0415560f * c.z,
          0.0556434f * c.x - 0.2040259f * c.y + 1.0572252f * c.z};
}
// The reference white: the XYZ of linear RGB (1, 1, 1).
const Vec3& white() {
  static const Vec3 w = linearToXyz({1, 1, 1});
  return w;
}

Vec3 xyzToYcc(Vec3 c) {
  const Vec3& w = white();
  const float x = c.x / w.x, y = c.y / w.y, z = c.z / w.z;
  return {116 * y - 16, 500 * (x - y), 200 * (y - z)};
}
Vec3 yccToXyz(Vec3 c) {
  const Vec3& w = white();
  const float y = (c.x + 16) / 116;
  return {(y + c.y / 500) * w.x, y * w.y, (y - c.z / 200) * w.z};
}

// CIELAB, then the Hunt adjustment (chroma scaled by L/100: dark colours look less colourful).
Vec3 xyzToHuntLab(Vec3 c) {
  const Vec3& w = white();
  constexpr float d = 6.0f / 29.0f;
  auto f = [&](float t) { return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0f / 29.0f; };
  const float fx = f(c.x / w.x), fy = f(c.y / w.y), fz = f(c.z / w.z);
  const float L = 116 * fy - 16;
  return {L, 0.01f * L * 500 * (fx - fy), 0.01f * L * 200 * (fy - fz)};
}
float hyab(Vec3 a, Vec3 b) { return std::abs(a.x - b.x) + std::hypot(a.y - b.y, a.z - b.z); }

// The largest colour difference FLIP expects: pure green against pure blue, raised to qc.
float maxColourDifference() {
  return std::pow(hyab(xyzToHuntLab(linearToXyz({0, 1, 0})), xyzToHuntLab(linearToXyz({0, 0, 1}))), kQc);
}

// A single-channel image and separable convolution with repeated borders.
struct Plane {
  int w = 0, h = 0;
  std::vector<float> v;
  Plane(int width, int height) : w(width), h(height), v(size_t(width) * size_t(height), 0.0f) {}
  float& at(int x, int y) { return v[size_t(y) * size_t(w) + size_t(x)]; }
  float at(int x, int y) const { return v[size_t(y) * size_t(w) + size_t(x)]; }
};

Plane convolve(const Plane& src, const std::vector<float>& k, bool alongX) {
  Plane out(src.w, src.h);
  const int r = int(k.size() / 2);
  if (alongX) {  // each row copied with its edge pixels repeated r times on both sides
    std::vector<float> row(size_t(src.w + 2 * r));
    for (int y = 0; y < src.h; ++y) {
      const float* s = &src.v[size_t(y) * size_t(src.w)];
      for (int x = -r; x < src.w + r; ++x) row[size_t(x + r)] = s[std::clamp(x, 0, src.w - 1)];
      float* o = &out.v[size_t(y) * size_t(src.w)];
      for (int x = 0; x < src.w; ++x) {
        float acc = 0;
        for (size_t i = 0; i < k.size(); ++i) acc += k[i] * row[size_t(x) + i];
        o[x] = acc;
      }
    }
  } else {  // whole rows at a time (the same sums in the same order, faster in memory)
    for (int y = 0; y < src.h; ++y) {
      float* o = &out.v[size_t(y) * size_t(src.w)];
      for (int i = -r; i <= r; ++i) {
        const float* s = &src.v[size_t(std::clamp(y + i, 0, src.h - 1)) * size_t(src.w)];
        const float ki = k[size_t(i + r)];
        for (int x = 0; x < src.w; ++x) o[x] += ki * s[x];
      }
    }
  }
  return out;
}
Plane separable(const Plane& src, const std::vector<float>& kx, const std::vector<float>& ky) {
  return convolve(convolve(src, kx, true), ky, false);
}

// One channel's contrast sensitivity: terms a sqrt(pi/b) exp(-pi^2 r^2 / b), r in degrees.
struct Csf { float a1, b1, a2, b2; };
constexpr Csf kAchromatic{1.0f, 0.0047f, 0.0f, 1e-5f}, kRedGreen{1.0f, 0.0053f, 0.0f, 1e-5f},
    kBlueYellow{34.1f, 0.04f, 13.5f, 0.025f};

// Radius (pixels) covering 3 standard deviations of the widest Gaussian of any channel.
int csfRadius(float ppd) {
  const float bMax = 0.04f;  // kBlueYellow.b1, the widest term
  return int(std::ceil(3 * std::sqrt(bMax / (2 * kPi * kPi)) * ppd));
}

// The channel filtered by its CSF: each nonzero term as the product of its 1D factors, the 2D
// kernel (sum of the terms' products) normalised to sum 1 over the (2R+1)^2 window.
Plane filterCsf(const Plane& src, const Csf& csf, float ppd) {
  const int r = csfRadius(ppd);
  std::vector<std::vector<float>> factors;
  float total = 0;  // sum of the 2D kernel: sum over terms of (sum of its 1D factor)^2
  for (auto [a, b] : {std::pair{csf.a1, csf.b1}, std::pair{csf.a2, csf.b2}}) {
    if (a == 0) continue;
    std::vector<float> k(size_t(2 * r + 1));
    float s = 0;
    for (int i = -r; i <= r; ++i) {
      const float x = float(i) / ppd;
      s += k[size_t(i + r)] = std::sqrt(a * std::sqrt(kPi / b)) * std::exp(-kPi * kPi * x * x / b);
    }
    total += s * s;
    factors.push_back(std::move(k));
  }
  const float norm = 1 / std::sqrt(total);
  Plane out(src.w, src.h);
  for (auto& k : factors) {
    for (float& v : k) v *= norm;
    const Plane term = separable(src, k, k);
    for (size_t i = 0; i < out.v.size(); ++i) out.v[i] += term.v[i];
  }
  return out;
}

struct Ycc { Plane y, cx, cz; };
Ycc toYcc(const RgbaImage& img) {
  Ycc out{Plane(img.width, img.height), Plane(img.width, img.height), Plane(img.width, img.height)};
  for (size_t i = 0; i < out.y.v.size(); ++i) {
    const uint8_t* p = &img.rgba[4 * i];
    const Vec3 c = xyzToYcc(linearToXyz({srgbToLinear(p[0] / 255.0f), srgbToLinear(p[1] / 255.0f),
                                         srgbToLinear(p[2] / 255.0f)}));
    out.y.v[i] = c.x, out.cx.v[i] = c.y, out.cz.v[i] = c.z;
  }
  return out;
}

// Per pixel, the compressed colour difference of the CSF-filtered images, in [0, 1].
std::vector<float> colourDifference(const Ycc& ref, const Ycc& test, float ppd) {
  const float cmax = maxColourDifference(), breakpoint = kPc * cmax;
  auto filtered = [&](const Ycc& img) {
    return Ycc{filterCsf(img.y, kAchromatic, ppd), filterCsf(img.cx, kRedGreen, ppd), filterCsf(img.cz, kBlueYellow, ppd)};
  };
  const Ycc a = filtered(ref), b = filtered(test);
  auto huntLab = [](const Ycc& img, size_t i) {
    Vec3 rgb = xyzToLinear(yccToXyz({img.y.v[i], img.cx.v[i], img.cz.v[i]}));
    rgb = {std::clamp(rgb.x, 0.0f, 1.0f), std::clamp(rgb.y, 0.0f, 1.0f), std::clamp(rgb.z, 0.0f, 1.0f)};
    return xyzToHuntLab(linearToXyz(rgb));
  };
  std::vector<float> out(a.y.v.size());
  for (size_t i = 0; i < out.size(); ++i) {
    const float d = std::pow(hyab(huntLab(a, i), huntLab(b, i)), kQc);
    out[i] = d < breakpoint ? d * kPt / breakpoint : kPt + (d - breakpoint) / (cmax - breakpoint) * (1 - kPt);
  }
  return out;
}

// Gaussian (sum 1) and its first and second derivatives (positive weights sum 1, negative -1),
// sigma = 0.5 w ppd pixels, radius 3 sigma.
struct FeatureKernels { std::vector<float> g, d1, d2; };
FeatureKernels featureKernels(float ppd) {
  const float sigma = 0.5f * kFeatureWidth * ppd;
  const int r = int(std::ceil(3 * sigma));
  FeatureKernels k{std::vector<float>(size_t(2 * r + 1)), std::vector<float>(size_t(2 * r + 1)),
                   std::vector<float>(size_t(2 * r + 1))};
  float gSum = 0, d1Sum[2] = {0, 0}, d2Sum[2] = {0, 0};  // [0] positive, [1] negative magnitudes
  for (int i = -r; i <= r; ++i) {
    const float x = float(i), g = std::exp(-x * x / (2 * sigma * sigma));
    const float d1 = -x * g, d2 = (x * x / (sigma * sigma) - 1) * g;
    k.g[size_t(i + r)] = g, k.d1[size_t(i + r)] = d1, k.d2[size_t(i + r)] = d2;
    gSum += g;
    d1Sum[d1 > 0 ? 0 : 1] += std::abs(d1);
    d2Sum[d2 > 0 ? 0 : 1] += std::abs(d2);
  }
  for (size_t i = 0; i < k.g.size(); ++i) {
    k.g[i] /= gSum;
    k.d1[i] /= k.d1[i] > 0 ? d1Sum[0] : d1Sum[1];
    k.d2[i] /= k.d2[i] > 0 ? d2Sum[0] : d2Sum[1];
  }
  return k;
}

// Edge (gradient) and point (second derivative) magnitudes of the achromatic channel Y/Yn.
struct Features { Plane edge, point; };
Features features(const Plane& ycc, const FeatureKernels& k) {
  Plane grey(ycc.w, ycc.h);
  for (size_t i = 0; i < grey.v.size(); ++i) grey.v[i] = (ycc.v[i] + 16) / 116;
  const Plane dx = separable(grey, k.d1, k.g), dy = separable(grey, k.g, k.d1);
  const Plane ddx = separable(grey, k.d2, k.g), ddy = separable(grey, k.g, k.d2);
  Features f{Plane(grey.w, grey.h), Plane(grey.w, grey.h)};
  for (size_t i = 0; i < grey.v.size(); ++i) {
    f.edge.v[i] = std::hypot(dx.v[i], dy.v[i]);
    f.point.v[i] = std::hypot(ddx.v[i], ddy.v[i]);
  }
  return f;
}

bool sizesMatch(const RgbaImage& a, const RgbaImage& b) {
  return a.width > 0 && a.height > 0 && a.width == b.width && a.height == b.height &&
         a.rgba.size() == size_t(a.width) * size_t(a.height) * 4 && b.rgba.size() == a.rgba.size();
}

}  // namespace

double flipPixelsPerDegree(const FlipViewing& v) {
  return v.distanceMeters * (v.monitorWidthPixels / v.monitorWidthMeters) * std::numbers::pi / 180.0;
}

Result<FlipResult> computeFlip(const RgbaImage& reference, const RgbaImage& test, double pixelsPerDegree) {
  if (!sizesMatch(reference, test))
    return Result<FlipResult>::fail("FLIP: the images differ in size or data (" + std::to_string(reference.width) + "x" +
                                    std::to_string(reference.height) + " vs " + std::to_string(test.width) + "x" +
                                    std::to_string(test.height) + ")");
  if (!(pixelsPerDegree > 0)) return Result<FlipResult>::fail("FLIP: pixels per degree must be positive");
  FlipResult out;
  out.width = reference.width, out.height = reference.height, out.pixelsPerDegree = pixelsPerDegree;
  // Equal RGB everywhere gives 0 at every step (HyAB 0, feature difference 0): skip the filters.
  bool same = true;
  for (size_t i = 0; same && i < reference.rgba.size(); i += 4)
    same = std::equal(&reference.rgba[i], &reference.rgba[i] + 3, &test.rgba[i]);
  if (same) {
    out.error.assign(size_t(out.width) * size_t(out.height), 0.0f);
    return out;
  }
  const float ppd = float(pixelsPerDegree);
  const Ycc ref = toYcc(reference), tst = toYcc(test);
  std::vector<float> error = colourDifference(ref, tst, ppd);
  const FeatureKernels k = featureKernels(ppd);
  const Features fr = features(ref.y, k), ft = features(tst.y, k);
  double sum = 0;
  for (size_t i = 0; i < error.size(); ++i) {
    const float edge = std::abs(fr.edge.v[i] - ft.edge.v[i]), point = std::abs(fr.point.v[i] - ft.point.v[i]);
    const float feature = std::pow(std::max(edge, point) / std::numbers::sqrt2_v<float>, kQf);
    error[i] = std::pow(error[i], 1 - feature);
    sum += error[i];
    if (error[i] > out.max) out.max = error[i], out.maxX = int(i % size_t(out.width)), out.maxY = int(i / size_t(out.width));
  }
  out.mean = sum / double(error.size());
  out.weightedMedian = flipWeightedMedian(error);
  out.error = std::move(error);
  return out;
}

double flipWeightedMedian(std::vector<float> errors) {
  std::sort(errors.begin(), errors.end());
  double total = 0;
  for (float e : errors) total += e;
  double running = 0;
  for (float e : errors)
    if ((running += e) > 0.5 * total) return e;
  return 0;
}

RgbaImage flipErrorImage(const FlipResult& flip) {
  RgbaImage img{flip.width, flip.height, std::vector<uint8_t>(flip.error.size() * 4, 255)};
  const auto& map = magmaMap();
  for (size_t i = 0; i < flip.error.size(); ++i) {
    const auto& c = map[size_t(std::clamp(int(flip.error[i] * 255 + 0.5f), 0, 255))];
    for (int ch = 0; ch < 3; ++ch) img.rgba[4 * i + size_t(ch)] = uint8_t(255 * std::clamp(c[size_t(ch)], 0.0f, 1.0f) + 0.5f);
  }
  return img;
}

nlohmann::json toJson(const FlipResult& flip) {
  return {{"mean", flip.mean},
          {"weightedMedian", flip.weightedMedian},
          {"max", flip.max},
          {"maxAt", {flip.maxX, flip.maxY}},
          {"pixelsPerDegree", flip.pixelsPerDegree},
          {"definition", "LDR-FLIP (Andersson et al., HPG 2020) per pixel in [0,1] (0 = no visible difference) at the "
                         "paper's viewing conditions (0.7 m from a 0.7 m wide 3840 px monitor); mean over pixels; "
                         "weightedMedian: the error at which the error-weighted cumulative sum passes half (as the "
                         "authors' tool); max: the largest pixel error"}};
}

FlipResult flipFromJson(const nlohmann::json& j) {
  FlipResult r;
  if (!j.is_object()) return r;
  r.mean = j.value("mean", 0.0), r.weightedMedian = j.value("weightedMedian", 0.0), r.max = j.value("max", 0.0);
  r.pixelsPerDegree = j.value("pixelsPerDegree", 0.0);
  if (const auto at = j.value("maxAt", nlohmann::json()); at.is_array() && at.size() == 2)
    r.maxX = at[0].get<int>(), r.maxY = at[1].get<int>();
  return r;
}

nlohmann::json toJson(const ImageMetrics& metrics, const FlipResult& flip) {
  nlohmann::json j = toJson(metrics);
  j["flip"] = toJson(flip);
  return j;
}

std::string flipText(const FlipResult& flip) {
  if (flip.max == 0) return "FLIP 0 (no difference)";
  char b[160];
  std::snprintf(b, sizeof b, "FLIP mean %.3g, weighted median %.3g, max %.3g at (%d,%d)", flip.mean,
                flip.weightedMedian, flip.max, flip.maxX, flip.maxY);
  return b;
}

}  // namespace mb

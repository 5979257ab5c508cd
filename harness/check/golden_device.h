// Which goldens a device is checked against. The committed goldens (tests/golden) are
// llvmpipe's. A GPU differs from llvmpipe at silhouette edges and in texture filtering (an H100
// at 512x512: RMS 0.0007-0.0013, a few edge pixels up to 0.38), far more than one pipeline
// differs from another on one device, so a device that is not llvmpipe keeps its own goldens
// under devices/<slug>/ (`check --update` on it writes them); until it has them it is compared
// with llvmpipe's under the scenes' portable thresholds, and check says which it did.
#pragma once
#include <string>

namespace mb::check {

// GL_RENDERER names Mesa's llvmpipe (any LLVM version: its goldens are the main ones).
bool isLlvmpipe(const std::string& renderer);

// The folder name of a device's goldens, from GL_RENDERER: lower-case letters and digits, runs
// of anything else as one '-', none at either end ("NVIDIA H100 80GB HBM3/PCIe/SSE2" ->
// "nvidia-h100-80gb-hbm3-pcie-sse2"); "unknown-renderer" when nothing is left.
std::string deviceSlug(const std::string& renderer);

enum class GoldenSource {
  Llvmpipe,           // llvmpipe checked against llvmpipe's goldens
  Device,             // a device checked against (or updating) its own goldens
  LlvmpipeForDevice,  // a device without goldens of its own: llvmpipe's, portable thresholds
};
struct GoldenChoice {
  GoldenSource source = GoldenSource::Llvmpipe;
  std::string dir;  // the folder holding the golden.json to read (or, updating, to write)
};

// `base` is the llvmpipe goldens' folder; `deviceGoldensPresent` whether
// base/devices/<slug>/golden.json exists (the caller looks; this stays a pure rule). `update`:
// the folder --update writes (a device always writes its own).
GoldenChoice chooseGoldens(const std::string& base, const std::string& renderer, bool deviceGoldensPresent,
                           bool update);

// base/devices/<deviceSlug(renderer)>
std::string deviceGoldenDir(const std::string& base, const std::string& renderer);

// One line for the console and the report: which goldens, why, and under which thresholds;
// `drawnOn` names the renderer and its device for the reader.
std::string describeChoice(const GoldenChoice& choice, const std::string& base, const std::string& renderer,
                           const std::string& drawnOn);

}  // namespace mb::check

#include "harness/check/golden_device.h"

#include <filesystem>

namespace mb::check {

bool isLlvmpipe(const std::string& renderer) { return renderer.rfind("llvmpipe", 0) == 0; }

std::string deviceSlug(const std::string& renderer) {
  std::string slug;
  bool gap = false;
  for (char c : renderer) {
    const bool alnum = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z');
    if (!alnum) {
      gap = !slug.empty();
      continue;
    }
    if (gap) slug += '-';
    gap = false;
    slug += char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  }
  return slug.empty() ? "unknown-renderer" : slug;
}

std::string deviceGoldenDir(const std::string& base, const std::string& renderer) {
  return (std::filesystem::path(base) / "devices" / deviceSlug(renderer)).string();
}

GoldenChoice chooseGoldens(const std::string& base, const std::string& renderer, bool deviceGoldensPresent,
                           bool update) {
  if (isLlvmpipe(renderer)) return {GoldenSource::Llvmpipe, base};
  if (update || deviceGoldensPresent) return {GoldenSource::Device, deviceGoldenDir(base, renderer)};
  return {GoldenSource::LlvmpipeForDevice, base};
}

std::string describeChoice(const GoldenChoice& choice, const std::string& base, const std::string& renderer,
                           const std::string& drawnOn) {
  switch (choice.source) {
    case GoldenSource::Llvmpipe:
      return "goldens: " + choice.dir + " (llvmpipe's; drawn on " + drawnOn + ")";
    case GoldenSource::Device:
      return "goldens: " + choice.dir + " (this device's own; drawn on " + drawnOn + ")";
    case GoldenSource::LlvmpipeForDevice:
      return "goldens: " + choice.dir + " (llvmpipe's) for " + drawnOn + ", which has none of its own in " +
             deviceGoldenDir(base, renderer) +
             ": compared under the scenes' portable (device-tolerant) thresholds; `check --update` on this "
             "device writes its own";
  }
  return "";
}

}  // namespace mb::check

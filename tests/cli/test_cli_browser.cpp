// The report in a real browser: a report folder made by `motorbench report`
// is opened from disk by headless Chromium. The page's own inline script writes on <body> how
// many images it shows and how many failed to decode (report_html.cpp); --dump-dom reads that
// back. Every image must decode, a screenshot must not be blank, and deleting one image file must
// be seen as a broken image.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <set>

#include "harness/render/image_metrics.h"
#include "tests/support/chromium.h"
#include "tests/support/cli_test_support.h"

namespace mb::cli_test {
namespace {

namespace fs = std::filesystem;

struct ImageCount {
  int images = -1, broken = -1;
};

ImageCount countImages(const std::string& dom) {
  std::smatch m;
  ImageCount c;
  if (std::regex_search(dom, m, std::regex("data-images=\"(\\d+)\""))) c.images = std::stoi(m[1]);
  if (std::regex_search(dom, m, std::regex("data-broken-images=\"(\\d+)\""))) c.broken = std::stoi(m[1]);
  return c;
}

TEST(Browser, ReportImagesDecodeAndPageIsNotBlank) {
  const std::string exe = chromiumExe();
  if (exe.empty()) GTEST_SKIP() << "Chromium not installed (scripts/setup.sh installs it)";
  const fs::path dir = scratchDir("browser");
  std::string out;
  // Two pipelines: every kind of image the page shows (frames, diffs, the animated comparison,
  // the plots), written and linked by the same code for each pipeline, in a third of the time.
  ASSERT_EQ(runCommand(motorbench() + "report skinned_tube textured_box --frames 0 --no-bench --no-isa --pipelines matrix,motor -o " +
                           quoted(dir / "report"), &out), 0) << out;
  const fs::path page = dir / "report" / "report.html";

  // One launch prints the DOM and takes the screenshot of the same page load.
  int status = 0;
  const fs::path shot = dir / "shot.png";
  const ImageCount ok =
      countImages(runChromium(exe, dir / "profile", page, "--dump-dom --screenshot=" + quoted(shot), &status));
  ASSERT_EQ(status, 0);
  // 2 scenes x (images + diffs) + the animated comparison + the plots: well over ten.
  EXPECT_GT(ok.images, 10);
  EXPECT_EQ(ok.broken, 0);

  auto img = readImage(shot.string());
  ASSERT_TRUE(img) << img.error();
  std::set<uint32_t> colours;
  size_t dark = 0;
  for (size_t p = 0; p + 3 < img->rgba.size(); p += 4) {
    colours.insert(uint32_t(img->rgba[p]) << 16 | uint32_t(img->rgba[p + 1]) << 8 | img->rgba[p + 2]);
    dark += img->rgba[p] < 128 && img->rgba[p + 1] < 128 && img->rgba[p + 2] < 128;
  }
  EXPECT_GT(colours.size(), 100u) << "screenshot looks blank";
  EXPECT_GT(dark, img->rgba.size() / 4 / 100) << "less than 1 % of the screenshot is text or image";

  // The same page with one image file gone must report it.
  fs::remove(dir / "report" / "images" / "textured_box" / "t0_motor.png");
  const ImageCount missing = countImages(runChromium(exe, dir / "profile", page, "--dump-dom", &status));
  EXPECT_EQ(missing.images, ok.images);
  EXPECT_EQ(missing.broken, 1);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mb::cli_test

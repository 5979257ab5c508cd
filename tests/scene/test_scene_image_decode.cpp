// Image decoding (pipelines/scene/gltf/image_decode.h): header checks against hand-built
// headers, PNG pixels of every colour type and bit depth against values derived by hand from
// the raw samples written, the same RGBA8 as stb_image, an independent decoder (compiled into
// this test only, on the images the test generates), JPEG through libjpeg-turbo, and the
// fuzzer's finding jpeg-huffman.glb as a counted fallback.
#include <gtest/gtest.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "pipelines/scene/gltf/image_decode.h"
#include "pipelines/scene/loader.h"
#include "tests/hostile/gltf_builder.h"

// stb_image, an independent decoder as the reference for the decoded pixels. Only this test
// compiles it, and only images the test itself generated reach it.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace {

using mb::hostile::Bytes;

Bytes pngOf(uint32_t w, uint32_t h, uint8_t depth, uint8_t colourType, const std::vector<Bytes>& rows,
            const Bytes& plte = {}, const Bytes& trns = {}) {
  return mb::hostile::pngRaw(w, h, depth, colourType, rows, plte, trns);
}

Bytes rgba(std::initializer_list<std::array<int, 4>> px) {
  Bytes b;
  for (const auto& p : px)
    for (int c : p) b.push_back(uint8_t(c));
  return b;
}

// The old path: tinygltf's stb loader (16-bit when the PNG is 16-bit, RGBA requested), then
// the high byte of each 16-bit sample.
Bytes stbRgba8(const Bytes& file, int* w, int* h) {
  int comps = 0;
  Bytes out;
  if (stbi_is_16_bit_from_memory(file.data(), int(file.size()))) {
    stbi_us* p = stbi_load_16_from_memory(file.data(), int(file.size()), w, h, &comps, 4);
    if (!p) return out;
    for (size_t i = 0; i < size_t(*w) * size_t(*h) * 4; ++i) out.push_back(uint8_t(p[i] >> 8));
    stbi_image_free(p);
  } else {
    stbi_uc* p = stbi_load_from_memory(file.data(), int(file.size()), w, h, &comps, 4);
    if (!p) return out;
    out.assign(p, p + size_t(*w) * size_t(*h) * 4);
    stbi_image_free(p);
  }
  return out;
}

struct PngCase {
  const char* what;
  Bytes file;
  Bytes expected;  // RGBA8, derived by hand from the samples written
};

std::vector<PngCase> pngCases() {
  std::vector<PngCase> cs;
  // 8-bit grey: (g, g, g, 255).
  cs.push_back({"grey 8", pngOf(3, 1, 8, 0, {{0, 128, 255}}), rgba({{0, 0, 0, 255}, {128, 128, 128, 255}, {255, 255, 255, 255}})});
  // 1-bit grey 10110000: 1 -> 255.
  cs.push_back({"grey 1", pngOf(4, 1, 1, 0, {{0xB0}}), rgba({{255, 255, 255, 255}, {0, 0, 0, 255}, {255, 255, 255, 255}, {255, 255, 255, 255}})});
  // 4-bit grey 0x3F: 3 * 17 = 51, 15 * 17 = 255.
  cs.push_back({"grey 4", pngOf(2, 1, 4, 0, {{0x3F}}), rgba({{51, 51, 51, 255}, {255, 255, 255, 255}})});
  // 16-bit grey: the high byte.
  cs.push_back({"grey 16", pngOf(2, 1, 16, 0, {{0x12, 0x34, 0xFE, 0xFF}}), rgba({{0x12, 0x12, 0x12, 255}, {0xFE, 0xFE, 0xFE, 255}})});
  // Grey with tRNS grey 7: that value is transparent, every other opaque.
  cs.push_back({"grey 8 + tRNS", pngOf(2, 1, 8, 0, {{7, 8}}, {}, {0, 7}), rgba({{7, 7, 7, 0}, {8, 8, 8, 255}})});
  // Grey + alpha, alpha not premultiplied.
  cs.push_back({"grey+alpha 8", pngOf(2, 1, 8, 4, {{200, 10, 50, 255}}), rgba({{200, 200, 200, 10}, {50, 50, 50, 255}})});
  cs.push_back({"RGB 8", pngOf(2, 1, 8, 2, {{1, 2, 3, 250, 251, 252}}), rgba({{1, 2, 3, 255}, {250, 251, 252, 255}})});
  cs.push_back({"RGB 16", pngOf(1, 2, 16, 2, {{0xA0, 1, 0xB0, 2, 0xC0, 3}, {0, 0xFF, 0x7F, 0xFF, 0xFF, 0}}),
                rgba({{0xA0, 0xB0, 0xC0, 255}, {0, 0x7F, 0xFF, 255}})});
  // Palette (8-bit indices) with a shorter tRNS: entries past it are opaque.
  cs.push_back({"palette 8 + tRNS", pngOf(3, 1, 8, 3, {{2, 0, 1}}, {10, 20, 30, 40, 50, 60, 70, 80, 90}, {0, 128}),
                rgba({{70, 80, 90, 255}, {10, 20, 30, 0}, {40, 50, 60, 128}})});
  // Palette with 2-bit indices 00 01 10 11.
  cs.push_back({"palette 2", pngOf(4, 1, 2, 3, {{0x1B}}, {0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255}),
                rgba({{0, 0, 0, 255}, {255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}})});
  // RGBA: straight alpha stays as stored (OpenImageIO would premultiply without the hint).
  cs.push_back({"RGBA 8", pngOf(1, 2, 8, 6, {{200, 100, 50, 10}, {1, 2, 3, 0}}), rgba({{200, 100, 50, 10}, {1, 2, 3, 0}})});
  cs.push_back({"RGBA 16", pngOf(1, 1, 16, 6, {{0x80, 0, 0x40, 0xFF, 0x20, 1, 0x10, 0x80}}), rgba({{0x80, 0x40, 0x20, 0x10}})});
  // Adam7, 2x2 RGB: pass 1 holds (0,0), pass 6 (1,0), pass 7 row 1; passes 2-5 are empty.
  cs.push_back({"RGB 8 Adam7", mb::hostile::pngRaw(2, 2, 8, 2, {{1, 2, 3}, {4, 5, 6}, {7, 8, 9, 10, 11, 12}}, {}, {}, true),
                rgba({{1, 2, 3, 255}, {4, 5, 6, 255}, {7, 8, 9, 255}, {10, 11, 12, 255}})});
  return cs;
}

TEST(ImageDecode, PngEveryColourTypeGivesTheHandDerivedRgba8) {
  for (const PngCase& c : pngCases()) {
    auto d = mb::decodeImage(c.file.data(), c.file.size());
    ASSERT_TRUE(d.ok()) << c.what << ": " << d.error();
    EXPECT_EQ(size_t(d->width) * size_t(d->height) * 4, c.expected.size()) << c.what;
    EXPECT_EQ(d->rgba, c.expected) << c.what;
  }
}

TEST(ImageDecode, PngPixelsAreThoseOfThePreviousDecoder) {
  for (const PngCase& c : pngCases()) {
    int w = 0, h = 0;
    Bytes old = stbRgba8(c.file, &w, &h);
    auto d = mb::decodeImage(c.file.data(), c.file.size());
    ASSERT_TRUE(d.ok()) << c.what;
    EXPECT_EQ(d->rgba, old) << c.what;
  }
}

// An image written by OpenImageIO (libjpeg-turbo, quality 100) from `px` (w x h x channels).
Bytes writeJpeg(int w, int h, int channels, const Bytes& px) {
  std::vector<unsigned char> file;
  OIIO::Filesystem::IOVecOutput vec(file);
  auto out = OIIO::ImageOutput::create("jpeg", &vec);
  EXPECT_TRUE(out != nullptr);
  if (!out) return {};
  OIIO::ImageSpec spec(w, h, channels, OIIO::TypeDesc::UINT8);
  spec.attribute("Compression", "jpeg:100");
  EXPECT_TRUE(out->open("memory.jpg", spec)) << out->geterror();
  EXPECT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data())) << out->geterror();
  out->close();
  return Bytes(file.begin(), file.end());
}

Bytes gradient(int w, int h, int channels) {
  Bytes px;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c) px.push_back(uint8_t(64 + 2 * x + 2 * y + 20 * c));  // smooth: no edges for 4:2:0 chroma
  return px;
}

int maxDiff(const Bytes& a, const Bytes& b) {
  int m = 0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) m = std::max(m, std::abs(int(a[i]) - int(b[i])));
  return a.size() == b.size() ? m : 256;
}

TEST(ImageDecode, JpegColourAndGreyThroughLibjpeg) {
  for (int channels : {3, 1}) {
    const int w = 32, h = 16;
    Bytes src = gradient(w, h, channels);
    Bytes file = writeJpeg(w, h, channels, src);
    auto hd = mb::readImageHeader(file.data(), file.size());
    ASSERT_TRUE(hd.ok()) << hd.error();
    EXPECT_EQ(hd->format, mb::ImageFormat::Jpeg);
    EXPECT_EQ(hd->width, uint32_t(w));
    EXPECT_EQ(hd->height, uint32_t(h));
    auto d = mb::decodeImage(file.data(), file.size());
    ASSERT_TRUE(d.ok()) << d.error();
    ASSERT_EQ(d->rgba.size(), size_t(w * h * 4));
    Bytes expected;  // the source expanded to RGBA8
    for (int i = 0; i < w * h; ++i)
      for (int c = 0; c < 4; ++c) expected.push_back(c == 3 ? 255 : src[size_t(i * channels + (channels == 1 ? 0 : c))]);
    // Quality 100 of a smooth gradient: lossy, but within a few levels of the source.
    EXPECT_LE(maxDiff(d->rgba, expected), 6) << channels << " channels";
    for (int i = 0; i < w * h; ++i) EXPECT_EQ(d->rgba[size_t(i) * 4 + 3], 255);
    // The reference decoder (stb_image) uses its own IDCT, upsampling and colour conversion:
    // JPEG pixels may differ from it by a level or two (no JPEG in the corpus or the built-in
    // scenes, so no golden changes). Printed, and bounded.
    int ow = 0, oh = 0;
    int vsStb = maxDiff(d->rgba, stbRgba8(file, &ow, &oh));
    std::printf("[ jpeg     ] %d channels: max |OIIO - stb_image| = %d levels\n", channels, vsStb);
    EXPECT_LE(vsStb, 4);
    // Hard edges (a wrapping ramp) show the decoders' differences most.
    Bytes edges;
    for (int i = 0; i < w * h * channels; ++i) edges.push_back(uint8_t((i * 37) % 256));
    Bytes edgeFile = writeJpeg(w, h, channels, edges);
    auto e = mb::decodeImage(edgeFile.data(), edgeFile.size());
    ASSERT_TRUE(e.ok()) << e.error();
    int edgeVsStb = maxDiff(e->rgba, stbRgba8(edgeFile, &ow, &oh));
    std::printf("[ jpeg     ] %d channels, hard edges: max |OIIO - stb_image| = %d levels\n", channels, edgeVsStb);
    EXPECT_LE(edgeVsStb, 4);
  }
}

TEST(ImageDecode, HeadersAreCheckedBeforeAnyDecoding) {
  // 60000 x 60000 with 16 bytes of data: refused from the header, nothing allocated.
  Bytes bomb = mb::hostile::png(60000, 60000, Bytes(16, 200), 4, 1);
  auto d = mb::decodeImage(bomb.data(), bomb.size());
  ASSERT_FALSE(d.ok());
  EXPECT_NE(d.error().find("60000x60000 pixels is too large"), std::string::npos) << d.error();
  // An IDAT chunk declaring 1.1 GB in a small file.
  Bytes chunk = mb::hostile::checkerPng();
  chunk[33] = 0x45;
  d = mb::decodeImage(chunk.data(), chunk.size());
  ASSERT_FALSE(d.ok());
  EXPECT_NE(d.error().find("chunk is longer"), std::string::npos) << d.error();
  // Not PNG, JPEG or WebP (a GIF header): refused, no reader guessed from the content.
  Bytes gif = {'G', 'I', 'F', '8', '9', 'a', 1, 0, 1, 0, 0, 0, 0, ';'};
  d = mb::decodeImage(gif.data(), gif.size());
  ASSERT_FALSE(d.ok());
  EXPECT_NE(d.error().find("not a PNG, JPEG or WebP image"), std::string::npos) << d.error();
  // A PNG that ends after IHDR (finding F13: OpenImageIO's read callback leaked a string when
  // libpng hit the end): refused before OpenImageIO runs.
  Bytes ihdrOnly = mb::hostile::checkerPng();
  ihdrOnly.resize(8 + 25 + 3);
  d = mb::decodeImage(ihdrOnly.data(), ihdrOnly.size());
  ASSERT_FALSE(d.ok());
  EXPECT_NE(d.error().find("no IEND"), std::string::npos) << d.error();
  // Complete chunks but no IEND (cut after IDAT), and junk after IEND (ignored, decodes).
  Bytes noIend = mb::hostile::checkerPng();
  noIend.resize(noIend.size() - 12);
  EXPECT_FALSE(mb::decodeImage(noIend.data(), noIend.size()).ok());
  Bytes trailing = mb::hostile::checkerPng();
  trailing.insert(trailing.end(), {1, 2, 3, 4, 5, 6, 7, 8, 9});
  EXPECT_TRUE(mb::decodeImage(trailing.data(), trailing.size()).ok());
  // Zero width.
  Bytes zero = pngOf(0, 1, 8, 0, {{}});
  EXPECT_FALSE(mb::readImageHeader(zero.data(), zero.size()).ok());
  // Truncated inside IHDR.
  Bytes cut = mb::hostile::checkerPng();
  EXPECT_FALSE(mb::readImageHeader(cut.data(), 20).ok());
  EXPECT_FALSE(mb::decodeImage(cut.data(), 0).ok());
  // JPEG: SOI, junk, an APP0 segment, then SOF0 declaring 300 high x 500 wide (hand-built).
  Bytes jpg = {0xFF, 0xD8, 0xFF, 0xE0, 0x00, 0x04, 0xAA, 0xBB, 0x12, 0x34,  // APP0 + 2 junk bytes
               0xFF, 0xFF, 0xC0, 0x00, 0x0B, 0x08, 0x01, 0x2C, 0x01, 0xF4, 0x01, 0x01, 0x11, 0x00};
  auto hd = mb::readImageHeader(jpg.data(), jpg.size());
  ASSERT_TRUE(hd.ok()) << hd.error();
  EXPECT_EQ(hd->width, 500u);
  EXPECT_EQ(hd->height, 300u);
  // The same frame header claiming 65535 x 65535: over the pixel limit.
  jpg[16] = jpg[17] = jpg[18] = jpg[19] = 0xFF;
  d = mb::decodeImage(jpg.data(), jpg.size());
  ASSERT_FALSE(d.ok());
  EXPECT_NE(d.error().find("too large"), std::string::npos) << d.error();
  // Scan data before any frame header.
  Bytes sos = {0xFF, 0xD8, 0xFF, 0xDA, 0x00, 0x02};
  EXPECT_FALSE(mb::readImageHeader(sos.data(), sos.size()).ok());
  // Truncated JPEG: every prefix fails cleanly.
  for (size_t n = 0; n < 20; ++n) EXPECT_FALSE(mb::readImageHeader(jpg.data(), n).ok()) << n;
}

// A fuzzer finding (tests/fuzz/regressions/f12): a GLB with a 1x1 PNG (magenta) and a JPEG whose
// Huffman table counts sum past 256. stb_image wrote past its table; libjpeg refuses the table.
TEST(ImageDecode, JpegHuffmanFindingIsACountedFallback) {
  const auto path = std::filesystem::path(MB_SOURCE_DIR) / "tests" / "fuzz" / "regressions" / "f12_jpeg_huffman_counts_over_256.glb";
  std::ifstream in(path, std::ios::binary);
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_EQ(bytes.size(), 900u) << path;
  auto r = mb::loadGltfMemory(bytes, "jpeg-huffman.glb");
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r->stats.imagesNotDecoded, 1);
  ASSERT_EQ(r->images.size(), 2u);
  EXPECT_EQ(r->images[0].width, 1);
  EXPECT_EQ(r->images[0].rgba, (Bytes{255, 0, 255, 255}));  // the PNG's one pixel
  EXPECT_EQ(r->images[1].rgba, (Bytes{255, 255, 255, 255}));  // replaced by 1x1 white
  bool reason = false;
  for (const auto& u : r->unsupported) reason |= u.find("image 1: JPEG error") != std::string::npos && u.find("Huffman") != std::string::npos;
  EXPECT_TRUE(reason) << "the reason (libjpeg: Bogus Huffman table definition) is listed";
}

}  // namespace

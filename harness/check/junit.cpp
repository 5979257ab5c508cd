#include "harness/check/junit.h"

#include <cstdint>
#include <cstdio>
#include <ctime>
#include <fstream>

namespace mb::check {
namespace {

constexpr const char* kReplacement = "\xEF\xBF\xBD";  // U+FFFD

// Length of the well-formed UTF-8 sequence at s[i] that XML 1.0 allows, or 0.
size_t xmlCharLength(const std::string& s, size_t i) {
  const auto byte = [&](size_t k) { return k < s.size() ? uint8_t(s[k]) : uint8_t(0); };
  const uint8_t c = byte(i);
  if (c < 0x80) return (c >= 0x20 || c == '\t' || c == '\n' || c == '\r') ? 1 : 0;
  size_t n = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? (c >= 0xF0 ? 0 : 3) : c >= 0xC2 ? 2 : 0;
  if (n == 0) return 0;
  uint32_t cp = c & (n == 2 ? 0x1F : n == 3 ? 0x0F : 0x07);
  for (size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3F);
  }
  const uint32_t least[5] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < least[n] || cp > 0x10FFFF) return 0;                   // overlong or too large
  if ((cp >= 0xD800 && cp <= 0xDFFF) || cp == 0xFFFE || cp == 0xFFFF) return 0;  // not XML characters
  return n;
}

std::string attribute(const char* key, const std::string& value) {
  return std::string(" ") + key + "=\"" + xmlEscape(value) + "\"";
}

std::string secondsText(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f", s < 0 ? 0.0 : s);
  return b;
}

std::string nowIso8601() {
  std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char b[32];
  std::strftime(b, sizeof b, "%Y-%m-%dT%H:%M:%S", &tm);
  return b;
}

std::string caseXml(const JunitCase& c) {
  std::string x = "    <testcase" + attribute("classname", c.classname) + attribute("name", c.name) +
                  attribute("time", secondsText(c.seconds));
  const char* element = c.kind == JunitCase::Kind::Fail    ? "failure"
                        : c.kind == JunitCase::Kind::Error ? "error"
                        : c.kind == JunitCase::Kind::Skipped ? "skipped"
                                                             : nullptr;
  if (!element) return x + "/>\n";
  x += ">\n      <" + std::string(element) + attribute("message", c.message);
  if (c.kind != JunitCase::Kind::Skipped) x += attribute("type", element);
  x += c.detail.empty() ? "/>\n" : ">" + xmlEscape(c.detail) + "</" + element + ">\n";
  return x + "    </testcase>\n";
}

}  // namespace

std::string xmlEscape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const size_t n = xmlCharLength(text, i);
    if (n == 0) {
      out += kReplacement;
      ++i;
      continue;
    }
    switch (text[i]) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      case '\n': out += "&#10;"; break;  // kept through attribute-value normalisation
      case '\r': out += "&#13;"; break;
      case '\t': out += "&#9;"; break;
      default: out.append(text, i, n);
    }
    i += n;
  }
  return out;
}

JunitCounts junitCounts(const std::vector<JunitCase>& cases) {
  JunitCounts n;
  for (const JunitCase& c : cases) {
    ++n.tests;
    n.failures += c.kind == JunitCase::Kind::Fail;
    n.errors += c.kind == JunitCase::Kind::Error;
    n.skipped += c.kind == JunitCase::Kind::Skipped;
    n.seconds += c.seconds;
  }
  return n;
}

std::string junitXml(const std::string& suite, const std::vector<JunitCase>& cases) {
  const JunitCounts n = junitCounts(cases);
  // <testsuites> carries no skipped count: the Jenkins schema has none there.
  const std::string counts = attribute("tests", std::to_string(n.tests)) +
                             attribute("failures", std::to_string(n.failures)) +
                             attribute("errors", std::to_string(n.errors));
  const std::string time = attribute("time", secondsText(n.seconds));
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites" + attribute("name", suite) + counts + time +
                  ">\n  <testsuite" + attribute("name", suite) + counts +
                  attribute("skipped", std::to_string(n.skipped)) + time + attribute("timestamp", nowIso8601()) + ">\n";
  for (const JunitCase& c : cases) x += caseXml(c);
  return x + "  </testsuite>\n</testsuites>\n";
}

Status writeJunit(const std::string& path, const std::string& suite, const std::vector<JunitCase>& cases) {
  std::ofstream out(path, std::ios::binary);
  out << junitXml(suite, cases);
  out.close();
  if (!out) return Status::fail(path + ": cannot write the JUnit file");
  return {};
}

}  // namespace mb::check

// The JUnit writer (harness/check/junit.h) and the content hash (harness/check/content_hash.h)
// against hand-derived references: escaped text, well-formed bytes for any input, the counts of
// the suite, and SHA-256 against FIPS 180-4's test vectors.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "harness/check/content_hash.h"
#include "harness/check/junit.h"

namespace {

using mb::check::JunitCase;
using Kind = JunitCase::Kind;

TEST(Junit, EscapesMarkupQuotesAndNewlines) {
  EXPECT_EQ(mb::check::xmlEscape("a<b>&\"c\"'d'"), "a&lt;b&gt;&amp;&quot;c&quot;&apos;d&apos;");
  EXPECT_EQ(mb::check::xmlEscape("line1\nline2\tx\r"), "line1&#10;line2&#9;x&#13;");
  EXPECT_EQ(mb::check::xmlEscape("Fox \xC3\xA9t\xC3\xA9.glb"), "Fox \xC3\xA9t\xC3\xA9.glb");  // UTF-8 kept
}

TEST(Junit, ReplacesWhatXmlCannotHold) {
  const std::string fffd = "\xEF\xBF\xBD";
  EXPECT_EQ(mb::check::xmlEscape(std::string("a\x01" "b", 3)), "a" + fffd + "b");           // control character
  EXPECT_EQ(mb::check::xmlEscape(std::string("a\0b", 3)), "a" + fffd + "b");                // NUL
  EXPECT_EQ(mb::check::xmlEscape("\xFF" "x"), fffd + "x");                                  // not UTF-8
  EXPECT_EQ(mb::check::xmlEscape("\xC3"), fffd);                                           // truncated sequence
  EXPECT_EQ(mb::check::xmlEscape("\xC0\xAF"), fffd + fffd);                                // overlong '/'
  EXPECT_EQ(mb::check::xmlEscape("\xED\xA0\x80"), fffd + fffd + fffd);                     // a surrogate
  EXPECT_EQ(mb::check::xmlEscape("\xF0\x9F\x98\x80"), "\xF0\x9F\x98\x80");                  // U+1F600 kept
}

TEST(Junit, OneSuiteWithCountsAndOneElementPerOutcome) {
  std::vector<JunitCase> cases = {
      {"props/Fox.glb", "rest.motor", 0.25, Kind::Pass, "", ""},
      {"props/Fox.glb", "rest.matrix", 0.5, Kind::Fail, "12.5 % of pixels over 0.004", "golden a.png\nb.png"},
      {"normal_torus", "rest.motor", 1.0, Kind::Error, "missing <golden> & more", ""},
      {"normal_torus", "rest.affine", 0, Kind::Skipped, "not judged", ""}};
  const mb::check::JunitCounts n = mb::check::junitCounts(cases);
  EXPECT_EQ(n.tests, 4);
  EXPECT_EQ(n.failures, 1);
  EXPECT_EQ(n.errors, 1);
  EXPECT_EQ(n.skipped, 1);
  EXPECT_DOUBLE_EQ(n.seconds, 1.75);
  const std::string x = mb::check::junitXml("motorbench check", cases);
  EXPECT_EQ(x.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"motorbench check\" tests=\"4\" "
                    "failures=\"1\" errors=\"1\" time=\"1.750\">\n  <testsuite name=\"motorbench check\" tests=\"4\" "
                    "failures=\"1\" errors=\"1\" skipped=\"1\" time=\"1.750\" timestamp=\"",
                    0),
            0u)
      << x;
  EXPECT_NE(x.find("<testcase classname=\"props/Fox.glb\" name=\"rest.motor\" time=\"0.250\"/>"), std::string::npos) << x;
  EXPECT_NE(x.find("<failure message=\"12.5 % of pixels over 0.004\" type=\"failure\">golden a.png&#10;b.png</failure>"),
            std::string::npos)
      << x;
  EXPECT_NE(x.find("<error message=\"missing &lt;golden&gt; &amp; more\" type=\"error\"/>"), std::string::npos) << x;
  EXPECT_NE(x.find("<skipped message=\"not judged\"/>"), std::string::npos) << x;
  EXPECT_EQ(x.substr(x.size() - 29), "  </testsuite>\n</testsuites>\n") << x;
}

TEST(Junit, WriteNamesAFileItCannotWrite) {
  mb::Status s = mb::check::writeJunit("/proc/no/such/junit.xml", "s", {});
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find("/proc/no/such/junit.xml"), std::string::npos) << s.error();
}

// FIPS 180-4 / NIST CSHA examples: "", "abc", the 448-bit two-block message and one of exactly
// 64 bytes (the padding goes to a block of its own).
TEST(ContentHash, Sha256OfTheStandardsVectors) {
  using mb::check::sha256Hex;
  EXPECT_EQ(sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256Hex(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  EXPECT_EQ(sha256Hex(std::string(64, 'a')), "ffe054fe7ae0cb6dc65c3af9b61d5209f439851db43d0ba5997337df154668eb");
}

}  // namespace

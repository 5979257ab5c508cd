// JUnit XML (the Ant/Jenkins format CI systems read: GitLab, Jenkins, GitHub test reporters) for
// the commands that judge images: one <testsuite> of one <testcase> per judged item (scene x
// pipeline x pose for check, one pair for compare and diff, one scene x frame for report), a
// <failure> or <error> with its reason, <skipped> for what was not judged.
//
// Every text and attribute is XML-escaped; bytes that XML 1.0 cannot hold (control characters,
// malformed UTF-8) are replaced by U+FFFD, so any file name or message gives a well-formed file.
#pragma once
#include <string>
#include <vector>

#include "pipelines/result.h"

namespace mb::check {

struct JunitCase {
  std::string classname, name;  // e.g. "check.Fox_glb", "rest.motor"
  double seconds = 0;
  enum class Kind { Pass, Fail, Error, Skipped } kind = Kind::Pass;
  std::string message;  // one line: the reason (the failure's message attribute)
  std::string detail;   // longer text: the element's content (metrics, paths); may be empty
};

struct JunitCounts {
  int tests = 0, failures = 0, errors = 0, skipped = 0;
  double seconds = 0;
};
JunitCounts junitCounts(const std::vector<JunitCase>& cases);

// `text` safe inside an XML attribute or element (& < > " ' escaped, invalid bytes replaced).
std::string xmlEscape(const std::string& text);

// The whole document: <testsuites> holding one <testsuite name="suite">.
std::string junitXml(const std::string& suite, const std::vector<JunitCase>& cases);

// Writes junitXml() to `path` (its folder must exist; prepareOutputFile checks that first);
// the error names the file.
Status writeJunit(const std::string& path, const std::string& suite, const std::vector<JunitCase>& cases);

}  // namespace mb::check

// Output paths checked before the work: every command that writes a file or a
// folder creates missing parent folders (as render does) and refuses, naming the option and the
// path, a folder where a file goes, a file name where a folder goes, and a place it cannot write
// to, before it measures anything.
#pragma once
#include <string>

#include "pipelines/result.h"

namespace mb {

// `path` will be written as one file (e.g. --json FILE): not an existing folder nor a name
// ending in '/', its folder created when missing and writable.
Status prepareOutputFile(const std::string& option, const std::string& path);

// `path` will be a folder of outputs (`holds` says what goes in, for the message): not an
// existing file nor a file-like name (out.png, x.json), created when missing, writable.
Status prepareOutputFolder(const std::string& option, const std::string& path, const std::string& holds);

// Writes `text` as the whole file `path`; "PATH: cannot write" when it cannot be written in full.
Status writeTextFile(const std::string& path, const std::string& text);

}  // namespace mb

#include "harness/cli/output_paths.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <system_error>
#include <filesystem>
#include <fstream>

namespace mb {
namespace {

namespace fs = std::filesystem;

// Extensions of the files the commands write: a folder argument named like one is a mistake.
bool fileLikeName(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  for (const char* e : {".png", ".jpg", ".jpeg", ".exr", ".tif", ".tiff", ".bmp", ".gif", ".hdr", ".json", ".md",
                        ".html", ".txt", ".csv"})
    if (ext == e) return true;
  return false;
}

// Creates `dir` (and its parents) and checks that files can be made in it.
Status writableFolder(const std::string& option, const std::string& path, const fs::path& dir) {
  std::error_code ec;
  const fs::path d = dir.empty() ? fs::path(".") : dir;
  if (fs::exists(d, ec) && !fs::is_directory(d, ec))
    return Status::fail(option + " " + path + ": " + d.string() + " is a file, not a folder");
  fs::create_directories(d, ec);
  if (ec) return Status::fail(option + " " + path + ": cannot create folder " + d.string() + ": " + ec.message());
  if (::access(d.c_str(), W_OK | X_OK) != 0)
    return Status::fail(option + " " + path + ": cannot write into folder " + d.string() + " (no write permission)");
  // access() says yes to root on any folder, and knows nothing of read-only mounts: make and
  // remove a file there, so the refusal comes now and not after the work.
  std::string probe = (d / ".motorbench-write-probe-XXXXXX").string();
  const int fd = ::mkstemp(probe.data());
  if (fd < 0)
    return Status::fail(option + " " + path + ": cannot write into folder " + d.string() + " (" +
                        std::error_code(errno, std::generic_category()).message() + ")");
  ::close(fd);
  ::unlink(probe.c_str());
  return Status();
}

}  // namespace

Status prepareOutputFile(const std::string& option, const std::string& path) {
  std::error_code ec;
  const fs::path p(path);
  if (path.empty()) return Status::fail(option + ": expected a file name");
  if (path.back() == '/' || fs::is_directory(p, ec))
    return Status::fail(option + " " + path + ": is a folder; it writes one file: give a file name such as " +
                        (p / "out.json").lexically_normal().string());
  if (Status ok = writableFolder(option, path, p.parent_path()); !ok) return ok;
  if (fs::exists(p, ec) && ::access(p.c_str(), W_OK) != 0)
    return Status::fail(option + " " + path + ": the file exists and cannot be written (no write permission)");
  return Status();
}

Status prepareOutputFolder(const std::string& option, const std::string& path, const std::string& holds) {
  std::error_code ec;
  const fs::path p(path);
  if (path.empty()) return Status::fail(option + ": expected a folder");
  if (fs::exists(p, ec) && !fs::is_directory(p, ec))
    return Status::fail(option + " " + path + ": is a file; this command writes a folder (" + holds + ")");
  if (!fs::exists(p, ec) && fileLikeName(p))
    return Status::fail(option + " " + path + ": looks like a file name, but this command writes a folder (" + holds +
                        "); give a folder name such as " + (p.parent_path() / p.stem()).string());
  return writableFolder(option, path, p);
}

Status writeTextFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  if (!out || !out.write(text.data(), std::streamsize(text.size())) || !out.flush())
    return Status::fail(path + ": cannot write");
  return Status();
}

}  // namespace mb

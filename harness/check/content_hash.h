// The content hash golden.json records for a glTF file checked against its goldens: SHA-256
// (FIPS 180-4) of the file's bytes followed, for each external resource the file names (buffers[]
// and images[] uris that are not data: URIs, in that order), by "\n<uri>\n<byte count>\n" and the
// resource's bytes ("\n<uri>\nmissing" when it cannot be read). A file without external
// resources hashes as `sha256sum FILE` does.
// An edited .gltf, .glb, .bin or texture changes it, so `check` can name a changed asset instead
// of judging it against images of the old one.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "pipelines/result.h"

namespace mb::check {

// Lower-case hex SHA-256 of `bytes`.
std::string sha256Hex(const std::string& bytes);

struct ContentHash {
  std::string sha256;                  // of the file and its external resources, as above
  std::vector<std::string> resources;  // the external uris hashed (a missing one hashes as missing)
};

// The hash of glTF file `path`; the error names the file when it cannot be read. A .gltf whose
// JSON cannot be parsed hashes as its bytes alone (the loader will name the problem).
Result<ContentHash> contentHash(const std::string& path);

}  // namespace mb::check

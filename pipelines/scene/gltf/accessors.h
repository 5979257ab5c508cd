// Validated decoding of glTF accessors (any component type, normalized integers, byteStride /
// interleaving, byteOffset, sparse) into tight arrays. Every byte read is range-checked first,
// so malformed files give an error message, never an out-of-range read.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "pipelines/result.h"

namespace tinygltf {
class Model;
}

namespace mb {

// A decoded accessor: `count` elements of `components` values each, row-major per element
// (matrices column-major inside an element, as glTF stores them).
template <class T>
struct AccessorData {
  size_t count = 0;
  int components = 0;
  std::vector<T> values;  // count * components
};

// Accessors with more elements than this are rejected before anything is allocated.
constexpr size_t kMaxAccessorCount = size_t(1) << 26;

// Decodes accessor `index` as floats. Normalized integers map to [0,1] / [-1,1] as the glTF
// spec says (signed: max(c / (2^(n-1)-1), -1)); other integers convert by value. `what` names
// the use in messages ("POSITION"). Elements past the end of the bufferView but inside its
// buffer are read from the buffer (readsPastBufferView); past the buffer is an error: "accessor
// 3 (POSITION) reads past bufferView 1 and past the end of buffer 0 (8 bytes follow the view)"
// (no file name: the loader prefixes it).
Result<AccessorData<float>> readAccessorFloat(const tinygltf::Model& model, int index,
                                              const std::string& what);

// Decodes an integer accessor (indices, JOINTS_n) exactly. Fails on float or normalized data
// and on negative values.
Result<AccessorData<uint32_t>> readAccessorUint(const tinygltf::Model& model, int index,
                                                const std::string& what);

// True when accessor `index` reads past the end of its bufferView but not past the end of the
// view's buffer (glTF 2.0 forbids it; readAccessorFloat/Uint read the buffer's bytes). False
// when it fits its view, has none, or is malformed otherwise.
bool readsPastBufferView(const tinygltf::Model& model, int index);

// An integer component `c` of `componentType` as a normalized accessor reads it (glTF 2.0
// 3.11: unsigned c / (2^n - 1), signed max(c / (2^(n-1) - 1), -1)); floats unchanged.
double normalizedValue(double c, int componentType);

// Bytes per component of a glTF componentType, 0 when unknown.
int componentSize(int componentType);

// Components per element of a glTF accessor type (SCALAR 1 ... MAT4 16), 0 when unknown.
int typeComponents(int type);

}  // namespace mb

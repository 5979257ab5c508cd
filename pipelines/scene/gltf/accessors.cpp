#include "pipelines/scene/gltf/accessors.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace mb {
namespace {

constexpr int kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125,
              kFloat = 5126;

template <class T>
T load(const uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof v);  // unaligned-safe; glTF is little-endian like our targets
  return v;
}

double readComponent(const uint8_t* p, int type, bool normalized) {
  double c = 0.0;
  switch (type) {
    case kByte: c = load<int8_t>(p); break;
    case kUByte: c = load<uint8_t>(p); break;
    case kShort: c = load<int16_t>(p); break;
    case kUShort: c = load<uint16_t>(p); break;
    case kUInt: c = load<uint32_t>(p); break;
    default: return load<float>(p);
  }
  return normalized ? normalizedValue(c, type) : c;
}

// Byte offset of component `c` inside one element. Matrix columns start on 4-byte
// boundaries (glTF 2.0 "data alignment"), which matters for byte/short MAT2 and MAT3.
size_t componentOffset(int accessorType, int compSize, int c) {
  int rows = accessorType == TINYGLTF_TYPE_MAT2 ? 2 : accessorType == TINYGLTF_TYPE_MAT3 ? 3
           : accessorType == TINYGLTF_TYPE_MAT4 ? 4 : 0;
  if (!rows) return size_t(c) * compSize;
  size_t colStride = (size_t(rows) * compSize + 3) & ~size_t(3);
  return size_t(c / rows) * colStride + size_t(c % rows) * compSize;
}

size_t elementSize(int accessorType, int compSize, int comps) {
  return componentOffset(accessorType, compSize, comps - 1) + compSize;
}

std::string label(int index, const std::string& what) {
  return "accessor " + std::to_string(index) + (what.empty() ? "" : " (" + what + ")");
}

// A bufferView's bytes: its first byte, its byteLength and byteStride, and `room`, the bytes
// from its first byte to the end of its buffer (>= length).
struct ViewSpan {
  const uint8_t* base = nullptr;
  size_t length = 0, room = 0, stride = 0;
};

// Checks that bufferView `bv` exists and lies inside its buffer.
Result<ViewSpan> viewBytes(const tinygltf::Model& m, int bv, const std::string& who) {
  if (bv < 0 || size_t(bv) >= m.bufferViews.size())
    return Result<ViewSpan>::fail(who + " refers to missing bufferView " + std::to_string(bv));
  const auto& view = m.bufferViews[size_t(bv)];
  if (view.buffer < 0 || size_t(view.buffer) >= m.buffers.size())
    return Result<ViewSpan>::fail("bufferView " + std::to_string(bv) + " refers to missing buffer " +
                                  std::to_string(view.buffer));
  const auto& data = m.buffers[size_t(view.buffer)].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
    return Result<ViewSpan>::fail("bufferView " + std::to_string(bv) + " lies outside buffer " +
                                  std::to_string(view.buffer));
  return ViewSpan{data.data() + view.byteOffset, view.byteLength, data.size() - view.byteOffset, view.byteStride};
}

// True when `count` elements of `elemSize` bytes at `stride` starting at `offset` fit in `length`.
bool fits(size_t offset, size_t count, size_t stride, size_t elemSize, size_t length) {
  if (count == 0) return offset <= length;
  if (offset > length || elemSize > length - offset) return false;
  return (count - 1) <= (length - offset - elemSize) / std::max<size_t>(stride, 1);
}

template <class T>
Result<AccessorData<T>> decode(const tinygltf::Model& m, int index, const std::string& what,
                               bool integer) {
  using R = Result<AccessorData<T>>;
  std::string who = label(index, what);
  if (index < 0 || size_t(index) >= m.accessors.size()) return R::fail(who + " does not exist");
  const auto& acc = m.accessors[size_t(index)];
  int cs = componentSize(acc.componentType), comps = typeComponents(acc.type);
  if (!cs) return R::fail(who + ": unsupported componentType " + std::to_string(acc.componentType));
  if (!comps) return R::fail(who + ": unsupported type " + std::to_string(acc.type));
  if (integer && (acc.componentType == kFloat || acc.componentType == kByte ||
                  acc.componentType == kShort || acc.normalized))
    return R::fail(who + ": expected unsigned integer components");
  if (acc.count > kMaxAccessorCount)
    return R::fail(who + ": count " + std::to_string(acc.count) + " is implausibly large");

  size_t elem = elementSize(acc.type, cs, comps);
  const uint8_t* data = nullptr;
  size_t stride = 0;
  if (acc.bufferView >= 0) {  // range checks before anything is allocated
    auto view = viewBytes(m, acc.bufferView, who);
    if (!view) return R::fail(view.error());
    stride = view->stride ? view->stride : elem;
    if (stride < elem)
      return R::fail(who + ": byteStride " + std::to_string(stride) + " of bufferView " +
                     std::to_string(acc.bufferView) + " is smaller than an element (" +
                     std::to_string(elem) + " bytes)");
    // Past the view but inside its buffer (invalid glTF, seen in exported files): the buffer's
    // bytes are read, counted as LoadStats::accessorsPastBufferView (accessor_bounds.cpp).
    if (!fits(acc.byteOffset, acc.count, stride, elem, view->room))
      return R::fail(who + " reads past bufferView " + std::to_string(acc.bufferView) + " and past the end of buffer " +
                     std::to_string(m.bufferViews[size_t(acc.bufferView)].buffer) + " (" +
                     std::to_string(view->room - view->length) + " bytes follow the view)");
    data = view->base + acc.byteOffset;
  }

  AccessorData<T> out;
  out.count = acc.count;
  out.components = comps;
  out.values.assign(acc.count * size_t(comps), T(0));  // no bufferView: zeros (glTF spec)

  auto fill = [&](const uint8_t* base, size_t stride, size_t n, auto dstIndex) {
    for (size_t i = 0; i < n; ++i)
      for (int c = 0; c < comps; ++c)
        out.values[dstIndex(i) * comps + size_t(c)] = T(readComponent(
            base + i * stride + componentOffset(acc.type, cs, c), acc.componentType, acc.normalized));
  };

  if (data) fill(data, stride, acc.count, [](size_t i) { return i; });

  if (acc.sparse.isSparse) {
    const auto& sp = acc.sparse;
    std::string swho = who + " sparse";
    if (sp.count < 0 || size_t(sp.count) > acc.count)
      return R::fail(swho + " count " + std::to_string(sp.count) + " exceeds accessor count");
    int ics = componentSize(sp.indices.componentType);
    if (!ics || sp.indices.componentType == kFloat || sp.indices.componentType == kByte ||
        sp.indices.componentType == kShort)
      return R::fail(swho + " indices: invalid componentType");
    if (sp.indices.byteOffset < 0 || sp.values.byteOffset < 0)
      return R::fail(swho + ": negative byteOffset");
    auto iview = viewBytes(m, sp.indices.bufferView, swho + " indices");
    if (!iview) return R::fail(iview.error());
    auto vview = viewBytes(m, sp.values.bufferView, swho + " values");
    if (!vview) return R::fail(vview.error());
    const size_t ilen = iview->length, vlen = vview->length;
    const uint8_t* ibase = iview->base;
    const uint8_t* vbase = vview->base;
    size_t n = size_t(sp.count);
    // Sparse data is tightly packed (byteStride does not apply).
    if (!fits(size_t(sp.indices.byteOffset), n, size_t(ics), size_t(ics), ilen))
      return R::fail(swho + " indices read past bufferView " + std::to_string(sp.indices.bufferView));
    if (!fits(size_t(sp.values.byteOffset), n, elem, elem, vlen))
      return R::fail(swho + " values read past bufferView " + std::to_string(sp.values.bufferView));
    std::vector<size_t> targets(n);
    for (size_t i = 0; i < n; ++i) {
      double t = readComponent(ibase + size_t(sp.indices.byteOffset) + i * size_t(ics),
                               sp.indices.componentType, false);
      if (t >= double(acc.count))
        return R::fail(swho + " index " + std::to_string(size_t(t)) + " out of range (count " +
                       std::to_string(acc.count) + ")");
      targets[i] = size_t(t);
    }
    fill(vbase + size_t(sp.values.byteOffset), elem, n, [&](size_t i) { return targets[i]; });
  }
  return out;
}

}  // namespace

double normalizedValue(double c, int componentType) {
  switch (componentType) {
    case kByte: return std::max(c / 127.0, -1.0);
    case kUByte: return c / 255.0;
    case kShort: return std::max(c / 32767.0, -1.0);
    case kUShort: return c / 65535.0;
    case kUInt: return c / 4294967295.0;
    default: return c;
  }
}

int componentSize(int t) {
  switch (t) {
    case kByte: case kUByte: return 1;
    case kShort: case kUShort: return 2;
    case kUInt: case kFloat: return 4;
    default: return 0;
  }
}

int typeComponents(int t) {
  switch (t) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

bool readsPastBufferView(const tinygltf::Model& m, int index) {
  if (index < 0 || size_t(index) >= m.accessors.size()) return false;
  const auto& acc = m.accessors[size_t(index)];
  const int cs = componentSize(acc.componentType), comps = typeComponents(acc.type);
  if (acc.bufferView < 0 || !cs || !comps || acc.count > kMaxAccessorCount) return false;
  auto view = viewBytes(m, acc.bufferView, "");
  if (!view) return false;
  const size_t elem = elementSize(acc.type, cs, comps), stride = view->stride ? view->stride : elem;
  return stride >= elem && !fits(acc.byteOffset, acc.count, stride, elem, view->length) &&
         fits(acc.byteOffset, acc.count, stride, elem, view->room);
}

Result<AccessorData<float>> readAccessorFloat(const tinygltf::Model& model, int index,
                                              const std::string& what) {
  return decode<float>(model, index, what, false);
}

Result<AccessorData<uint32_t>> readAccessorUint(const tinygltf::Model& model, int index,
                                                const std::string& what) {
  return decode<uint32_t>(model, index, what, true);
}

}  // namespace mb

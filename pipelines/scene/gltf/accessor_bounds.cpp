// Accessor min/max against the data (LoadStats::accessorBoundsMismatch). glTF 2.0 3.6.2.5: the
// bounds are of the raw values (normalized has no effect), after sparse substitution; float
// bounds are compared rounded to single precision, as the spec asks readers to round them.
// Also accessors read past their bufferView (LoadStats::accessorsPastBufferView).
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "pipelines/scene/gltf/accessors.h"
#include "pipelines/scene/gltf/gltf_convert.h"

namespace mb {

void countAccessorBoundsMismatches(const tinygltf::Model& m, Scene& scene) {
  for (size_t i = 0; i < m.accessors.size(); ++i) {
    const tinygltf::Accessor& acc = m.accessors[i];
    if (acc.minValues.empty() && acc.maxValues.empty()) continue;
    // Decoded exactly as the accessor's users decode it; a failure is theirs to report.
    auto data = readAccessorFloat(m, int(i), "");
    if (!data || data->count == 0) continue;
    const size_t comps = size_t(data->components);
    std::vector<float> lo(comps, std::numeric_limits<float>::infinity()), hi(comps, -lo[0]);
    for (size_t k = 0; k < data->values.size(); ++k) {
      lo[k % comps] = std::min(lo[k % comps], data->values[k]);
      hi[k % comps] = std::max(hi[k % comps], data->values[k]);
    }
    // A declared bound as the decoded data would hold it (NaN data compares unequal: counted).
    auto same = [&](const std::vector<double>& declared, const std::vector<float>& actual) {
      if (declared.empty()) return true;
      if (declared.size() != comps) return false;
      for (size_t c = 0; c < comps; ++c) {
        const double v = acc.normalized ? normalizedValue(declared[c], acc.componentType) : declared[c];
        if (!(std::fabs(v) <= double(std::numeric_limits<float>::max())) || float(v) != actual[c]) return false;
      }
      return true;
    };
    scene.stats.accessorBoundsMismatch += !(same(acc.minValues, lo) && same(acc.maxValues, hi));
  }
}

void countAccessorsPastBufferView(const tinygltf::Model& m, Scene& scene) {
  for (size_t i = 0; i < m.accessors.size(); ++i) scene.stats.accessorsPastBufferView += readsPastBufferView(m, int(i));
}

}  // namespace mb

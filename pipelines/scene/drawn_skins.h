// One palette per node drawn with a skin (drawnSkin), in node order: the loop every pipeline's
// CPU palette code runs over, the filling of each palette its own.
#pragma once
#include <vector>

#include "pipelines/scene/scene.h"

namespace mb {

// Resizes `palettes` (storage reused) to the nodes drawn with a skin, sets each palette's node
// and calls fill(palette, skin, node).
template <class Palette, class Fill>
inline void forEachDrawnSkin(const Scene& scene, std::vector<Palette>& palettes, Fill&& fill) {
  size_t count = 0;
  for (size_t n = 0; n < scene.nodes.size(); ++n) {
    const Skin* skin = drawnSkin(scene, n);
    if (!skin) continue;
    if (palettes.size() <= count) palettes.emplace_back();
    Palette& palette = palettes[count++];
    palette.node = int(n);
    fill(palette, *skin, n);
  }
  palettes.resize(count);
}

}  // namespace mb

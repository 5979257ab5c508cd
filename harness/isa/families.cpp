#include "harness/isa/families.h"

#include <algorithm>

namespace mb::isa {
namespace {

int roundUp(int v, int granule) { return (v + granule - 1) / granule * granule; }
bool rdna(Generation g) { return g >= Generation::Rdna1; }

}  // namespace

const std::vector<Family>& allFamilies() {
  static const std::vector<Family> families = {
      {"tahiti", Generation::Gcn1},       {"polaris10", Generation::Gcn4},
      {"vega10", Generation::Gcn5},       {"navi10", Generation::Rdna1},
      {"navi21", Generation::Rdna2, false, true}, {"navi21", Generation::Rdna2, true, true},
      {"gfx1100", Generation::Rdna3},
  };
  return families;
}

std::string generationName(Generation g) {
  switch (g) {
    case Generation::Gcn1: return "GCN 1";
    case Generation::Gcn4: return "GCN 4";
    case Generation::Gcn5: return "GCN 5";
    case Generation::Rdna1: return "RDNA 1";
    case Generation::Rdna2: return "RDNA 2";
    case Generation::Rdna3: return "RDNA 3";
  }
  return "?";
}

int wavesPerSimd(const Family& f, const Registers& r) {
  const Generation g = f.generation;
  int waves = 0;
  if (!rdna(g)) {
    waves = f.name.rfind("polaris", 0) == 0 ? 8 : 10;
    if (r.vgprs > 0) waves = std::min(waves, 256 / roundUp(r.vgprs, 4));
    if (r.sgprs > 0) {
      const bool gcn3plus = g != Generation::Gcn1;
      waves = std::min(waves, (gcn3plus ? 800 : 512) / roundUp(r.sgprs, gcn3plus ? 16 : 8));
    }
  } else {
    waves = g == Generation::Rdna1 ? 20 : 16;
    const int wave64Registers = g == Generation::Rdna3 ? 768 : 512;
    const int registers = wave64Registers * (64 / r.waveSize);
    if (r.vgprs > 0) {
      int granule = r.waveSize == 32 ? 8 : 4;
      if (g >= Generation::Rdna2) granule = std::max(granule, wave64Registers / 64 * (r.waveSize == 32 ? 2 : 1));
      waves = std::min(waves, registers / roundUp(r.vgprs, granule));
    }
  }
  if (r.fragment && r.interpolants > 0) {
    const int perWave = roundUp(48 * r.interpolants, 512);
    const int share = rdna(g) ? 32768 : 16384;
    waves = std::min(waves, (share + perWave - 1) / perWave);
  }
  return waves;
}

int radvSubgroupsPerSimd(const Family& f, int waves, int waveSize) {
  return rdna(f.generation) ? waves * waveSize / 32 : waves;
}

}  // namespace mb::isa

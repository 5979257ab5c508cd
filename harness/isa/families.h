// The AMD GPU families `motorbench isa` compiles for through RADV's null device, and the
// occupancy rule of each generation: how many waves of a shader one SIMD holds, from its
// register counts (README.md, "motorbench isa", states the same rule).
#pragma once
#include <string>
#include <vector>

namespace mb::isa {

enum class Generation { Gcn1, Gcn4, Gcn5, Rdna1, Rdna2, Rdna3 };

struct Family {
  std::string name;        // RADV_FORCE_FAMILY value: "navi21"
  Generation generation;
  bool ngg = false;        // NGG culling on (RDNA 2's default); off: RADV_DEBUG=nonggc
  bool nggSetting = false; // the family is run twice, so its id says which
  // "navi21" or "navi21-ngg" / "navi21-nonggc" for the families run both ways.
  std::string id() const { return nggSetting ? name + (ngg ? "-ngg" : "-nonggc") : name; }
};

// tahiti, polaris10, vega10, navi10, navi21 (NGG culling off), navi21 (on), gfx1100.
const std::vector<Family>& allFamilies();
// "GCN 1", "RDNA 2", ...
std::string generationName(Generation g);

// What the rule needs to know about one compiled shader.
struct Registers {
  int vgprs = 0, sgprs = 0;
  int waveSize = 64;      // as compiled (32 or 64)
  bool fragment = false;
  int interpolants = 0;   // fragment inputs (their LDS share limits waves only in theory)
};

// Waves of the compiled wave size one SIMD holds:
//   GCN (gfx6-gfx9): 256 VGPRs per lane per SIMD in granules of 4 -> 256 / roundup(v, 4);
//     SGPRs: 512 per SIMD in granules of 8 (GCN 1-2), 800 in granules of 16 (GCN 3-5);
//     at most 10 waves (8 on Polaris: GCN 4's Polaris10/11/12).
//   RDNA (gfx10+): SGPRs are not shared (no limit); VGPRs per SIMD: 512 wave64 registers
//     (1024 wave32; gfx1100: 768 / 1536), granule 4 (wave64) or 8 (wave32), and from RDNA 2
//     the hardware granule (registers / 64 = 8 on RDNA 2, 12 on gfx1100; doubled for wave32);
//     at most 20 waves (RDNA 1) or 16 (RDNA 2, 3).
//   Fragment shaders also take 48 bytes of LDS per interpolant per wave (granule 512 B) from
//   the SIMD's share of LDS (16 KiB on GCN, 32 KiB on RDNA), never the limit here.
int wavesPerSimd(const Family& f, const Registers& r);

// RADV's "Subgroups per SIMD" in the same terms: on RDNA RADV counts in 32-lane units
// (waves * waveSize / 32), on GCN in waves.
int radvSubgroupsPerSimd(const Family& f, int waves, int waveSize);

}  // namespace mb::isa

#include "harness/claims/claim_table.h"

namespace mb::claims {

std::vector<ClaimRow> claimTable() {
  std::vector<ClaimRow> rows;
  for (auto part : {opRows(), accuracyRows(), memoryRows(), compactRows(), speedRows(), corpusRows()})
    rows.insert(rows.end(), part.begin(), part.end());
  return rows;
}

}  // namespace mb::claims

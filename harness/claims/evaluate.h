// One evaluator for every declared row: reads the row's figures, applies its rule and words
// the verdict with the evidence and the rule beside it.
#pragma once
#include <vector>

#include "harness/claims/claim_table.h"
#include "harness/claims/claims_model.h"
#include "harness/claims/figure_set.h"

namespace mb::claims {

Claim evaluate(const ClaimRow& row, const FigureSet& figures);
std::vector<Claim> evaluateAll(const std::vector<ClaimRow>& rows, const FigureSet& figures);

}  // namespace mb::claims

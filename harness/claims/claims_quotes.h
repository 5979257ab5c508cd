// Which sentence (or table row) of the paper each of the paper's rows tests.
// A row quotes its sentence; a row without one is ours, whatever its family. Rows the paper
// prints as one table entry (gp_rt / gp_tr) are tallied once.
#pragma once
#include <vector>

#include "harness/claims/claims_model.h"

namespace mb::claims {

// Sets Claim::quote and Claim::tallyAs from the table; a row without a quote becomes ours
// (origin "not claimed by the paper" unless it already names its kind).
void applyPaperQuotes(std::vector<Claim>& rows);

}  // namespace mb::claims

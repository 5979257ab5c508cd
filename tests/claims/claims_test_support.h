// The one claim row of `rows` with id `id` (a test failure when there is none).
#pragma once
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "harness/claims/claims_model.h"

namespace mb::claims_test {

inline claims::Claim only(const std::vector<claims::Claim>& rows, const std::string& id) {
  for (const claims::Claim& c : rows)
    if (c.id == id) return c;
  ADD_FAILURE() << "no row " << id;
  return {};
}

}  // namespace mb::claims_test

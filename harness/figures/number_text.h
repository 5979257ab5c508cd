// How a number is printed, defined once for every writer (report.md/html, claims.md, the figures'
// own text, the command lines' tables), so the same number reads the same everywhere. Where two
// texts of a number differ on purpose, each has its own name saying how.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace mb::figures {

// `v` with `digits` significant digits ("-" when v is not a number); a whole number (a count)
// in full, never in exponent notation ("3240", not "3.24e+03").
std::string fmt(const nlohmann::json& v, int digits = 3);
std::string fmt(double v, int digits = 3);
// `v` with three significant digits as printf's %.3g writes it ("3.24e+03", "nan", "inf"): the
// claims', the scope ladder's and a Figure's text, not special-cased like fmt.
std::string sig3(double v);
// Fixed decimals ("-" when not a number).
std::string fixed(const nlohmann::json& v, int decimals);
// "0.97x" style ratio ("-" when not a number).
std::string ratio(const nlohmann::json& v);
// Percentage of a 0..1 fraction, e.g. "0.31 %".
std::string percent(const nlohmann::json& fraction, int decimals = 2);
// A positive number as printf's `format` writes it; "-" for zero, a negative or not a number
// (a throughput or ratio the bench did not measure).
std::string positiveOrDash(const nlohmann::json& v, const char* format = "%.4g");

}  // namespace mb::figures
